#include "apps/run_thermal.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>

#include "apps/surface_occluder.hpp"
#include "apps/thermal_outputs.hpp"
#include "apps/thermal_picture.hpp"
#include "render/charts.hpp"
#include "sim/embedded_scenes.hpp"
#include "sim/simulation.hpp"

namespace fs = std::filesystem;

namespace ejecta::app {

namespace {

std::string sceneKeyError(const Scene& scene, const std::string& reason) {
  return scene.sourcePath + ":" + std::to_string(scene.thermal.line) + ": key 'thermal.study': " + reason;
}

// One pass as kept for the summary.
struct Pass {
  long snapshotIndex = 0;
  double time = 0.0;
  fs::path dir;
  radiation::ThermalResult result;
  SnapshotEmitterStats stats;
  std::size_t occluderTriangles = 0;  // the asteroid's surface, when the output has grids
  double hottestFace = 0.0;  // [K]
};

struct PassLog {
  std::vector<Pass> passes;
  std::vector<std::string> notes;
  std::size_t nextTime = 0;
  bool started = false;
  std::unique_ptr<render::Renderer> renderer;
  bool pictures = true;
};

double hottestSteadyFace(const radiation::ThermalResult& r) {
  double t = 0.0;
  for (const radiation::PatchThermal& p : r.patches) t = std::max(t, p.steadyTemperature);
  return t;
}

std::string fixed(double x, int digits) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", digits, x);
  return buffer;
}

// The lightest coating that keeps every sized face's structure within its limit, as one line.
std::string recommendation(const radiation::ThermalResult& r) {
  const radiation::PatchThermal* hottest = nullptr;
  bool allWithin = true;
  for (const radiation::PatchThermal& p : r.patches) {
    if (!p.wall) continue;
    allWithin = allWithin && p.structureWithinLimit;
    if (!hottest || p.layerPeak.back() > hottest->layerPeak.back()) hottest = &p;
  }
  std::string best;
  double bestMass = std::numeric_limits<double>::infinity();
  double bestThickness = 0.0;
  for (const auto& [coating, mass] : r.totalAddedMass) {
    if (!std::isfinite(mass) || mass >= bestMass) continue;
    double thickness = 0.0;
    for (const radiation::PatchThermal& p : r.patches)
      for (const radiation::ShieldSizing& s : p.sizing)
        if (s.material == coating) thickness = std::max(thickness, s.thickness);
    best = coating;
    bestMass = mass;
    bestThickness = thickness;
  }
  if (best.empty())
    return r.totalAddedMass.empty() ? "no coatings sized"
                                    : "no candidate coating suffices within the thickest allowed";
  if (bestThickness <= 0.0 && hottest)
    return "none needed: the bare structure peaks at " + fixed(hottest->layerPeak.back(), 0) +
           " K against its " + fixed(hottest->structureLimit, 0) + " K limit" +
           (allWithin ? "" : " (the study's own wall does not)");
  return best + " " + fixed(bestThickness * 1e3, 3) + " mm, +" + fixed(bestMass, 2) + " kg";
}

void addSummary(const Pass& pass, const std::string& outDir, RunSummary& summary) {
  auto& x = summary.extras;
  const radiation::ThermalResult& r = pass.result;
  x.push_back({"thermal_time_s", pass.time});
  x.push_back({"thermal_dir", (fs::path(outDir) / pass.dir).string()});
  x.push_back({"thermal_hot_particles", static_cast<std::int64_t>(pass.stats.hot)});
  x.push_back({"thermal_emitters", static_cast<std::int64_t>(pass.stats.emitters)});
  x.push_back({"thermal_occluder_triangles", static_cast<std::int64_t>(pass.occluderTriangles)});
  std::string faces;
  for (const radiation::PatchThermal& p : r.patches) {
    faces += (faces.empty() ? "" : ",") + p.patch;
    const std::string k = "thermal_" + p.patch;
    x.push_back({k + "_peak_flux_W_m2", p.peakFlux});
    x.push_back({k + "_steady_K", p.steadyTemperature});
    if (p.wall) x.push_back({k + "_structure_peak_K", p.layerPeak.back()});
  }
  x.push_back({"thermal_faces", faces});
  for (const auto& [coating, mass] : r.totalAddedMass) {
    // The thickest any sized face needs (NaN when one cannot be protected).
    double thickness = 0.0;
    for (const radiation::PatchThermal& p : r.patches)
      for (const radiation::ShieldSizing& s : p.sizing)
        if (s.material == coating)
          thickness = s.feasible ? std::max(thickness, s.thickness)
                                 : std::numeric_limits<double>::quiet_NaN();
    x.push_back({"thermal_shield_" + coating + "_mm", thickness * 1e3});
    x.push_back({"thermal_shield_" + coating + "_kg", mass});
  }
  x.push_back({"thermal_shield", recommendation(r)});
}

// flux.png (each face's flux along the pass) and wall_<patch>.png for the hottest face.
void writePassCharts(const Pass& pass, const fs::path& dir, const std::string& name) {
  render::ChartRunner charts;
  if (!charts.chartsAvailable()) return;
  render::ChartSpec flux{.csv = dir / "flux.csv", .x = "time_s", .xlabel = "time in the pass [s]",
                         .ylabel = "incident flux [W/m^2]",
                         .title = name + ": flux on each face", .out = dir / "flux.png"};
  for (const radiation::PatchThermal& p : pass.result.patches)
    flux.series.push_back({.y = p.patch + "_W_m2", .label = p.patch, .markers = true});
  charts.writeChart(flux);
  const radiation::PatchThermal* hottest = nullptr;
  for (const radiation::PatchThermal& p : pass.result.patches)
    if (p.wall && (!hottest || p.peakFlux > hottest->peakFlux)) hottest = &p;
  if (!hottest) return;
  const radiation::LayeredWall& wall = hottest->wall->wall();
  render::ChartSpec temps{.csv = dir / ("wall_" + hottest->patch + ".csv"), .x = "time_s",
                          .series = {{.y = "hot_face_K", .label = "hot face"}},
                          .xlabel = "time in the pass [s]", .ylabel = "temperature [K]",
                          .title = name + ": wall of " + hottest->patch,
                          .out = dir / ("wall_" + hottest->patch + ".png")};
  for (std::size_t k = 0; k + 1 < wall.layerCount(); ++k)
    temps.series.push_back({.y = "interface_" + std::to_string(k + 1) + "_K",
                            .label = wall.layers()[k].material.name + " / " +
                                     wall.layers()[k + 1].material.name});
  temps.series.push_back({.y = "cold_face_K", .label = "cold face"});
  charts.writeChart(temps);
}

}  // namespace

radiation::ThermalStudy loadSceneThermalStudy(const Scene& scene) {
  const std::string& name = scene.thermal.study;
  const fs::path sceneFile(scene.sourcePath);
  const fs::path beside = sceneFile.parent_path() / name;
  try {
    if (fs::is_regular_file(sceneFile) && fs::is_regular_file(beside))
      return radiation::loadThermalStudy(beside);
    std::string embedded = name;
    if (embedded.size() > 5 && embedded.ends_with(".toml")) embedded.resize(embedded.size() - 5);
    const std::string_view text = findEmbeddedScene(embedded);
    if (!text.empty())
      return radiation::parseThermalStudy(std::string(text), "<embedded " + embedded + ">", ".");
  } catch (const radiation::ThermalStudyError& e) {
    throw SceneError(sceneKeyError(scene, e.what()));
  }
  throw SceneError(sceneKeyError(
      scene, "no study file '" + name + "'" +
                 (fs::is_regular_file(sceneFile) ? " beside the scene (" + beside.string() + ")" : "") +
                 " and no study of that name compiled in (e.g. \"thermal/follower\")"));
}

void addThermalOutputs(RunOptions& options, const Scene& scene, bool charts) {
  if (!scene.thermal.enabled || options.outDir.empty()) return;
  if (spatialDimension(scene.geometry) < 3 && scene.geometry != Geometry::Axisymmetric)
    throw SceneError(scene.sourcePath + ":" + std::to_string(scene.thermal.line) +
                     ": table 'thermal': a " + std::string(geometryName(scene.geometry)) +
                     " run has no 3D extent to radiate from; use an RZ or 3D scene");
  auto study = std::make_shared<const radiation::ThermalStudy>(loadSceneThermalStudy(scene));
  std::vector<std::string> names;
  for (const MaterialSpec& m : scene.materials) names.push_back(m.name);
  std::vector<std::string> unknown;
  const SnapshotEmitterOptions emitterOptions = emitterOptionsFor(*study, names, &unknown);
  for (const std::string& m : unknown)
    std::fprintf(stderr, "ejecta: warning: %s: emissivity given for '%s', a material the scene lacks\n",
                 study->source.c_str(), m.c_str());

  auto log = std::make_shared<PassLog>();
  const fs::path outDir = options.outDir;
  const ThermalOutputOptions wanted = scene.thermal;
  const Geometry geometry = scene.geometry;
  const std::string sceneName = scene.name;

  auto previous = options.onOutput;
  options.onOutput = [=](const Simulation& sim, const SnapshotInfo& info, bool final) {
    if (previous) previous(sim, info, final);
    if (!log->started) {
      // A restarted run begins at its last snapshot: the passes before it were made by the run
      // that wrote it (their thermal_NNNN/ are there), so they are not repeated.
      log->started = true;
      while (log->nextTime < wanted.times.size() && wanted.times[log->nextTime] < info.time * (1.0 - 1e-9))
        ++log->nextTime;
    }
    bool due = wanted.times.empty() && final;
    // A time between two outputs is served by the later one (a tiny tolerance for round-off).
    while (log->nextTime < wanted.times.size() &&
           info.time >= wanted.times[log->nextTime] * (1.0 - 1e-9)) {
      due = true;
      ++log->nextTime;
    }
    if (final && log->nextTime < wanted.times.size()) {
      char note[160];
      std::snprintf(note, sizeof note, "thermal times from %.6g s are after the run's end; ran at %.6g s",
                    wanted.times[log->nextTime], info.time);
      log->notes.push_back(note);
      log->nextTime = wanted.times.size();
      due = true;
    }
    if (!due) return;
    Pass pass;
    pass.snapshotIndex = info.snapshotIndex;
    pass.time = info.time;
    char dirName[32];
    std::snprintf(dirName, sizeof dirName, "thermal_%04ld", info.snapshotIndex);
    pass.dir = dirName;
    const auto start = std::chrono::steady_clock::now();
    try {
      const radiation::Emitters emitters =
          emittersFromParticles(sim.particles(), geometry, emitterOptions, &pass.stats);
      // The asteroid's surface occludes when the fields hook (run before this one) wrote the
      // output's grid file with its level set, as `ejecta thermal --from` does by default.
      char gridName[40];
      std::snprintf(gridName, sizeof gridName, "fields_%04ld.vdb", info.snapshotIndex);
      const std::string gridFile = (outDir / "fields" / gridName).string();
      std::optional<radiation::TriangleMesh> occluder;
      const SurfaceOccluderOptions occluderOptions;
      SurfaceOccluderStats occluderStats;
      if (fs::exists(gridFile) && gridFileHasSurface(gridFile))
        occluder = occluderFromGridFile(gridFile, occluderOptions, &occluderStats);
      pass.occluderTriangles = occluderStats.triangles;
      pass.result = radiation::runThermalStudy(*study, emitters, occluder ? &*occluder : nullptr);
      writeThermalOutputs(outDir / pass.dir, *study, pass.result,
                          particleSourceJson("in-situ", info.time, geometry, pass.stats) + ",\n" +
                              occluderJson(occluder ? &gridFile : nullptr, occluderOptions, occluderStats));
    } catch (const std::exception& e) {
      log->notes.push_back("thermal pass at t = " + fixed(info.time * 1e3, 3) + " ms failed: " + e.what());
      std::fprintf(stderr, "ejecta: thermal pass at t = %g s failed: %s\n", info.time, e.what());
      return;
    }
    pass.hottestFace = hottestSteadyFace(pass.result);
    if (log->pictures) {
      try {
        if (!log->renderer) log->renderer = std::make_unique<render::Renderer>();
        writeThermalPicture(*log->renderer, sim.particles(), geometry, info.time, *study, pass.result,
                            sceneName + ": hot material and the spacecraft's faces",
                            outDir / pass.dir / "crater.png");
      } catch (const std::exception& e) {
        log->pictures = false;
        log->notes.push_back(std::string("no thermal pictures: ") + e.what());
      }
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::fprintf(stderr,
                   "ejecta: thermal pass at t = %.4g ms: %zu hot particles -> %zu emitters, %zu occluder "
                   "triangles; hottest steady face %.0f K (%.1f s) -> %s/\n",
                   info.time * 1e3, pass.stats.hot, pass.stats.emitters, pass.occluderTriangles,
                   pass.hottestFace, seconds,
                   (outDir / pass.dir).string().c_str());
    log->passes.push_back(std::move(pass));
  };

  auto previousFinish = options.onFinish;
  options.onFinish = [=](const Simulation& sim, RunSummary& summary) {
    if (previousFinish) previousFinish(sim, summary);
    summary.extras.push_back({"thermal_passes", static_cast<std::int64_t>(log->passes.size())});
    std::string notes;
    for (const std::string& note : log->notes) notes += (notes.empty() ? "" : "; ") + note;
    if (log->passes.empty()) {
      if (!notes.empty()) summary.extras.push_back({"thermal_note", notes});
      return;
    }
    const Pass* governing = &log->passes.front();
    for (const Pass& p : log->passes)
      if (p.hottestFace > governing->hottestFace) governing = &p;
    addSummary(*governing, outDir.string(), summary);
    for (const Pass& p : log->passes) {
      if (!charts) break;
      try {
        writePassCharts(p, outDir / p.dir, sceneName);
      } catch (const std::exception& e) {
        notes += (notes.empty() ? "" : "; ") + std::string("thermal charts failed: ") + e.what();
        break;
      }
    }
    if (!notes.empty()) summary.extras.push_back({"thermal_note", notes});
  };
}

}  // namespace ejecta::app
