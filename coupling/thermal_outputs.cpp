#include "coupling/thermal_outputs.hpp"

#include <algorithm>

#include "core/atomic_file.hpp"

namespace ejecta::coupling {

namespace fs = std::filesystem;

SnapshotEmitterOptions emitterOptionsFor(const radiation::ThermalStudy& study,
                                         const std::vector<std::string>& materialNames,
                                         std::vector<std::string>* unknownMaterials) {
  SnapshotEmitterOptions options;
  options.minTemperature = study.emitters.minTemperature;
  options.defaultEmissivity = study.emitters.defaultEmissivity;
  options.materialNames = materialNames;
  for (const std::string& name : materialNames) {
    const auto it = study.emitters.emissivityByMaterial.find(name);
    options.emissivityByMaterial.push_back(it != study.emitters.emissivityByMaterial.end()
                                               ? it->second
                                               : study.emitters.defaultEmissivity);
  }
  if (unknownMaterials)
    for (const auto& [name, eps] : study.emitters.emissivityByMaterial)
      if (std::find(materialNames.begin(), materialNames.end(), name) == materialNames.end())
        unknownMaterials->push_back(name);
  return options;
}

std::string particleSourceJson(const std::string& path, double time, Geometry geometry,
                               const SnapshotEmitterStats& stats) {
  return "  \"emitter_kind\": \"particles\",\n  \"snapshot\": {\"path\": " + jsonString(path) +
         ", \"time_s\": " + jsonNumber(time) +
         ", \"geometry\": " + jsonString(std::string(geometryName(geometry))) +
         ", \"particles\": " + std::to_string(stats.particles) +
         ", \"hot_particles\": " + std::to_string(stats.hot) +
         ", \"max_ring_copies\": " + std::to_string(stats.maxCopies) + "}";
}

std::string occluderJson(const std::string* gridFile, const SurfaceOccluderOptions& options,
                         const SurfaceOccluderStats& stats) {
  if (!gridFile) return "  \"occluder\": null";
  return "  \"occluder\": {\"grid_file\": " + jsonString(*gridFile) +
         ", \"level_set\": " + jsonString(options.grid) +
         ", \"triangles\": " + std::to_string(stats.triangles) +
         ", \"inset_voxels\": " + jsonNumber(options.insetVoxels) +
         ", \"inset_m\": " + jsonNumber(stats.inset) + ", \"area_m2\": " + jsonNumber(stats.area) + "}";
}

std::string writeThermalOutputs(const fs::path& dir, const radiation::ThermalStudy& study,
                                const radiation::ThermalResult& result, const std::string& extraJson) {
  fs::create_directories(dir);
  writeFileAtomically(dir / "flux.csv", radiation::formatThermalFluxCsv(result));
  for (const radiation::PatchThermal& p : result.patches)
    if (p.wall) radiation::writeWallHistoryCsv(dir / ("wall_" + p.patch + ".csv"), *p.wall);
  if (!study.sizing.coatings.empty())
    writeFileAtomically(dir / "sizing.csv", radiation::formatThermalSizingCsv(result));
  const std::string json = radiation::formatThermalJson(result, extraJson);
  writeFileAtomically(dir / "thermal.json", json);
  return json;
}

}  // namespace ejecta::coupling
