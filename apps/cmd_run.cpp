// `ejecta run`: load a scene (or the embedded default), run it, write outputs, print a summary.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "apps/commands.hpp"
#include "apps/interrupt.hpp"
#include "sim/parallel/communicator.hpp"
#include "coupling/run_images.hpp"
#include "coupling/run_thermal.hpp"
#include "fields/crater_summary.hpp"
#include "fields/fragment_outputs.hpp"
#include "fields/shield_outputs.hpp"
#include "fields/run_outputs.hpp"
#include "sim/setup/embedded_scenes.hpp"
#include "sim/run/run.hpp"
#include "sim/run/run_directory.hpp"
#include "sim/setup/memory_estimate.hpp"
#include "sim/setup/scene.hpp"
#include "sim/setup/scene_catalog.hpp"

namespace fs = std::filesystem;

namespace ejecta::app {

using namespace ejecta::coupling;  // the in-situ chain (coupling/)

namespace {

// The source's yield and where it sat, and the target's share (sim/run/energy_ledger.hpp).
void printSource(const LedgerSummary::Source& source) {
  if (source.yieldKt)
    std::printf("  source: yield %.4g kt (%.4g J)", *source.yieldKt, source.yield);
  else
    std::printf("  source: yield %.4g J per metre (2D planar)", source.yield);
  if (source.depthOfBurst) {
    std::printf(", depth of burst %.3g m", *source.depthOfBurst);
    if (source.scaledDepthOfBurst)
      std::printf(" (scaled %.3g m/kt^1/3)", *source.scaledDepthOfBurst);
  }
  std::printf("\n");
  // A target that gained nothing has no kinetic/internal split: 0% of each.
  if (source.targetShareOfYield)
    std::printf("  coupling: the target holds %.1f%% of the yield (%.1f%% kinetic, %.1f%% "
                "internal); the device keeps %.1f%%\n",
                100 * *source.targetShareOfYield, 100 * source.targetKineticFraction.value_or(0.0),
                100 * source.targetInternalFraction.value_or(0.0),
                100 * source.explosiveShareOfYield.value_or(0.0));
}

// The governing thermal pass (coupling/run_thermal.hpp).
void printThermal(const ThermalSummary& thermal) {
  if (const auto& p = thermal.governing) {
    std::printf("  spacecraft: the hottest of %ld pass(es), %s t = %.3g ms (%s/; up to %ld hot "
                "particles -> %ld emitters)\n",
                static_cast<long>(thermal.passes), p->evolving ? "the one from" : "over the rock of",
                p->time * 1e3, p->dir.c_str(), static_cast<long>(p->hotParticles),
                static_cast<long>(p->emitters));
    std::printf("    %-8s %15s %18s %14s\n", "face", "peak flux", "steady (eq. 4.8)", "wall peak");
    for (const ThermalSummary::Face& f : p->faces) {
      std::printf("    %-8s %9.3g W/m^2 %16.0f K", f.name.c_str(), f.peakFlux, f.steadyTemperature);
      if (f.structurePeak) std::printf(" %12.0f K", *f.structurePeak);
      std::printf("\n");
    }
    std::printf("  shield: %s\n", p->recommendation.c_str());
  }
  if (!thermal.note.empty()) std::printf("  thermal: %s\n", thermal.note.c_str());
}

// What the fields/ and thermal hooks hand back at the end of the run, for the printed summary.
struct HookResults {
  std::optional<fields::CraterSummary> crater;
  std::optional<fields::ShieldSummary> shield;
  std::optional<fields::FragmentSummary> fragments;
  std::optional<ThermalSummary> thermal;
};

void printSummary(const RunOutcome& r, const HookResults& hooks, const std::string& outDir) {
  const RunSummary& s = r.summary;
  // wall_seconds sums every invocation of a restarted run; total_wall_seconds is this command's.
  std::printf("ejecta: %s %s: %zu particles, %ld steps to t = %.6g s in %.2f s wall (this command: "
              "%.2f s with set-up and outputs; %d threads)\n",
              s.scene.c_str(), !r.ok ? "FAILED" : r.interrupted ? "INTERRUPTED" : "completed", s.particles, s.steps, s.tEnd,
              s.wallSeconds, s.totalWallSeconds, s.threads);
  if (std::isfinite(s.energy.relativeError))
    std::printf("  energy: initial %.8g J, final %.8g J, relative error %.3g\n", s.energy.initial,
                s.energy.final, s.energy.relativeError);
  else
    std::printf("  energy: final %.8g J (no relative error: the run stopped before its initial "
                "energy was taken)\n", s.energy.final);
  // Individual time steps (docs/time_steps.md): the steps above are sub-steps; the cost is the
  // particle-steps.
  if (s.has("particle_updates"))
    std::printf("  individual time steps: %lld particle-steps (%.3g per particle; %.3g of "
                "particles x sub-steps)\n",
                static_cast<long long>(s.integer("particle_updates")),
                static_cast<double>(s.integer("particle_updates")) / static_cast<double>(s.particles),
                static_cast<double>(s.integer("particle_updates")) /
                    (static_cast<double>(s.particles) * static_cast<double>(std::max(s.steps, 1L))));
  // The crater (fields/crater_summary.hpp).
  if (const auto& c = hooks.crater) {
    if (c->found) {
      std::printf("  crater: depth %.3g m, apparent diameter %.3g m, rim-to-rim %.3g m "
                  "(profile: crater_profile.csv)\n",
                  c->depth, c->apparentDiameter, c->rimDiameter);
      if (c->growth)
        std::printf("  crater %s: %+.1f%% in %s over the last fifth of the run (since t = %.3g s)\n",
                    c->growth->growing ? "still growing" : "has stopped growing",
                    100.0 * c->growth->change, c->planar ? "area" : "volume", c->growth->since);
    }
    else if (!c->note.empty())
      std::printf("  crater: none measured (%s)\n", c->note.c_str());
    if (c->scaled)
      std::printf("  %s\n",
                  fields::describeScaledCrater(
                      c->scalingClass, *c->scaled, c->found ? std::optional<double>(c->volume) : std::nullopt,
                      c->found ? std::optional<double>(c->apparentDiameter) : std::nullopt).c_str());
  }
  // The Whipple shield's verdict (fields/shield_outputs.hpp) and the fragments.
  if (const auto& sh = hooks.shield) {
    std::printf("  Whipple shield: %s\n", fields::describeVerdict(*sh).c_str());
    std::printf("  debris cloud: %.4g g moving at up to %.3g km/s, %.3g mm beyond the bumper, "
                "%.3g mm wide (half-angle %.3g deg); %.4g g on the wall\n",
                sh->cloud.mass * 1e3, sh->cloud.leadingSpeed * 1e-3, sh->cloud.leadingEdge * 1e3,
                2 * sh->cloud.radius * 1e3, sh->cloud.halfAngle * 180 / 3.14159265358979323846,
                sh->cloud.massOnWall * 1e3);
  }
  if (const auto& f = hooks.fragments)
    std::printf("  fragments: %zu (%zu measured, %zu single failed particles); the largest %.4g kg "
                "(%.3g%% of the mass, %.3g mm); sizes below %.3g mm are not measured\n",
                f->fragments, f->resolved, f->failedParticles, f->largestMass,
                100 * f->largestMassFraction, f->largestDiameter * 1e3, f->resolutionLimit * 1e3);
  if (r.ledger.source) printSource(*r.ledger.source);
  if (hooks.thermal) printThermal(*hooks.thermal);
  // One line per gauge: the pulse it recorded (sim/run/gauge_summary.hpp).
  for (const GaugeSummary& g : r.gauges) {
    std::printf("  gauge %s: peak %.4g MPa at %.4g ms", g.name.c_str(), g.peakPressure * 1e-6,
                g.peakTime * 1e3);
    if (g.decayTime && g.decayFit)
      std::printf(", decay constant %.3g us (1/e; fit %.3g us)", *g.decayTime * 1e6,
                  *g.decayFit * 1e6);
    else if (g.decayTime)
      std::printf(", decay constant %.3g us (1/e)", *g.decayTime * 1e6);
    std::printf("\n");
  }
  if (!outDir.empty()) {
    const fs::path dir(outDir);
    std::printf("  outputs: %s/{summary.json, energy.csv, snapshots.xdmf, snapshots/%s%s%s%s%s%s%s%s}\n",
                outDir.c_str(), fs::is_directory(dir / "fields") ? ", fields/" : "",
                hooks.thermal && hooks.thermal->governing ? ", thermal_*/" : "",
                fs::is_directory(dir / "images") ? ", images/" : "",
                fs::exists(dir / "gauges.csv") ? ", gauges.csv" : "",
                fs::exists(dir / "crater_profile.csv") ? ", crater_profile.csv" : "",
                fs::exists(dir / "crater_history.csv") ? ", crater_history.csv" : "",
                fs::exists(dir / "shield_history.csv") ? ", shield_history.csv" : "",
                fs::exists(dir / "fragments.csv") ? ", fragments.csv, size_frequency.csv" : "");
    if (s.has("charts"))
      std::printf("  charts: %s\n", s.text("charts").c_str());
    else if (s.has("charts_note"))
      std::printf("  charts: %s\n", s.text("charts_note").c_str());
  }
  if (!r.ok) std::fprintf(stderr, "ejecta: run failed: %s\n", r.error.c_str());
  if (r.interrupted) std::fprintf(stderr, "ejecta: %s\n", s.message.c_str());
}

// The exit status of a run (documented in `ejecta --help` and the README).
int exitStatus(const RunOutcome& r) {
  if (!r.ok) return 2;
  if (r.interrupted) return InterruptGuard::exitCode();
  return 0;
}

// A new run never writes over another's outputs: its later snapshots would survive among the
// new ones, and a restart would resume the old run (docs/robustness.md).
void prepareOutputDirectory(const std::string& outDir, bool overwrite) {
  const auto earlier = findEarlierRun(outDir);
  if (!earlier) return;
  if (!overwrite)
    throw std::runtime_error(earlier->describe(outDir) +
                             "; give --overwrite to replace it, --restart " + outDir +
                             " to resume it, or another --out");
  const std::size_t removed = clearRunOutputs(outDir);
  std::fprintf(stderr, "ejecta: --overwrite: removed the earlier run's %zu output(s) from '%s'\n",
               removed, outDir.c_str());
}

}  // namespace

void addInSituOutputs(const Scene& scene, RunOptions& options, bool charts) {
  fields::addFieldOutputs(options, scene);
  fields::addShieldOutputs(options, scene);
  fields::addFragmentOutputs(options, scene);
  addImageOutputs(options, scene, charts);
  addThermalOutputs(options, scene, charts);
}

int runCommand(const RunArgs& args) {
  RunOptions options;
  options.started = std::chrono::steady_clock::now();
  options.threads = args.threads;
  // A terminal gets the live line; a log (a batch job, a pipe, CI) a plain line every
  // --progress-every seconds (default 60).
  options.progress = !args.quiet && interactive();
  if (!args.quiet && !options.progress) options.progressInterval = args.progressEvery;
  // Under mpirun: every rank of MPI_COMM_WORLD (one rank otherwise); rank 0 prints.
  options.ranks = worldCommunicator();
  const bool root = options.ranks->isRoot();
  const InterruptGuard interrupts;
  options.interrupted = [] { return InterruptGuard::received() != 0; };
  auto hooks = std::make_shared<HookResults>();
  options.configure = [charts = args.charts, hooks](const Scene& scene, RunOptions& o) {
    fields::addFieldOutputs(o, scene, [hooks](const fields::CraterSummary& c) { hooks->crater = c; });
    fields::addShieldOutputs(o, scene, [hooks](const fields::ShieldSummary& s) { hooks->shield = s; });
    fields::addFragmentOutputs(o, scene, [hooks](const fields::FragmentSummary& f) { hooks->fragments = f; });
    addImageOutputs(o, scene, charts);
    addThermalOutputs(o, scene, charts, [hooks](const ThermalSummary& t) { hooks->thermal = t; });
  };
  if (!args.restartDir.empty()) {
    if (!args.scene.empty())
      throw std::runtime_error("--restart takes the scene stored in the run; do not give a SCENE "
                               "with it (--set time.t_end=... extends the run)");
    options.restartOverrides = args.overrides;
    const RunOutcome r = restartRun(args.restartDir, options);
    if (root) printSummary(r, *hooks, args.restartDir);
    return exitStatus(r);
  }
  std::string source, path;
  if (args.scene.empty()) {
    source = std::string(findEmbeddedScene("default"));
    path = "<default scene>";
  } else {
    SceneText scene = readSceneArgument(args.scene);
    source = std::move(scene.text);
    path = std::move(scene.label);
  }
  const Scene scene = parseScene(source, path, args.overrides);
  options.outDir = args.outDir.empty() ? (fs::path("runs") / scene.name).string() : args.outDir;
  options.sceneSource = source;
  options.overrides = args.overrides;
  if (root) {
    if (options.ranks->size() > 1)
      std::fprintf(stderr, "ejecta: running '%s' (%s) on %d ranks -> %s\n", scene.name.c_str(),
                   path.c_str(), options.ranks->size(), options.outDir.c_str());
    else
      std::fprintf(stderr, "ejecta: running '%s' (%s) -> %s\n", scene.name.c_str(), path.c_str(),
                   options.outDir.c_str());
  }
  // Refusals come before --overwrite clears anything: a run that cannot start keeps the old one.
  requireRunMemory(scene, options.ranks->size());
  if (root) prepareOutputDirectory(options.outDir, args.overwrite);
  // Every rank waits for rank 0's clearing before any writes (a collective).
  if (options.ranks->size() > 1) options.ranks->maximum(0.0);
  const RunOutcome r = runScene(scene, options);
  if (root) printSummary(r, *hooks, options.outDir);
  return exitStatus(r);
}

}  // namespace ejecta::app
