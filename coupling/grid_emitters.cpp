// Grid file -> voxel emitters: fields::readGridVoxels, then radiation::selectVoxelEmitters.
#include "coupling/grid_emitters.hpp"

#include <filesystem>
#include <numbers>
#include <regex>
#include <span>
#include <stdexcept>

#include "core/join.hpp"
#include "fields/grid_voxels.hpp"

namespace ejecta::coupling {

namespace fs = std::filesystem;

radiation::Emitters emittersFromGridFile(const std::string& path, const GridEmitterOptions& options,
                                         GridEmitterStats* stats) {
  fields::GridVoxelOptions read;
  read.grid = options.grid;
  read.threshold = options.minTemperature;
  const fields::GridVoxels v = fields::readGridVoxels(path, read);
  if (v.sourceGeometry == "2d")
    throw std::runtime_error(path + ": the grids of a planar-2D run are a slab with no 3D extent to "
                             "radiate from; use an RZ or 3D run");
  if (!v.missingFractions.empty()) {
    throw std::runtime_error(path + ": the file has the fraction grids of " + joinList(v.materials) + " but not of " +
                             joinList(v.missingFractions) +
                             " (the run's other materials): voxels of those alone would be dropped" +
                             (v.fractionsAreFill ? ", and the voxels they share counted part-filled" : "") +
                             "; write every material's fraction (the scene's [fields] grids = [\"temperature\", "
                             "\"fractions\"], or ejecta fields SNAPSHOT --grids temperature,fractions), or take "
                             "the particles as emitters (--from the run or its snapshot, --emitters particles)");
  }

  radiation::VoxelEmitterSource source;
  source.x = v.x;
  source.y = v.y;
  source.z = v.z;
  source.temperature = v.value;
  source.voxelVolume = v.voxelVolume;
  for (const std::vector<double>& f : v.fraction) source.fraction.emplace_back(f);
  source.fractionsAreFill = v.fractionsAreFill;

  radiation::EmitterSelection selection;
  selection.minTemperature = options.minTemperature;
  selection.defaultEmissivity = options.defaultEmissivity;
  selection.materialNames = v.materials;
  for (const std::string& m : v.materials) {
    const auto it = options.emissivityByMaterial.find(m);
    selection.emissivityByMaterial.push_back(it != options.emissivityByMaterial.end() ? it->second
                                                                                      : options.defaultEmissivity);
  }
  radiation::Emitters e;
  try {
    e = radiation::selectVoxelEmitters(source, selection);
  } catch (const std::invalid_argument& err) {
    throw std::invalid_argument(path + ": grid '" + options.grid + "': " + err.what());
  }

  if (stats) {
    GridEmitterStats s;
    s.activeVoxels = v.activeVoxels;
    s.hotVoxels = v.size();
    s.emitters = e.size();
    s.voxelSize = v.voxelSize;
    for (double r : e.radius) s.hotVolume += 4.0 / 3.0 * std::numbers::pi * r * r * r;
    s.time = v.time;
    s.sourceGeometry = v.sourceGeometry;
    s.materials = v.materials;
    s.fillWeighted = v.fractionsAreFill;
    *stats = s;
  }
  return e;
}

std::optional<std::string> gridFileForSnapshot(const std::string& snapshot) {
  const fs::path p(snapshot);
  static const std::regex pattern(R"(snap_(\d{4,})\.h5)");
  std::smatch m;
  const std::string name = p.filename().string();
  if (!std::regex_match(name, m, pattern)) return std::nullopt;
  const fs::path grid = p.parent_path().parent_path() / "fields" / ("fields_" + m[1].str() + ".vdb");
  if (!fs::exists(grid)) return std::nullopt;
  return grid.string();
}

}  // namespace ejecta::coupling
