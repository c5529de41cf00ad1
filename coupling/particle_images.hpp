#pragma once
// Pictures of a run's particles (render/ over sim/'s particles): the view that suits the run's
// geometry, a field's values with its units, the time. Used by `ejecta render`, by the frames
// `ejecta run` writes for a scene's [images] table, and under the spacecraft in a thermal pass's
// picture (coupling/thermal_picture.hpp).
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "render/renderer.hpp"
#include "sim/state/particles.hpp"
#include "sim/setup/scene.hpp"

namespace ejecta::coupling {

struct ParticleImageOptions {
  std::string field = "density";  // a field of sim/state/particle_fields.hpp
  bool log = false;
  std::string cut = "z";          // 3D: keep the half with x, y or z <= cutAt ("none": no cut)
  double cutAt = 0.0;             // [m]
  std::optional<render::Camera> camera;  // 3D; none: look at everything from above and aside
  std::string title;              // default: "<scene>: <field>"
  bool axes = false;              // distance axes along the edges (plane and RZ pictures)
  // Plane and RZ pictures: the centre and width shown [m]; none: fit everything drawn.
  std::optional<std::array<double, 2>> center;
  double width = 0.0;
};

// The strip's axes for `geometry`: on when asked, named x, y (RZ: r, z).
void setDistanceAxes(render::Annotations& annotations, Geometry geometry, bool on);

// The scene file's [images.camera] as the renderer takes it.
render::Camera renderCamera(const ImageCamera& camera);

// What a particle layer points into: it must outlive the layer's use.
struct ParticleLayerArrays {
  std::vector<double> values;  // the field coloured by
  std::vector<double> radii;   // each disc's radius [m] (particleDiscRadii)
};

// The layer of the real particles coloured by `options.field`, each a disc sized to its own
// spacing. Throws std::invalid_argument for an unknown field.
render::ParticleLayer particleLayer(const ParticleSet& p, Geometry geometry,
                                    const ParticleImageOptions& options, ParticleLayerArrays& arrays);

// Disc radii that tile the picture without gaps: 0.75 of each particle's own spacing, the
// side of its volume m / rho (per unit depth in 2D planar; RZ: m / (2 pi r rho), the ring's
// cross-section). A square lattice needs 1/sqrt(2) = 0.707 of the spacing to cover its cells'
// centres: below that the gaps form a moire. Falls back to h / 2 where the volume is not finite.
std::vector<double> particleDiscRadii(const ParticleSet& p, Geometry geometry);

// The view that suits the geometry: a plane, RZ mirrored about the axis, or 3D through the
// options' camera (or an automatic one), cut in half. Throws std::invalid_argument for an unknown
// cut.
render::View particleView(Geometry geometry, const ParticleImageOptions& options);
render::View particleView(Geometry geometry, const std::string& cut);

// Draws the particles and writes the PNG atomically. Throws std::invalid_argument for an
// unknown field or cut.
void writeParticleImage(render::Renderer& renderer, const ParticleSet& p, Geometry geometry,
                        double time, const std::string& sceneName,
                        const ParticleImageOptions& options, const std::filesystem::path& out);

}  // namespace ejecta::coupling
