// `ejecta crater INPUT`: crater depth, diameters, volume, excavated mass, elongation and profile
// of a snapshot (.h5) or a grid file (.vdb) written by ejecta.
#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "apps/commands.hpp"
#include "core/atomic_file.hpp"
#include "core/units.hpp"
#include "fields/crater.hpp"
#include "fields/crater_setup.hpp"
#include "fields/crater_summary.hpp"
#include "fields/grid_set.hpp"
#include "fields/measure_crater.hpp"
#include "fields/vdb_grids.hpp"
#include "sim/io/snapshot.hpp"
#include "sim/io/snapshot_checks.hpp"
#include "sim/run/run.hpp"

namespace fs = std::filesystem;

namespace ejecta::app {

namespace {

nlohmann::ordered_json toJson(const fields::CraterMetrics& m, const fields::CraterSetup& setup,
                              const std::string& input, double resolution) {
  nlohmann::ordered_json j;
  j["input"] = input;
  j["resolution_m"] = resolution;
  j["reference_surface"] = setup.surface.kind == fields::ReferenceSurface::Kind::Sphere
                               ? nlohmann::ordered_json{{"kind", "sphere"},
                                                        {"center_m", setup.surface.center},
                                                        {"radius_m", setup.surface.radius}}
                               : nlohmann::ordered_json{{"kind", "plane"},
                                                        {"point_m", setup.surface.point},
                                                        {"normal", setup.surface.normal}};
  j["impact_point_m"] = setup.impactPoint;
  j["target_materials"] = setup.targetNames;
  j["planar"] = setup.planar;
  j["found"] = m.found;
  if (!m.note.empty()) j["note"] = m.note;
  j["depth_m"] = m.depth;
  j["deepest_point_m"] = m.deepestPoint;
  j["apparent_diameter_m"] = m.apparentDiameter;
  j["rim_diameter_m"] = m.rimDiameter;
  j["rim_height_m"] = m.rimHeight;
  j[setup.planar ? "area_m2" : "volume_m3"] = m.volume;
  j[setup.planar ? "excavated_mass_kg_per_m" : "excavated_mass_kg"] = m.excavatedMass;
  j["along_track_diameter_m"] = m.alongTrackDiameter;
  j["cross_track_diameter_m"] = m.crossTrackDiameter;
  j["elongation"] = m.elongation;
  if (setup.scaling) {  // [crater] scaling (docs/crater.md)
    const fields::ScaledCrater k = fields::scaleCrater(setup.scaling->law, setup.scaling->impact);
    j["scaling"] = {{"class", setup.scaling->law.name},
                    {"regime", k.strengthRegime ? "strength" : "gravity"},
                    {"strength_pa", k.strength},
                    {"volume_m3", k.volume},
                    {"diameter_m", 2.0 * k.radius},
                    {"depth_m", k.depth}};
  }
  nlohmann::ordered_json profile = nlohmann::ordered_json::array();
  for (const fields::CraterProfileBin& b : m.profile)
    profile.push_back({b.distance, b.depthMean, b.depthMin, b.depthMax});
  j["profile_columns"] = {"distance_m", "depth_mean_m", "depth_min_m", "depth_max_m"};
  j["profile"] = profile;
  return j;
}

}  // namespace

int craterCommand(const CraterArgs& args) {
  const double resolution =
      args.resolution.empty() ? 0.0 : parseQuantity(args.resolution, Dimension::Length);
  if (resolution < 0.0) throw std::runtime_error("--resolution: must be positive");
  fields::CraterMetrics metrics;
  fields::CraterSetup setup;
  double used = resolution;
  const std::string ext = fs::path(args.input).extension().string();
  if (ext == ".vdb") {
    const fields::GridFileCraterInput in = fields::craterInputFromGridFile(args.input);
    setup = in.setup;
    used = resolution > 0.0 ? resolution : in.voxel;
    metrics = fields::analyseCrater(in.field, fields::craterOptions(setup, used));
  } else {
    SnapshotInfo info;
    const ParticleSet particles = readSnapshot(args.input, info);
    const Scene scene = storedScene(info, args.input);
    checkSnapshotMaterials(particles, scene.materials.size(), args.input);
    const auto found = fields::craterSetupFromScene(scene);
    if (!found)
      throw std::runtime_error(args.input + ": scene '" + scene.name + "' is not an impact "
                               "(no moving body striking bodies at rest, or [crater] enabled = false)");
    setup = *found;
    const fields::ParticleContext ctx = fields::ParticleContext::fromScene(scene);
    used = resolution > 0.0 ? resolution : 0.5 * fields::medianSmoothingLength(particles);
    metrics = fields::measureCrater(particles, ctx, setup, used);
  }
  if (!args.profile.empty()) writeFileAtomically(args.profile, fields::craterProfileCsv(metrics));
  if (args.json) {
    std::printf("%s\n", toJson(metrics, setup, args.input, used).dump(2).c_str());
    return metrics.found ? 0 : 3;
  }
  if (!metrics.found) {
    std::printf("ejecta crater: %s: no crater found (%s)\n", args.input.c_str(), metrics.note.c_str());
    return 3;
  }
  std::printf("ejecta crater: %s (resolution %.3g m, target: ", args.input.c_str(), used);
  for (std::size_t i = 0; i < setup.targetNames.size(); ++i)
    std::printf("%s%s", i ? ", " : "", setup.targetNames[i].c_str());
  std::printf(")\n  depth %.3f m, apparent diameter %.3f m, rim-to-rim %.3f m, rim height %.3f m\n",
              metrics.depth, metrics.apparentDiameter, metrics.rimDiameter, metrics.rimHeight);
  if (setup.planar)
    std::printf("  area %.4g m^2 (per metre of depth), excavated mass %.4g kg/m\n", metrics.volume,
                metrics.excavatedMass);
  else
    std::printf("  volume %.4g m^3, excavated mass %.4g kg, elongation %.3f (%.3f m along, %.3f m across)\n",
                metrics.volume, metrics.excavatedMass, metrics.elongation,
                metrics.alongTrackDiameter, metrics.crossTrackDiameter);
  if (setup.scaling) {
    // The scene's [crater] scaling (fields/crater_scaling.hpp).
    const fields::ScaledCrater k = fields::scaleCrater(setup.scaling->law, setup.scaling->impact);
    std::printf("  %s\n",
                fields::describeScaledCrater(setup.scaling->law.name, k, metrics.volume,
                                             metrics.apparentDiameter).c_str());
  }
  if (!metrics.note.empty()) std::printf("  note: %s\n", metrics.note.c_str());
  return 0;
}

}  // namespace ejecta::app
