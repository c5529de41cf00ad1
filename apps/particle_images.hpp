#pragma once
// Pictures of a run's particles (render/ over sim/'s particles): the view that suits the run's
// geometry, a field's values with its units, the time. Used by `ejecta render` and by the frames
// `ejecta run` writes for a scene's [images] table.
#include <filesystem>
#include <string>

#include "render/renderer.hpp"
#include "sim/particles.hpp"
#include "sim/scene.hpp"

namespace ejecta::app {

struct ParticleImageOptions {
  std::string field = "density";  // a field of sim/particle_fields.hpp
  bool log = false;
  std::string cut = "z";          // 3D: keep the half with x, y or z <= 0 ("none": no cut)
  std::string title;              // default: "<scene>: <field>"
};

// Draws the particles (RZ mirrored about the axis; 3D from an automatic camera, cut in half)
// and writes the PNG atomically. Throws std::invalid_argument for an unknown field or cut.
void writeParticleImage(render::Renderer& renderer, const ParticleSet& p, Geometry geometry,
                        double time, const std::string& sceneName,
                        const ParticleImageOptions& options, const std::filesystem::path& out);

}  // namespace ejecta::app
