// `ejecta thermal STUDY.toml --from RUN_DIR|SNAPSHOT.h5|GRIDS.vdb [--emitters particles|voxels]
// [--occlude|--no-occlude] [--occluder-inset VOXELS] [--out DIR] [--json]`: the radiation chain
// on a run's hot material: flux on every spacecraft patch along the pass, eq. 4.8 face
// temperatures, transient walls and coating sizing (radiation/thermal_study.hpp,
// docs/thermal.md). The hot material is the snapshot's particles (coupling/snapshot_emitters.hpp) or
// the grid file's hot voxels (coupling/grid_emitters.hpp); the asteroid's surface, meshed from the
// grid file's level set, occludes (coupling/surface_occluder.hpp). Writes flux.csv,
// wall_<patch>.csv, sizing.csv and thermal.json.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "apps/commands.hpp"
#include "core/join.hpp"
#include "coupling/grid_emitters.hpp"
#include "coupling/snapshot_emitters.hpp"
#include "coupling/surface_occluder.hpp"
#include "coupling/thermal_charts.hpp"
#include "coupling/thermal_outputs.hpp"
#include "radiation/thermal_study.hpp"
#include "sim/io/snapshot.hpp"
#include "sim/io/snapshot_checks.hpp"
#include "sim/run/run.hpp"
#include "sim/setup/scene_catalog.hpp"

namespace ejecta::app {

using namespace ejecta::coupling;  // the in-situ chain (coupling/)

namespace fs = std::filesystem;

namespace {

// Where the outputs go: RUN_DIR/thermal for a run's snapshot or grid file, else runs/<study name>.
fs::path defaultOutDir(const fs::path& input, const std::string& name) {
  const fs::path parent = input.parent_path();
  if (parent.filename() == "snapshots" || parent.filename() == "fields") return parent.parent_path() / "thermal";
  return fs::path("runs") / name;
}

// The spheres' total volume [m^3]: what each kind of emitter makes of the same hot material.
double emitterVolume(const radiation::Emitters& e) {
  double v = 0.0;
  for (double r : e.radius) v += 4.0 / 3.0 * std::numbers::pi * r * r * r;
  return v;
}

bool isGridFile(const std::string& path) {
  return fs::path(path).extension() == ".vdb" && !fs::is_directory(path);
}

// What --from, --emitters and --occlude resolve to.
struct Inputs {
  bool voxels = false;                   // emitters from the grid file's hot voxels
  std::string snapshot;                  // particles: the snapshot
  std::optional<std::string> gridFile;   // the grid file of the same output, if any
  bool occlude = false;
};

Inputs resolveInputs(const ThermalArgs& args) {
  if (args.emitters != "" && args.emitters != "particles" && args.emitters != "voxels")
    throw std::runtime_error("--emitters " + args.emitters + ": expected particles or voxels");
  if (args.occlude && args.noOcclude) throw std::runtime_error("--occlude and --no-occlude contradict each other");
  Inputs in;
  if (isGridFile(args.from)) {
    if (!fs::exists(args.from)) throw std::runtime_error(args.from + ": no such grid file");
    if (args.emitters == "particles")
      throw std::runtime_error(args.from + ": a grid file holds no particles; --emitters particles needs a run "
                               "directory or a snapshot");
    in.voxels = true;
    in.gridFile = args.from;
  } else {
    in.snapshot = resolveSnapshotPath(args.from);
    in.gridFile = gridFileForSnapshot(in.snapshot);
    in.voxels = args.emitters == "voxels";
    if (in.voxels && !in.gridFile)
      throw std::runtime_error(in.snapshot + ": no grid file fields/fields_NNNN.vdb was written with this "
                               "snapshot; voxel emitters need one (a [fields] table in the scene, or "
                               "`ejecta fields SNAPSHOT.h5 --out RUN_DIR/fields/fields_NNNN.vdb`)");
  }
  const bool surface = in.gridFile && gridFileHasSurface(*in.gridFile);
  if (args.occlude && !surface)
    throw std::runtime_error((in.gridFile ? *in.gridFile + ": no \"surface\" level set"
                                          : in.snapshot + ": no grid file of this output") +
                             " to occlude with (--occlude); the scene's [fields] table writes it (level_set = true)");
  in.occlude = args.noOcclude ? false : (args.occlude || surface);
  return in;
}

}  // namespace

int thermalCommand(const ThermalArgs& args) {
  // A file, or a shipped study's name ("thermal/follower", `ejecta scenes`), as `ejecta run` takes scenes.
  const SceneText text = readSceneArgument(args.scene, "thermal study");
  const radiation::ThermalStudy study =
      radiation::parseThermalStudy(text.text, text.label, text.directory);
  if (args.from.empty())
    throw std::runtime_error(args.scene + ": no hot material: give --from RUN_DIR, SNAPSHOT.h5 or GRIDS.vdb");
  const Inputs in = resolveInputs(args);

  radiation::Emitters emitters;
  std::vector<std::string> materialNames;
  std::string sourceJson, sourceText;
  if (in.voxels) {
    GridEmitterOptions options;
    options.minTemperature = study.emitters.minTemperature;
    options.defaultEmissivity = study.emitters.defaultEmissivity;
    options.emissivityByMaterial = study.emitters.emissivityByMaterial;
    GridEmitterStats s;
    emitters = emittersFromGridFile(*in.gridFile, options, &s);
    materialNames = s.materials;
    sourceJson = "  \"emitter_kind\": \"voxels\",\n  \"grid_file\": {\"path\": " + jsonString(*in.gridFile) +
                 ", \"time_s\": " + jsonNumber(s.time) + ", \"geometry\": " + jsonString(s.sourceGeometry) +
                 ", \"voxel_size_m\": " + jsonNumber(s.voxelSize) + ", \"active_voxels\": " + std::to_string(s.activeVoxels) +
                 ", \"hot_voxels\": " + std::to_string(s.hotVoxels) + ", \"emitters\": " + std::to_string(s.emitters) +
                 ", \"hot_volume_m3\": " + jsonNumber(s.hotVolume) + ", \"fill_weighted\": " + (s.fillWeighted ? "true" : "false") +
                 "}";
    char line[512];
    std::snprintf(line, sizeof line,
                  "grid file %s (t = %g s, %s, voxel %g m): %zu active voxels, %zu at >= %g K -> %zu voxel "
                  "emitters (%.4g m^3%s)\n",
                  in.gridFile->c_str(), s.time, s.sourceGeometry.c_str(), s.voxelSize, s.activeVoxels, s.hotVoxels,
                  study.emitters.minTemperature, s.emitters, s.hotVolume,
                  s.fillWeighted ? ", each sphere the voxel's filled fraction" : ", full voxels");
    sourceText = line;
  } else {
    SnapshotInfo info;
    const ParticleSet particles = readSnapshot(in.snapshot, info);
    try {
      for (const MaterialSpec& m : storedScene(info, in.snapshot).materials) materialNames.push_back(m.name);
    } catch (const std::exception&) {
      // No stored scene: the groups are "material<m>" and every material takes the default.
    }
    if (!materialNames.empty()) checkSnapshotMaterials(particles, materialNames.size(), in.snapshot);
    const SnapshotEmitterOptions options = emitterOptionsFor(study, materialNames);
    SnapshotEmitterStats stats;
    emitters = emittersFromParticles(particles, info.geometry, options, &stats);
    sourceJson = particleSourceJson(in.snapshot, info.time, info.geometry, stats);
    char line[512];
    std::snprintf(line, sizeof line,
                  "snapshot %s (t = %g s, %s): %zu particles, %zu at >= %g K -> %zu emitter spheres (%.4g m^3)\n",
                  in.snapshot.c_str(), info.time, std::string(geometryName(info.geometry)).c_str(), stats.particles,
                  stats.hot, study.emitters.minTemperature, stats.emitters, emitterVolume(emitters));
    sourceText = line;
  }
  sourceJson += ",\n  \"emitter_volume_m3\": " + jsonNumber(emitterVolume(emitters));
  for (const auto& [name, eps] : study.emitters.emissivityByMaterial)
    if (std::find(materialNames.begin(), materialNames.end(), name) == materialNames.end())
      std::fprintf(stderr, "ejecta thermal: warning: %s: emissivity given for '%s', a material the %s lacks\n",
                   args.scene.c_str(), name.c_str(), in.voxels ? "grid file" : "snapshot");

  radiation::TriangleMesh occluder;
  std::string occluderText = occluderJson(nullptr, {}, {});
  if (in.occlude) {
    SurfaceOccluderOptions options;
    options.insetVoxels = args.occluderInset;
    SurfaceOccluderStats s;
    occluder = occluderFromGridFile(*in.gridFile, options, &s);
    occluderText = occluderJson(&*in.gridFile, options, s);
    char line[512];
    std::snprintf(line, sizeof line, "occluder: the surface of %s, %g m (%g voxels) inside, %zu triangles, %.4g m^2\n",
                  in.gridFile->c_str(), s.inset, options.insetVoxels, s.triangles, s.area);
    sourceText += line;
  } else {
    sourceText += "occluder: none (only the spacecraft blocks rays)\n";
  }

  const radiation::ThermalResult result = radiation::runThermalStudy(study, emitters, in.occlude ? &occluder : nullptr);

  const fs::path input = in.voxels ? fs::path(*in.gridFile) : fs::path(in.snapshot);
  const fs::path out = args.outDir.empty() ? defaultOutDir(input, study.name) : fs::path(args.outDir);
  const std::string json = writeThermalOutputs(out, study, result, sourceJson + ",\n" + occluderText);

  // Charts beside the CSVs when matplotlib is there; a failed chart costs only the chart.
  std::string chartsText;
  render::ChartRunner charts;
  if (!args.noCharts && charts.chartsAvailable()) {
    try {
      chartsText = joinList(writeThermalCharts(charts, result, out, study.name));
    } catch (const std::exception& e) {
      std::fprintf(stderr, "ejecta: thermal charts failed: %s\n", e.what());
    }
  }

  if (args.json) {
    std::fputs(json.c_str(), stdout);
  } else {
    std::fputs(sourceText.c_str(), stdout);
    std::fputs(radiation::formatThermalText(result).c_str(), stdout);
    std::printf("wrote %s/{flux.csv, wall_<patch>.csv%s, thermal.json%s%s}\n", out.string().c_str(),
                study.sizing.coatings.empty() ? "" : ", sizing.csv", chartsText.empty() ? "" : ", ",
                chartsText.c_str());
  }
  return 0;
}

}  // namespace ejecta::app
