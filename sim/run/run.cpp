#include "sim/run/run.hpp"

#include <omp.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <cstdlib>
#include <limits>
#include <regex>
#include <algorithm>
#include <sstream>

#include "core/atomic_file.hpp"
#include "core/join.hpp"
#include "sim/io/snapshot.hpp"
#include "sim/io/snapshot_checks.hpp"
#include "sim/io/xdmf.hpp"
#include "sim/run/energy_ledger.hpp"
#include "sim/run/run_directory.hpp"
#include "sim/setup/bodies.hpp"
#include "sim/setup/memory_estimate.hpp"
#include "sim/sources/gauge_decay.hpp"
#include "sim/sources/gauges.hpp"
#include "sim/sph/kernel.hpp"

namespace fs = std::filesystem;

namespace ejecta {

namespace {

// The scene's material table as snapshots record it (sim/io/snapshot.hpp, SnapshotMaterial).
std::vector<SnapshotMaterial> materialRecords(const Scene& scene) {
  std::vector<SnapshotMaterial> records;
  for (const MaterialSpec& m : scene.materials) {
    const auto model = [](const ModelSpec& spec) {
      if (!spec.present || spec.model.empty()) return std::string("none");
      return spec.library.empty() ? spec.model : spec.model + " (" + spec.library + ")";
    };
    records.push_back({m.name, m.library.empty() ? m.eos : m.eos + " (" + m.library + ")",
                       model(m.strength), model(m.fracture)});
  }
  return records;
}

std::vector<std::string> materialNames(const std::vector<SnapshotMaterial>& records) {
  std::vector<std::string> names;
  for (const SnapshotMaterial& m : records) names.push_back(m.name);
  return names;
}

constexpr const char* kOverridePrefix = "# ejecta-override: ";
// A delayed deposit the run has fired, with the ledger's state just before it: restart state
// that travels in the stored scene text as a comment line, so a restart neither fires it again
// nor loses the reference its share is measured from.
constexpr const char* kFiringPrefix = "# ejecta-deposit-fired: ";

std::string formatFiring(const DepositFiring& f) {
  std::ostringstream out;
  out.precision(17);
  out << kFiringPrefix << f.deposit << ' ' << f.time << ' ' << f.step;
  for (double c : f.point) out << ' ' << c;
  out << ' ' << f.kineticBefore.size();
  for (double e : f.kineticBefore) out << ' ' << e;
  for (double e : f.internalBefore) out << ' ' << e;
  return out.str();
}

DepositFiring parseFiring(const std::string& text) {
  std::istringstream in(text);
  DepositFiring f;
  std::size_t materials = 0;
  in >> f.deposit >> f.time >> f.step >> f.point[0] >> f.point[1] >> f.point[2] >> materials;
  f.kineticBefore.resize(materials);
  f.internalBefore.resize(materials);
  for (double& e : f.kineticBefore) in >> e;
  for (double& e : f.internalBefore) in >> e;
  if (!in) throw SceneError("stored scene: malformed line '" + std::string(kFiringPrefix) + text + "'");
  return f;
}

std::string snapshotName(long index) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "snap_%04ld.h5", index);
  return buf;
}

// Scene text with the --set overrides recorded as comment lines, so a restart rebuilds the
// same scene from the snapshot alone.
std::string sourceWithOverrides(const RunOptions& o, const std::vector<DepositFiring>& firings = {}) {
  std::string text;
  for (const std::string& s : o.overrides) text += kOverridePrefix + s + "\n";
  for (const DepositFiring& f : firings) text += formatFiring(f) + "\n";
  return text + o.sceneSource;
}

// Inverse of sourceWithOverrides: the scene text and the override strings.
void splitStoredScene(const std::string& stored, std::string& source,
                      std::vector<std::string>& overrides,
                      std::vector<DepositFiring>* firings = nullptr) {
  source.clear();
  overrides.clear();
  std::istringstream in(stored);
  std::string line;
  const std::string prefix = kOverridePrefix, firingPrefix = kFiringPrefix;
  while (std::getline(in, line)) {
    if (line.rfind(prefix, 0) == 0) overrides.push_back(line.substr(prefix.size()));
    else if (line.rfind(firingPrefix, 0) == 0) {
      if (firings) firings->push_back(parseFiring(line.substr(firingPrefix.size())));
    } else source += line + "\n";
  }
}

std::string formatDuration(double seconds) {
  char buf[32];
  if (seconds < 60) std::snprintf(buf, sizeof buf, "%.0fs", seconds);
  else if (seconds < 3600) std::snprintf(buf, sizeof buf, "%.0fm%02.0fs", std::floor(seconds / 60), std::fmod(seconds, 60));
  else std::snprintf(buf, sizeof buf, "%.0fh%02.0fm", std::floor(seconds / 3600), std::fmod(seconds / 60, 60));
  return buf;
}

// Output state of one run directory.
class RunOutputs {
 public:
  // Every rank keeps the logs' state (their sums are collectives); rank 0 alone writes.
  RunOutputs(const RunOptions& o, bool writer) : options_(o), writer_(writer) {
    if (!enabled()) return;
    fs::create_directories(fs::path(o.outDir) / "snapshots");
  }
  bool enabled() const { return writer_ && !options_.outDir.empty(); }
  bool logging() const { return !options_.outDir.empty(); }

  // A restart resumes from a snapshot that the log has usually run past: keep the header and
  // the rows up to `step`, so the resumed steps are not listed twice.
  void truncateEnergyLog(long step) {
    truncateLog("energy.csv", step);
    truncateLog("gauges.csv", step);
  }
  void truncateLog(const char* name, long step) {
    if (!enabled()) return;
    const fs::path path = fs::path(options_.outDir) / name;
    std::ifstream in(path);
    if (!in) return;
    std::string kept, line;
    if (std::getline(in, line)) kept += line + "\n";
    while (std::getline(in, line))
      if (std::stol(line.substr(0, line.find(','))) <= step) kept += line + "\n";
    in.close();
    writeFileAtomically(path, kept);
  }
  // Scenes with several materials get the ledger's columns: <material>_kinetic_J and
  // <material>_internal_J for each, after the totals.
  void openEnergyLog(bool append, const Scene& scene) {
    if (!logging()) return;
    materials_ = scene.materials.size() > 1 ? scene.materials.size() : 0;
    // The target's gain as a share of the yield (a source) or of the impactor's kinetic energy.
    const LedgerGroups g = ledgerGroups(scene);
    coupling_ = materials_ > 0 && !g.target.empty() &&
                (!g.impactor.empty() || !scene.detonations.empty() || !scene.deposits.empty());
    gauged_ = !scene.gauges.empty();
    for (const GaugeSpec& gauge : scene.gauges) gaugePoints_.push_back(gauge.position);
    if (!enabled()) return;
    const fs::path path = fs::path(options_.outDir) / "energy.csv";
    energy_.open(path, append ? std::ios::app : std::ios::trunc);
    if (!append) {
      energy_ << "step,time_s,dt_s,kinetic_J,internal_J,total_J,relative_error,"
                 "momentum_x,momentum_y,momentum_z";
      for (std::size_t m = 0; m < materials_; ++m) {
        const std::string key = ledgerKey(scene.materials[m].name);
        energy_ << ',' << key << "_kinetic_J," << key << "_internal_J";
      }
      if (coupling_) energy_ << ",target_share";
      energy_ << '\n';
    }
    energy_.precision(12);
    if (!scene.gauges.empty()) {
      gauges_.open(fs::path(options_.outDir) / "gauges.csv", append ? std::ios::app : std::ios::trunc);
      if (!append) gauges_ << gaugeHeader(gaugeLayout(scene)) << '\n';
      gauges_.precision(12);
    }
  }
  void logGauges(Simulation& sim) {
    if (!gauged_) return;
    // The particles within reach of a gauge, from every rank (one rank: all of its own).
    const ParticleSet& near = sim.particlesNear(gaugePoints_);
    if (!gauges_.is_open()) return;
    gauges_ << sim.stepCount() << ',' << sim.time()
            << gaugeRow(gaugeLayout(sim.scene()), readGauges(gaugeLayout(sim.scene()), near)) << '\n';
  }
  void logEnergy(const Simulation& sim, double e0) {
    if (!logging()) return;
    const ConservedTotals t = sim.totals();
    const std::vector<ConservedTotals> byMaterial =
        materials_ > 0 ? sim.totalsByMaterial() : std::vector<ConservedTotals>{};
    if (!energy_.is_open()) return;
    // A delayed deposit is a source, not an error: the expected total includes what it added.
    const double expected = e0 + sim.delayedEnergyAdded();
    energy_ << sim.stepCount() << ',' << sim.time() << ',' << sim.lastDt() << ',' << t.kinetic
            << ',' << t.internal << ',' << t.total() << ',' << (t.total() - expected) / std::abs(expected)
            << ',' << t.momentum[0] << ',' << t.momentum[1] << ',' << t.momentum[2];
    if (materials_ > 0) {
      for (const ConservedTotals& m : byMaterial) energy_ << ',' << m.kinetic << ',' << m.internal;
      if (coupling_) energy_ << ',' << couplingShare(reference_, byMaterial);
    }
    energy_ << '\n';
  }
  // Every rank writes its particles into the one file (a collective); rank 0 the XDMF series.
  void writeSnapshot(const Simulation& sim, SnapshotInfo info) {
    if (!logging()) return;
    energy_.flush();
    gauges_.flush();
    const std::string name = snapshotName(info.snapshotIndex);
    info.sceneSource = sourceWithOverrides(options_, sim.depositFirings());
    info.materials = materialRecords(sim.scene());
    const std::uint64_t total = sim.totalParticles();
    ejecta::writeSnapshot((fs::path(options_.outDir) / "snapshots" / name).string(), sim.particles(),
                          info, sim.ranks());
    if (!enabled()) return;
    xdmf_.push_back({"snapshots/" + name, info.time, total, info.geometry,
                     xdmfAttributes(sim.particles()), materialNames(info.materials)});
    writeXdmfSeries((fs::path(options_.outDir) / "snapshots.xdmf").string(), xdmf_);
  }
  void setSeries(std::vector<XdmfEntry> entries) { xdmf_ = std::move(entries); }
  // Each gauge's shock pulse (sim/run/gauge_summary.hpp), from the whole of gauges.csv (a
  // restarted run's too).
  std::vector<GaugeSummary> gaugePulses() {
    if (!gauges_.is_open()) return {};
    gauges_.flush();
    return gaugeSummaries(readGaugePressures((fs::path(options_.outDir) / "gauges.csv").string()));
  }
  void setCouplingReference(CouplingReference ref) { reference_ = std::move(ref); }

 private:
  const RunOptions& options_;
  bool writer_ = true;
  bool gauged_ = false;
  std::vector<std::array<double, 3>> gaugePoints_;
  std::ofstream energy_;
  std::ofstream gauges_;
  std::size_t materials_ = 0;  // ledger columns in energy.csv (0: one material, totals only)
  bool coupling_ = false;      // energy.csv has the target_share column
  CouplingReference reference_;
  std::vector<XdmfEntry> xdmf_;
};

// Progress on stderr: on a terminal one line rewritten in place twice a second; in a batch
// job's log (RunOptions::progressInterval) a plain line every interval, so the log shows the
// run advancing without a wall of carriage returns.
class ProgressLine {
 public:
  ProgressLine(bool live, double interval) : live_(live), interval_(live ? 0.0 : interval) {}
  void update(const Simulation& sim, double wallSeconds, bool force = false) {
    if (live_) {
      if (!force && wallSeconds - last_ < 0.5) return;
      last_ = wallSeconds;
      std::fprintf(stderr, "\r[ejecta] %s    ", describe(sim, wallSeconds).c_str());
      std::fflush(stderr);
    } else if (interval_ > 0 && !force && wallSeconds - last_ >= interval_) {
      last_ = wallSeconds;
      std::fprintf(stderr, "[ejecta] %s, %s wall\n", describe(sim, wallSeconds).c_str(),
                   formatDuration(wallSeconds).c_str());
      std::fflush(stderr);
    }
  }
  void finish() {
    if (live_) std::fprintf(stderr, "\n");
  }

 private:
  static std::string describe(const Simulation& sim, double wallSeconds) {
    const double tEnd = sim.scene().time.tEnd;
    const double fraction = std::clamp(sim.time() / tEnd, 0.0, 1.0);
    const double eta = fraction > 0 ? wallSeconds * (1 - fraction) / fraction : 0.0;
    char line[160];
    std::snprintf(line, sizeof line, "step %ld  t = %.4g s  dt = %.3g s  %5.1f%%  ETA %s",
                  sim.stepCount(), sim.time(), sim.lastDt(), 100 * fraction, formatDuration(eta).c_str());
    return line;
  }
  bool live_;
  double interval_;
  double last_ = 0.0;
};

}  // namespace

int resolveThreads(int requested) {
  // The default is the process's at its first use (OMP_NUM_THREADS or every core): a Simulation
  // lowers OpenMP's own default for a small run (fewer than ~500 particles a thread), which
  // must not carry over to the runs after it in the same process (verify, sweeps, benches).
  static const int processDefault = omp_get_max_threads();
  return requested > 0 ? requested : processDefault;
}

namespace {

bool reached(double time, double target) { return time >= target * (1.0 - 1e-12); }

// The interruption hook's answer, agreed by every rank (a signal may reach one rank first).
bool stopRequested(const Simulation& sim, const RunOptions& options) {
  const bool mine = options.interrupted && options.interrupted();
  if (sim.ranks().size() == 1) return mine;
  return sim.ranks().maximum(mine ? 1.0 : 0.0) > 0.0;
}

// The time loop shared by fresh and restarted runs. `info` holds the output cadence state.
// `atSnapshot`: the current state is already on disk (a restart), so no final duplicate.
// `fresh`: a new run: initialise the simulation and write snapshot 0 first.
RunOutcome drive(Simulation& sim, const RunOptions& options, RunOutputs& outputs,
                 SnapshotInfo info, double wallBefore, bool atSnapshot, bool fresh) {
  const Scene& scene = sim.scene();
  const double tEnd = scene.time.tEnd;
  const double interval = scene.output.snapshotInterval;
  const bool snapshots = scene.output.snapshots;
  const auto start = std::chrono::steady_clock::now();
  auto wall = [&] {
    return wallBefore +
           std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  const bool root = sim.ranks().isRoot();
  ProgressLine progress(options.progress && root, root ? options.progressInterval : 0.0);
  RunOutcome outcome;
  bool lastWritten = atSnapshot;
  double outputSeconds = 0.0;  // writing the snapshots, and the in-situ hooks
  auto snapshot = [&](bool final) {
    const auto begin = std::chrono::steady_clock::now();
    info.time = sim.time();
    info.step = sim.stepCount();
    info.dtNext = sim.dtNext();
    info.wallSeconds = wall();
    sim.evaluateSkipped();  // between synchronisation points: an interrupt or a failure
    if (snapshots) outputs.writeSnapshot(sim, info);
    // On every rank: hooks splat their own particles and merge, or gather what they draw.
    if (options.onOutput) options.onOutput(sim, info, final);
    ++info.snapshotIndex;
    outputSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  };
  if (!fresh)
    outputs.setCouplingReference(couplingReference(scene, info.initialMaterialKinetic,
                                                   info.initialMaterialInternal,
                                                   sim.depositFirings()));
  std::size_t firingsSeen = sim.depositFirings().size();
  try {
    if (fresh) {
      // Derivatives of the initial state; snapshot 0 holds it with them.
      sim.initialise();
      const ConservedTotals t0 = sim.totals();
      info.initialEnergy = t0.total();
      info.initialMomentum = t0.momentum;
      info.initialMaterialKinetic.clear();
      info.initialMaterialInternal.clear();
      for (const ConservedTotals& m : sim.totalsByMaterial()) {
        info.initialMaterialKinetic.push_back(m.kinetic);
        info.initialMaterialInternal.push_back(m.internal);
      }
      outputs.setCouplingReference(couplingReference(scene, info.initialMaterialKinetic,
                                                     info.initialMaterialInternal));
      outputs.logEnergy(sim, info.initialEnergy);
      outputs.logGauges(sim);
      if (options.observer) options.observer(sim);
      snapshot(false);
    }
    while (!reached(sim.time(), tEnd)) {
      if (scene.time.maxSteps > 0 && sim.stepCount() >= scene.time.maxSteps)
        throw SimulationError("reached time.max_steps = " + std::to_string(scene.time.maxSteps) +
                              " at t = " + std::to_string(sim.time()) + " s before t_end");
      const double limit = std::min(tEnd, info.nextOutputTime);
      sim.step(limit);
      lastWritten = false;
      if (stopRequested(sim, options)) {
        outcome.interrupted = true;
        break;
      }
      if (sim.depositFirings().size() != firingsSeen) {  // a delayed source fired: new reference
        firingsSeen = sim.depositFirings().size();
        outputs.setCouplingReference(couplingReference(scene, info.initialMaterialKinetic,
                                                       info.initialMaterialInternal,
                                                       sim.depositFirings()));
      }
      outputs.logEnergy(sim, info.initialEnergy);
      outputs.logGauges(sim);  // (the particles it reads are evaluated)
      if (options.observer) {
        sim.evaluateSkipped();  // an observer may read every particle
        options.observer(sim);
      }
      progress.update(sim, wall());
      if (reached(sim.time(), info.nextOutputTime) && !reached(sim.time(), tEnd)) {
        info.nextOutputTime = interval > 0 ? info.nextOutputTime + interval : tEnd;
        snapshot(false);
        lastWritten = true;
      }
    }
    if (!lastWritten) {
      // An interrupted run's last snapshot keeps the cadence: a restart writes the outputs due.
      if (!outcome.interrupted) info.nextOutputTime = tEnd;
      snapshot(true);
    }
  } catch (const SimulationError& e) {
    outcome.ok = false;
    outcome.error = e.what();
    try {
      snapshot(true);  // the offending state, for diagnosis
    } catch (const std::exception& w) {
      outcome.error += std::string(" (and the last snapshot could not be written: ") + w.what() + ")";
    }
  }
  progress.update(sim, wall(), true);
  progress.finish();

  const ConservedTotals t = sim.totals();
  RunSummary& s = outcome.summary;
  s.scene = scene.name;
  s.particles = sim.totalParticles();
  s.steps = sim.stepCount();
  s.tEnd = sim.time();
  s.wallSeconds = wall();
  s.threads = omp_get_max_threads();
  s.ranks = sim.ranks().size();
  if (s.ranks > 1) {
    // Where a distributed run's time went, on the slowest rank of each (docs/parallel.md).
    const DomainStats& d = sim.domain().stats();
    s.extras.push_back({"halo_exchange_seconds", sim.ranks().maximum(d.haloSeconds)});
    s.extras.push_back({"decomposition_seconds", sim.ranks().maximum(d.rebalanceSeconds)});
    s.extras.push_back({"output_seconds", sim.ranks().maximum(outputSeconds)});
    s.extras.push_back({"rebalances", static_cast<std::int64_t>(d.rebalances)});
    s.extras.push_back({"load_imbalance", d.lastImbalance});
  }
  // How far each resting body was moved to its rest (sim/setup/resting_bodies.hpp).
  for (const BodySpec& b : scene.bodies)
    if (!b.restOn.empty()) s.extras.push_back({"rest_move_" + b.name + "_m", b.restMove});
  s.energy.initial = info.initialEnergy;
  s.energy.final = t.total();
  const double expected = info.initialEnergy + sim.delayedEnergyAdded();
  // A run that stopped before its initial totals were taken has no reference: null in the file.
  s.energy.relativeError = expected != 0.0 ? (t.total() - expected) / std::abs(expected)
                           : t.total() == 0.0 ? 0.0
                                              : std::numeric_limits<double>::quiet_NaN();
  s.momentum.initial = info.initialMomentum;
  s.momentum.final = t.momentum;
  s.status = !outcome.ok           ? RunSummary::Status::Failed
             : outcome.interrupted ? RunSummary::Status::Interrupted
                                   : RunSummary::Status::Completed;
  s.message = outcome.error;
  if (outcome.interrupted)
    s.message = "interrupted at t = " + std::to_string(sim.time()) + " s (step " +
                std::to_string(sim.stepCount()) + ") before t_end; resume with ejecta run --restart " +
                options.outDir;
  s.extras.push_back({"geometry", std::string(geometryName(scene.geometry))});
  s.extras.push_back({"kernel", std::string(kernelName(scene.sph.kernel))});
  s.extras.push_back({"mean_neighbours", sim.meanNeighbours()});
  // Particle-steps per second. With individual time steps a (sub-)step advances only the
  // particles whose step ends there (docs/time_steps.md): the cost is the updates counted since
  // this invocation began (a restart's own part), over this invocation's wall time.
  double rate = s.wallSeconds > 0 ? static_cast<double>(s.particles) *
                                        static_cast<double>(s.steps) / s.wallSeconds
                                  : 0.0;
  s.extras.push_back({"stepping", std::string(sim.individualSteps() ? "individual" : "global")});
  if (sim.individualSteps()) {
    const double ownWall = wall() - wallBefore;
    s.extras.push_back({"particle_updates", static_cast<std::int64_t>(sim.particleUpdates())});
    rate = ownWall > 0 ? static_cast<double>(sim.particleUpdates()) / ownWall : 0.0;
  }
  s.extras.push_back({"particle_updates_per_second", rate});
  outcome.ledger = ledgerSummary(scene, info.initialMaterialKinetic, info.initialMaterialInternal,
                                 sim.totalsByMaterial(),
                                 sim.depositFirings());
  addToSummary(outcome.ledger, s);
  outcome.gauges = outputs.gaugePulses();
  addToSummary(outcome.gauges, s);
  // On every rank, as onOutput (the summary is rank 0's).
  if (options.onFinish) options.onFinish(sim, s);
  s.totalWallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                                     options.started.value_or(start)).count();
  if (outputs.enabled())
    writeSummaryJson((fs::path(options.outDir) / "summary.json").string(), s);
  return outcome;
}

}  // namespace

RunOutcome runSimulation(Simulation& sim, const RunOptions& options) {
  RunOutputs outputs(options, sim.ranks().isRoot());
  SnapshotInfo info;
  info.geometry = sim.scene().geometry;
  info.scene = sim.scene().name;
  const double interval = sim.scene().output.snapshotInterval;
  info.nextOutputTime = interval > 0 ? interval : sim.scene().time.tEnd;
  outputs.openEnergyLog(false, sim.scene());
  return drive(sim, options, outputs, info, 0.0, false, true);
}

RunOutcome runScene(const Scene& scene, const RunOptions& baseOptions) {
  RunOptions options = baseOptions;
  if (!options.started) options.started = std::chrono::steady_clock::now();
  if (options.configure) options.configure(scene, options);
  requireRunMemory(scene, options.ranks ? options.ranks->size() : 1);
  const int threads = resolveThreads(options.threads);
  MaterialTable materials = MaterialTable::fromScene(scene);
  // A distributed run builds each rank's slice only (unless its flaws need the whole body).
  ParticleSet particles = buildParticles(scene, materials, options.ranks.get());
  Simulation sim(scene, std::move(particles), std::move(materials), threads, options.ranks);
  for (const auto& package : options.packages) sim.addPackage(package);
  return runSimulation(sim, options);
}

namespace {

// A restart's --set: one of restartChangeableKeys(), or a refusal naming the key and why.
std::string keyOf(const std::string& change) {
  std::string key = change.substr(0, change.find('='));
  key.erase(0, key.find_first_not_of(" \t"));
  key.erase(key.find_last_not_of(" \t") + 1);
  return key;
}

void requireRestartChangeable(const std::string& change, const std::string& runDir) {
  const std::string key = keyOf(change);
  const auto& keys = restartChangeableKeys();
  if (change.find('=') == std::string::npos)
    throw SceneError("restart of " + runDir + ": --set '" + change + "' is not key=value");
  if (std::find(keys.begin(), keys.end(), key) != keys.end()) return;
  throw SceneError("restart of " + runDir + ": key '" + key + "' cannot change at a restart (the "
                   "run so far was made with the stored value; changing it midway would make the "
                   "outputs of no one scene); a restart may change " + joinList(keys) +
                   ". To run with another value, start a new run");
}

// The stored overrides that identify a run: those a restart may add are left out, so an
// extended run's snapshots are of the same run as the ones before the extension.
std::vector<std::string> identifyingOverrides(const std::vector<std::string>& overrides) {
  std::vector<std::string> kept;
  const auto& keys = restartChangeableKeys();
  for (const std::string& o : overrides)
    if (std::find(keys.begin(), keys.end(), keyOf(o)) == keys.end()) kept.push_back(o);
  return kept;
}

// A restart resumes the run its last snapshot holds; every earlier snapshot in the directory
// must be of that run (the same scene text and overrides; the delayed deposits fired differ).
void requireSameRun(const SnapshotInfo& earlier, const fs::path& earlierPath, const SnapshotInfo& last,
                    const fs::path& lastPath) {
  std::string a, b;
  std::vector<std::string> aOverrides, bOverrides;
  splitStoredScene(earlier.sceneSource, a, aOverrides);
  splitStoredScene(last.sceneSource, b, bOverrides);
  if (earlier.scene == last.scene && a == b &&
      identifyingOverrides(aOverrides) == identifyingOverrides(bOverrides) && earlier.time <= last.time)
    return;
  throw std::runtime_error(
      "restart: " + earlierPath.string() + " is not of the run in " + lastPath.string() +
      (earlier.scene != last.scene ? " (scene '" + earlier.scene + "', not '" + last.scene + "')"
       : earlier.time > last.time  ? " (it is later than the last snapshot)"
                                   : " (its stored scene or --set overrides differ)") +
      ": the directory mixes two runs; start the run again with --overwrite or into another --out");
}

}  // namespace

const std::vector<std::string>& restartChangeableKeys() {
  static const std::vector<std::string> keys = {"time.t_end", "time.max_steps"};
  return keys;
}

Scene storedScene(const SnapshotInfo& info, const std::string& snapshotPath) {
  if (info.sceneSource.empty())
    throw SceneError(snapshotPath + ": the snapshot holds no scene (/restart/scene_source is empty)");
  std::string source;
  std::vector<std::string> overrides;
  splitStoredScene(info.sceneSource, source, overrides);
  return parseScene(source, snapshotPath + " (stored scene)", overrides);
}

RunOutcome restartRun(const std::string& runDir, const RunOptions& baseOptions) {
  const fs::path dir = fs::path(runDir) / "snapshots";
  if (!fs::is_directory(dir))
    throw std::runtime_error("restart: '" + runDir + "' has no snapshots/ directory");
  std::vector<fs::path> files;
  const std::regex pattern(R"(snap_(\d{4,})\.h5)");
  for (const auto& entry : fs::directory_iterator(dir))
    if (std::regex_match(entry.path().filename().string(), pattern)) files.push_back(entry.path());
  if (files.empty()) throw std::runtime_error("restart: no snap_NNNN.h5 in '" + dir.string() + "'");
  // By snapshot index, not by name: snap_10000 comes after snap_9999.
  auto index = [](const fs::path& f) { return std::stol(f.stem().string().substr(5)); };
  std::sort(files.begin(), files.end(),
            [&](const fs::path& a, const fs::path& b) { return index(a) < index(b); });
  // Writes a killed process never finished (docs/robustness.md): nothing reads them.
  if (!baseOptions.ranks || baseOptions.ranks->isRoot()) removeStaleTemporaries(runDir);

  SnapshotInfo info;
  // A distributed restart: each rank reads its slice of the rows (Simulation then decomposes);
  // scenes whose flaws are drawn from the whole body read it whole, as they are built
  // (setup/bodies.hpp). Which it is, the stored scene says: every rank reads it first.
  int part = baseOptions.ranks ? baseOptions.ranks->rank() : 0;
  int parts = baseOptions.ranks ? baseOptions.ranks->size() : 1;
  if (parts > 1) {
    const SnapshotInfo head = readSnapshotInfo(files.back().string());
    if (needsWholeBody(MaterialTable::fromScene(storedScene(head, files.back().string())))) {
      part = 0;
      parts = 1;
    }
  }
  ParticleSet particles = readSnapshot(files.back().string(), info, part, parts);
  const std::size_t storedParticles =
      parts > 1 ? static_cast<std::size_t>(baseOptions.ranks->sum(particles.numReal)) : particles.numReal;
  RunOptions options = baseOptions;
  if (!options.started) options.started = std::chrono::steady_clock::now();
  options.outDir = runDir;
  // The scene as the run was started: its text and --set overrides travel in the snapshot.
  std::vector<DepositFiring> firings;
  splitStoredScene(info.sceneSource, options.sceneSource, options.overrides, &firings);
  for (const std::string& change : options.restartOverrides) {
    requireRestartChangeable(change, runDir);
    options.overrides.push_back(change);  // stored with the others: a later restart keeps it
  }
  const std::vector<std::string>& overrides = options.overrides;
  Scene scene = parseScene(options.sceneSource, files.back().string() + " (stored scene)", overrides);
  bool extendsEnd = false, changesSteps = false;
  for (const std::string& change : options.restartOverrides) {
    extendsEnd = extendsEnd || keyOf(change) == "time.t_end";
    changesSteps = changesSteps || keyOf(change) == "time.max_steps";
  }
  if (extendsEnd && scene.time.tEnd <= info.time * (1.0 + 1e-12))
    throw SceneError("restart: time.t_end = " + std::to_string(scene.time.tEnd) + " s is not beyond the last "
                     "snapshot's t = " + std::to_string(info.time) + " s of " + runDir);
  if (changesSteps && scene.time.maxSteps > 0 && scene.time.maxSteps <= info.step)
    throw SceneError("restart: time.max_steps = " + std::to_string(scene.time.maxSteps) + " is not beyond the " +
                     std::to_string(info.step) + " steps the run in " + runDir + " has taken");
  if (extendsEnd && reached(info.time, info.nextOutputTime)) {
    // A finished run's last snapshot is its final output: the extension's outputs keep the run's
    // cadence, each time summed interval by interval as the time loop sums them, so the steps
    // land where a straight run's land, to the bit.
    const double interval = scene.output.snapshotInterval;
    double next = interval > 0 ? interval : scene.time.tEnd;
    while (interval > 0 && reached(info.time, next)) next += interval;
    info.nextOutputTime = next;
  }
  checkSnapshotMaterials(particles, scene.materials.size(), files.back().string());
  if (options.configure) options.configure(scene, options);

  const bool root = !options.ranks || options.ranks->isRoot();
  RunOutputs outputs(options, root);
  std::vector<XdmfEntry> series;
  // The packages' declarations say which of their fields the XDMF lists (a snapshot stores the
  // values, not the declaration).
  for (const auto& package : options.packages) package->registerFields(particles);
  // The series so far, for rank 0's XDMF (the other ranks write none).
  for (const fs::path& f : root ? files : std::vector<fs::path>{}) {
    SnapshotInfo earlier;
    ParticleSet q = f == files.back() ? ParticleSet{} : readSnapshot(f.string(), earlier);
    if (f != files.back()) requireSameRun(earlier, f, info, files.back());
    if (f != files.back())
      for (const auto& package : options.packages) package->registerFields(q);
    const double time = f == files.back() ? info.time : earlier.time;
    const ParticleSet& stored = f == files.back() ? particles : q;
    // What the file itself holds: snapshots of older versions lack some datasets.
    const SnapshotLayout layout = readSnapshotLayout(f.string());
    std::vector<XdmfAttribute> attributes;
    for (const XdmfAttribute& a : xdmfAttributes(stored))
      if (std::find(layout.particleDatasets.begin(), layout.particleDatasets.end(), a.name) !=
          layout.particleDatasets.end())
        attributes.push_back(a);
    series.push_back({"snapshots/" + f.filename().string(), time,
                      f == files.back() ? storedParticles : stored.numReal, scene.geometry,
                      attributes, materialNames(materialRecords(scene)), layout.xdmfVertices});
  }
  outputs.setSeries(series);
  outputs.truncateEnergyLog(info.step);
  outputs.openEnergyLog(true, scene);

  const int threads = resolveThreads(options.threads);
  MaterialTable materials = MaterialTable::fromScene(scene);
  // Weibull flaws are drawn from the particles as built at t = 0: rebuild them for the draw.
  const bool needsFlaws = [&] {
    for (std::size_t m = 0; m < materials.size(); ++m)
      if (materials[m].fracture.kind == FractureKind::GradyKipp) return true;
    return false;
  }();
  const ParticleSet initial = needsFlaws ? buildParticles(scene, materials) : ParticleSet{};
  Simulation sim(scene, std::move(particles), std::move(materials), threads, options.ranks);
  for (const auto& package : options.packages) sim.addPackage(package);
  if (needsFlaws) sim.distributeFlaws(initial);
  sim.resume(info.time, info.step, info.dtNext);
  sim.restoreDepositFirings(std::move(firings));
  info.snapshotIndex += 1;
  return drive(sim, options, outputs, info, info.wallSeconds, true, false);
}

}  // namespace ejecta
