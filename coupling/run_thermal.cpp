#include "coupling/run_thermal.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>

#include "coupling/surface_occluder.hpp"
#include "coupling/thermal_charts.hpp"
#include "coupling/thermal_outputs.hpp"
#include "coupling/thermal_picture.hpp"
#include "radiation/format_number.hpp"
#include "render/charts.hpp"
#include "sim/setup/embedded_scenes.hpp"
#include "sim/run/simulation.hpp"

namespace fs = std::filesystem;

namespace ejecta::coupling {

namespace {

std::string sceneKeyError(const Scene& scene, const std::string& reason) {
  return scene.sourcePath + ":" + std::to_string(scene.thermal.line) + ": key 'thermal.study': " + reason;
}

// One finished pass as kept for the summary.
struct Pass {
  double time = 0.0;         // the material's time (snapshot), or the pass's start (evolving) [s]
  bool evolving = false;
  fs::path dir;              // relative to the run's directory
  radiation::ThermalResult result;
  SnapshotEmitterStats stats;          // the frame with the most emitters
  std::size_t occluderTriangles = 0;   // the asteroid's surface, when the output has grids
  double hottestFace = 0.0;            // [K]
};

// An evolving pass under way: the frames captured so far, one per sample time reached.
struct OpenPass {
  double start = 0.0;                  // [s]
  std::vector<std::shared_ptr<const radiation::Emitters>> emitters;
  std::vector<std::shared_ptr<const radiation::TriangleMesh>> occluders;
  SnapshotEmitterStats largest;
};

// The asteroid's surface from the latest grid file the run wrote, meshed once per file.
struct SurfaceCache {
  std::string latestFile;              // set by the output hook
  std::string meshedFile;
  std::shared_ptr<const radiation::TriangleMesh> mesh;
  SurfaceOccluderStats stats;
  const radiation::TriangleMesh* current(const SurfaceOccluderOptions& options) {
    if (latestFile.empty()) return nullptr;
    if (latestFile != meshedFile) {
      meshedFile = latestFile;
      stats = {};
      mesh = gridFileHasSurface(latestFile)
                 ? std::make_shared<const radiation::TriangleMesh>(
                       occluderFromGridFile(latestFile, options, &stats))
                 : nullptr;
    }
    return mesh.get();
  }
};

struct PassLog {
  std::vector<Pass> passes;
  std::vector<OpenPass> open;
  std::vector<std::string> notes;
  std::size_t nextTime = 0;
  bool started = false;
  SurfaceCache surface;
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

// The thickest coating of `coating` any sized face needs [m]; NaN when one cannot be protected.
double thickestCoating(const radiation::ThermalResult& r, const std::string& coating) {
  double thickness = 0.0;
  for (const radiation::PatchThermal& p : r.patches)
    for (const radiation::ShieldSizing& s : p.sizing)
      if (s.material == coating) {
        if (!s.feasible) return std::numeric_limits<double>::quiet_NaN();
        thickness = std::max(thickness, s.thickness);
      }
  return thickness;
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
    best = coating;
    bestMass = mass;
    bestThickness = thickestCoating(r, coating);
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

ThermalSummary::Pass governingSummary(const Pass& pass, const std::string& outDir) {
  const radiation::ThermalResult& r = pass.result;
  ThermalSummary::Pass out;
  out.time = pass.time;
  out.evolving = pass.evolving;
  out.dir = (fs::path(outDir) / pass.dir).string();
  out.hotParticles = static_cast<std::int64_t>(pass.stats.hot);
  out.emitters = static_cast<std::int64_t>(pass.stats.emitters);
  out.occluderTriangles = static_cast<std::int64_t>(pass.occluderTriangles);
  for (const radiation::PatchThermal& p : r.patches) {
    ThermalSummary::Face face{p.patch, p.peakFlux, p.steadyTemperature, std::nullopt};
    if (p.wall) face.structurePeak = p.layerPeak.back();
    out.faces.push_back(std::move(face));
  }
  for (const auto& [coating, mass] : r.totalAddedMass)
    out.shields.push_back({coating, thickestCoating(r, coating) * 1e3, mass});
  out.recommendation = recommendation(r);
  return out;
}

// A pass that failed: a note for the summary and a line on stderr; the run goes on.
// `print`: false on the ranks other than 0 of a distributed run (which know the failure too).
void noteFailure(PassLog& log, const char* atOrFrom, double time, const std::exception& e,
                 bool print = true) {
  const std::string what = std::string("thermal pass ") + atOrFrom + " t = " + fixed(time * 1e3, 3) +
                           " ms failed: " + e.what();
  log.notes.push_back(what);
  if (print) std::fprintf(stderr, "ejecta: %s\n", what.c_str());
}

// What every pass needs, fixed for the run.
struct PassContext {
  std::shared_ptr<const radiation::ThermalStudy> study;
  SnapshotEmitterOptions emitterOptions;
  SurfaceOccluderOptions occluderOptions;
  fs::path outDir;
  Geometry geometry = Geometry::Axisymmetric;
  std::string sceneName;
  bool charts = true;
};

// Runs the chain on the frames, writes the pass's files and picture, and logs it.
// Called on every rank alike (the picture's particles are gathered by all); rank 0 runs the
// chain and writes.
void finishPass(const PassContext& c, PassLog& log, Pass pass,
                const std::vector<radiation::PassFrame>& frames, const std::string& sourceJson,
                const std::string& occluderText, const Simulation& sim,
                std::optional<double> poseTime) {
  const ParticleSet& drawn = sim.gatheredParticles();
  if (!sim.ranks().isRoot()) return;
  const auto start = std::chrono::steady_clock::now();
  try {
    pass.result = radiation::runThermalStudy(*c.study, frames);
    writeThermalOutputs(c.outDir / pass.dir, *c.study, pass.result, sourceJson + ",\n" + occluderText);
  } catch (const std::exception& e) {
    noteFailure(log, pass.evolving ? "from" : "at", pass.time, e);
    return;
  }
  pass.hottestFace = hottestSteadyFace(pass.result);
  if (log.pictures) {
    try {
      if (!log.renderer) log.renderer = std::make_unique<render::Renderer>();
      writeThermalPicture(*log.renderer, drawn, c.geometry, sim.time(), *c.study, pass.result,
                          c.sceneName + ": hot material and the spacecraft's faces",
                          c.outDir / pass.dir / "crater.png", poseTime);
    } catch (const std::exception& e) {
      log.pictures = false;
      log.notes.push_back(std::string("no thermal pictures: ") + e.what());
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::fprintf(stderr,
               "ejecta: thermal pass %s t = %.4g ms: up to %zu hot particles -> %zu emitters, %zu "
               "occluder triangles; hottest steady face %.0f K (%.1f s) -> %s/\n",
               pass.evolving ? "from" : "at", pass.time * 1e3, pass.stats.hot, pass.stats.emitters,
               pass.occluderTriangles, pass.hottestFace, seconds, (c.outDir / pass.dir).string().c_str());
  log.passes.push_back(std::move(pass));
}

// The asteroid's surface as occluder, at rank 0 (none elsewhere). A grid file that cannot be
// meshed leaves the pass without one, noted, rather than failing it: a failure at rank 0 alone
// would put its passes out of step with the other ranks'.
const radiation::TriangleMesh* rootOccluder(const PassContext& c, PassLog& log, const Simulation& sim) {
  if (!sim.ranks().isRoot()) return nullptr;
  try {
    return log.surface.current(c.occluderOptions);
  } catch (const std::exception& e) {
    log.notes.push_back(std::string("no occluder from ") + log.surface.latestFile + ": " + e.what());
    log.surface.mesh = nullptr;
    return nullptr;
  }
}

// The emitters of every rank's hot particles, made at rank 0 (a collective; elsewhere none).
// Only the particles at or above the threshold travel. A bad particle value is thrown on every
// rank alike, so that the ranks' passes stay in step.
std::shared_ptr<const radiation::Emitters> sampleEmitters(const PassContext& c, const Simulation& sim,
                                                          SnapshotEmitterStats& stats) {
  const double threshold = c.emitterOptions.minTemperature;
  const ParticleSet hot = sim.gatherParticlesWhere(
      [threshold](const ParticleSet& p, std::size_t i) { return p.temperature[i] >= threshold; });
  const std::uint64_t total = sim.totalParticles();
  radiation::Emitters emitters;
  std::string error;
  if (sim.ranks().isRoot()) {
    try {
      emitters = emittersFromParticles(hot, c.geometry, c.emitterOptions, &stats);
      stats.particles = total;
    } catch (const std::exception& e) {
      error = e.what();
    }
  }
  error = sim.ranks().firstMessage(error);
  if (!error.empty()) throw std::invalid_argument(error);
  return std::make_shared<const radiation::Emitters>(std::move(emitters));
}

// A pass over the material of one output, frozen during the pass.
// `gridsNow`: this output wrote a grid file; only its surface occludes, as `ejecta thermal --from`
// the snapshot does.
void snapshotPass(const PassContext& c, PassLog& log, const Simulation& sim, const SnapshotInfo& info,
                  bool gridsNow) {
  Pass pass;
  pass.time = info.time;
  char dirName[32];
  std::snprintf(dirName, sizeof dirName, "thermal_%04ld", info.snapshotIndex);
  pass.dir = dirName;
  try {
    const auto emitters = sampleEmitters(c, sim, pass.stats);
    const radiation::TriangleMesh* occluder = gridsNow ? rootOccluder(c, log, sim) : nullptr;
    pass.occluderTriangles = occluder ? occluder->triangleCount() : 0;
    const std::vector<radiation::PassFrame> frames(c.study->approach.times().size(),
                                                   {emitters.get(), occluder});
    const std::string source = particleSourceJson("in-situ", info.time, c.geometry, pass.stats);
    const std::string occluderText =
        occluderJson(occluder ? &log.surface.meshedFile : nullptr, c.occluderOptions, log.surface.stats);
    finishPass(c, log, std::move(pass), frames, source, occluderText, sim, std::nullopt);
  } catch (const std::exception& e) {
    noteFailure(log, "at", info.time, e, sim.ranks().isRoot());
  }
}

// Captures the frames of the evolving passes whose sample times the run has reached, and
// finishes those that are complete. `padding`: the run ends; complete every open pass with its
// last frame.
void advanceEvolvingPasses(const PassContext& c, PassLog& log, const Simulation& sim, bool padding) {
  const std::vector<double> samples = c.study->approach.times();
  std::shared_ptr<const radiation::Emitters> now;  // this step's, made when first needed
  SnapshotEmitterStats nowStats;
  for (std::size_t k = 0; k < log.open.size();) {
    OpenPass& open = log.open[k];
    try {
      while (open.emitters.size() < samples.size() &&
             sim.time() >= (open.start + samples[open.emitters.size()]) * (1.0 - 1e-12)) {
        // Every sample time this step reaches, of every open pass, shares its material.
        if (!now) now = sampleEmitters(c, sim, nowStats);
        if (nowStats.emitters >= open.largest.emitters) open.largest = nowStats;
        // (The occluder is rank 0's alone, as is the chain it feeds.)
        const radiation::TriangleMesh* occluder = rootOccluder(c, log, sim);
        open.emitters.push_back(now);
        open.occluders.push_back(occluder ? log.surface.mesh : nullptr);
      }
    } catch (const std::exception& e) {
      noteFailure(log, "from", open.start, e, sim.ranks().isRoot());
      log.open.erase(log.open.begin() + static_cast<std::ptrdiff_t>(k));
      continue;
    }
    if (padding && !open.emitters.empty() && open.emitters.size() < samples.size()) {
      log.notes.push_back("the run ended " + fixed((open.start + samples.back() - sim.time()) * 1e3, 3) +
                          " ms before the pass from " + fixed(open.start * 1e3, 3) +
                          " ms did: its last samples see the material of the run's end");
      while (open.emitters.size() < samples.size()) {
        open.emitters.push_back(open.emitters.back());
        open.occluders.push_back(open.occluders.back());
      }
    }
    if (open.emitters.size() < samples.size()) {
      ++k;
      continue;
    }
    std::vector<radiation::PassFrame> frames;
    std::size_t triangles = 0;
    for (std::size_t i = 0; i < samples.size(); ++i) {
      frames.push_back({open.emitters[i].get(), open.occluders[i].get()});
      if (open.occluders[i]) triangles = std::max(triangles, open.occluders[i]->triangleCount());
    }
    Pass pass;
    pass.time = open.start;
    pass.evolving = true;
    pass.stats = open.largest;
    pass.occluderTriangles = triangles;
    pass.dir = "thermal_from_" + radiation::formatNumber("%.6g", open.start * 1e3) + "ms";
    std::string source = "  \"emitter_kind\": \"particles\",\n  \"hot_material\": \"evolving\",\n"
                         "  \"pass_start_s\": " + jsonNumber(open.start) +
                         ",\n  \"largest_frame\": {\"hot_particles\": " + std::to_string(open.largest.hot) +
                         ", \"emitters\": " + std::to_string(open.largest.emitters) + "}";
    const std::string occluderText = triangles > 0
        ? "  \"occluder\": {\"level_set\": \"surface\", \"from\": \"the run's latest grid file at each sample\", "
          "\"triangles\": " + std::to_string(triangles) + "}"
        : occluderJson(nullptr, c.occluderOptions, {});
    const OpenPass finished = std::move(open);  // keeps the frames' material alive
    log.open.erase(log.open.begin() + static_cast<std::ptrdiff_t>(k));
    // The picture: the particles now, the spacecraft at its last sample, where it is now.
    finishPass(c, log, std::move(pass), frames, source, occluderText, sim, samples.back());
  }
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

void addThermalOutputs(RunOptions& options, const Scene& scene, bool charts,
                       std::function<void(const ThermalSummary&)> onThermal) {
  if (!scene.thermal.enabled || options.outDir.empty()) return;
  if (spatialDimension(scene.geometry) < 3 && scene.geometry != Geometry::Axisymmetric)
    throw SceneError(scene.sourcePath + ":" + std::to_string(scene.thermal.line) +
                     ": table 'thermal': a " + std::string(geometryName(scene.geometry)) +
                     " run has no 3D extent to radiate from; use an RZ or 3D scene");
  auto context = std::make_shared<PassContext>();
  context->study = std::make_shared<const radiation::ThermalStudy>(loadSceneThermalStudy(scene));
  std::vector<std::string> names;
  for (const MaterialSpec& m : scene.materials) names.push_back(m.name);
  std::vector<std::string> unknown;
  context->emitterOptions = emitterOptionsFor(*context->study, names, &unknown);
  for (const std::string& m : unknown)
    std::fprintf(stderr, "ejecta: warning: %s: emissivity given for '%s', a material the scene lacks\n",
                 context->study->source.c_str(), m.c_str());
  context->outDir = options.outDir;
  context->geometry = scene.geometry;
  context->sceneName = scene.name;
  context->charts = charts;

  auto log = std::make_shared<PassLog>();
  const ThermalOutputOptions wanted = scene.thermal;
  // Every rank makes the same passes in step (their samples are collectives: sampleEmitters);
  // rank 0 runs them and writes their files.
  auto previous = options.onOutput;
  options.onOutput = [=](const Simulation& sim, const SnapshotInfo& info, bool final) {
    if (previous) previous(sim, info, final);
    // The fields hook (added before this one) has written this output's grids, if it writes any.
    char gridName[40];
    std::snprintf(gridName, sizeof gridName, "fields_%04ld.vdb", info.snapshotIndex);
    const fs::path gridFile = context->outDir / "fields" / gridName;
    const bool gridsNow = fs::exists(gridFile);
    if (gridsNow) log->surface.latestFile = gridFile.string();
    if (wanted.evolving) {
      if (final) advanceEvolvingPasses(*context, *log, sim, true);
      return;
    }
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
      log->notes.push_back("thermal times from " + fixed(wanted.times[log->nextTime] * 1e3, 3) +
                           " ms are after the run's end; ran at " + fixed(info.time * 1e3, 3) + " ms");
      log->nextTime = wanted.times.size();
      due = true;
    }
    if (due) snapshotPass(*context, *log, sim, info, gridsNow);
  };

  if (wanted.evolving) {
    auto previousObserver = options.observer;
    options.observer = [=](const Simulation& sim) {
      if (previousObserver) previousObserver(sim);
      if (!log->started) {
        // As above: a restarted run does not repeat the passes that began before it.
        log->started = true;
        while (log->nextTime < wanted.times.size() && wanted.times[log->nextTime] < sim.time() * (1.0 - 1e-9))
          ++log->nextTime;
      }
      // With no times, one pass from the start.
      const std::vector<double> starts = wanted.times.empty() ? std::vector<double>{0.0} : wanted.times;
      while (log->nextTime < starts.size() && sim.time() >= starts[log->nextTime] * (1.0 - 1e-12))
      {
        OpenPass open;
        open.start = starts[log->nextTime++];
        log->open.push_back(std::move(open));
      }
      if (!log->open.empty()) advanceEvolvingPasses(*context, *log, sim, false);
    };
  }

  auto previousFinish = options.onFinish;
  options.onFinish = [=](const Simulation& sim, RunSummary& summary) {
    if (previousFinish) previousFinish(sim, summary);
    if (!log->open.empty()) advanceEvolvingPasses(*context, *log, sim, true);
    if (!sim.ranks().isRoot()) return;
    ThermalSummary thermal;
    thermal.passes = static_cast<std::int64_t>(log->passes.size());
    std::string notes;
    for (const std::string& note : log->notes) notes += (notes.empty() ? "" : "; ") + note;
    if (!log->passes.empty()) {
      const Pass* governing = &log->passes.front();
      for (const Pass& p : log->passes)
        if (p.hottestFace > governing->hottestFace) governing = &p;
      thermal.governing = governingSummary(*governing, context->outDir.string());
      render::ChartRunner chartRunner;
      for (const Pass& p : log->passes) {
        if (!context->charts || !chartRunner.chartsAvailable()) break;
        try {
          writeThermalCharts(chartRunner, p.result, context->outDir / p.dir, context->sceneName);
        } catch (const std::exception& e) {
          notes += (notes.empty() ? "" : "; ") + std::string("thermal charts failed: ") + e.what();
          break;
        }
      }
    }
    thermal.note = notes;
    addToSummary(thermal, summary);
    if (onThermal) onThermal(thermal);
  };
}

}  // namespace ejecta::coupling
