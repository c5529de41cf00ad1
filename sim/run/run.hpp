#pragma once
// Running a scene with its outputs: snapshots (HDF5) at the scene's cadence with one XDMF series,
// the energy ledger of every step (energy.csv), summary.json, and a progress line on a terminal.
// A failure of the numerics writes a last snapshot and a summary with status "failed".
#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sim/setup/scene.hpp"
#include "sim/run/energy_ledger.hpp"
#include "sim/run/gauge_summary.hpp"
#include "sim/run/simulation.hpp"
#include "sim/io/snapshot.hpp"
#include "sim/run/summary.hpp"

namespace ejecta {

struct RunOptions {
  std::string outDir;                  // empty: no files written (verification in memory)
  int threads = 0;                     // 0: OpenMP's default
  bool progress = false;               // a live progress line on stderr (a terminal)
  // A plain progress line on stderr every this many seconds of wall time (a batch job's log,
  // where the live line's carriage returns would pile up); 0: none.
  double progressInterval = 0.0;
  // When the command began (scene read, particles built): summary.json's total_wall_seconds
  // counts from here to its own writing, the end hooks included. Unset: from runScene or
  // restartRun.
  std::optional<std::chrono::steady_clock::time_point> started;
  // A restart's changes to the stored scene (`ejecta run --restart DIR --set ...`): only the
  // keys restartChangeableKeys() lists; restartRun refuses any other, with the reason.
  std::vector<std::string> restartOverrides;
  std::string sceneSource;             // TOML text the scene came from, stored for restarts
  std::vector<std::string> overrides;  // --set strings, stored for restarts
  // Called after every step (and once after initialisation) with the simulation.
  std::function<void(const Simulation&)> observer;
  // Called at every output time, after the snapshot (if any) is written, with its info; `final`
  // is true for the run's last output (also after a failure). For in-situ outputs (fields/).
  std::function<void(const Simulation&, const SnapshotInfo&, bool final)> onOutput;
  // Called once at the end, before summary.json is written, to add to the summary.
  std::function<void(const Simulation&, RunSummary&)> onFinish;
  // Called by runScene and restartRun once the scene is known (a restart reads it from the
  // snapshot), to add hooks for it: the command line adds the fields/ outputs here.
  std::function<void(const Scene&, RunOptions&)> configure;
  // Physics packages beyond what the scene assembles (sim/run/physics_package.hpp), added to the
  // simulation of a new run and of a restart alike (so a package shared by both must keep no
  // state between steps).
  std::vector<std::shared_ptr<PhysicsPackage>> packages;
  // The ranks of a distributed run (sim/parallel/communicator.hpp; nullptr: one rank). Every
  // rank calls runScene or restartRun alike, and every rank calls the hooks, with its own
  // particles (Simulation::particles()): a hook's collectives (a grid's merge, a gather of the
  // particles it draws, Simulation::gatheredParticles()) are made by all ranks, and its files
  // written by rank 0 (Communicator::isRoot()), as the run's own are.
  std::shared_ptr<const Communicator> ranks;
  // Asked after every step: true stops the run there (a signal, docs/robustness.md), with a
  // last snapshot and summary.json of status "interrupted". Every rank asks; any rank's true
  // stops them all.
  std::function<bool()> interrupted;
};

struct RunOutcome {
  RunSummary summary;
  // The summary's typed parts, also written into summary.extras (as summary.json holds them).
  LedgerSummary ledger;
  std::vector<GaugeSummary> gauges;
  bool ok = true;
  bool interrupted = false;            // stopped by RunOptions::interrupted (ok stays true)
  std::string error;                   // the failure, when !ok
};

// Builds the particles from the scene, initialises and runs to t_end.
RunOutcome runScene(const Scene& scene, const RunOptions& options);
// Runs an already-built simulation to t_end (used by runScene and tests).
RunOutcome runSimulation(Simulation& sim, const RunOptions& options);
// Resumes the run in `runDir` from its last snapshot; continues writing there.
RunOutcome restartRun(const std::string& runDir, const RunOptions& options);

// The scene keys a restart may change: time.t_end (to extend a finished or interrupted run; it
// must lie beyond the snapshot's time) and time.max_steps. Every other key would change the run's
// physics, its particles or its outputs' cadence midway.
const std::vector<std::string>& restartChangeableKeys();

// The scene a snapshot was written from (its stored text and --set overrides). Throws
// SceneError naming the snapshot when it holds no scene.
Scene storedScene(const SnapshotInfo& info, const std::string& snapshotPath);

// Resolves the thread count of RunOptions (0 -> the process's OpenMP default at its first use,
// not a smaller one a previous small run set).
int resolveThreads(int requested);

}  // namespace ejecta
