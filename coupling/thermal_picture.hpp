#pragma once
// The picture of a thermal pass: the crater's particles coloured by temperature and, in the same
// view, the spacecraft where it sees the most flux, its faces coloured by their eq. 4.8 steady
// temperature (docs/thermal.md). The spacecraft is drawn as its section by the run's plane (RZ:
// the meridian plane z = 0 of the revolved world; 3D: the plane z = 0 as well), each face a band
// along its cut: a 3D body drawn whole would hide the faces that matter behind the ones facing the
// viewer.
#include <filesystem>
#include <optional>
#include <string>

#include "radiation/thermal_study.hpp"
#include "render/renderer.hpp"
#include "sim/state/particles.hpp"
#include "sim/setup/scene.hpp"

namespace ejecta::coupling {

// The spacecraft's section by the plane z = 0 as bands of width `band` [m] (two triangles per cut
// triangle), each carrying `patchValues[patch]`. Triangles that do not cross the plane add none.
struct SectionBands {
  std::vector<render::Vec3> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<double> values;  // per triangle
};
SectionBands sectionBands(const radiation::TriangleMesh& mesh, const std::vector<double>& patchValues,
                          double band);

// Draws the pass's picture to `out` (PNG, atomically). `time` is the particles' time [s]; the
// spacecraft is drawn at `poseTime` into its pass [s], or where it sees the most flux if unset.
void writeThermalPicture(render::Renderer& renderer, const ParticleSet& particles, Geometry geometry,
                         double time, const radiation::ThermalStudy& study,
                         const radiation::ThermalResult& result, const std::string& title,
                         const std::filesystem::path& out, std::optional<double> poseTime = {});

}  // namespace ejecta::coupling
