#pragma once
// What a run directory holds, so that a new run never mixes its outputs with an earlier run's
// (whose later snapshots a restart would otherwise resume) and interrupted writes leave nothing
// behind. docs/robustness.md.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

namespace ejecta {

// An earlier run found in a directory: what its files say.
struct EarlierRun {
  std::string scene;          // from its last snapshot ("" when none could be read)
  std::size_t snapshots = 0;  // snap_NNNN.h5 files
  double lastTime = 0.0;      // the last snapshot's time [s]
  std::string describe(const std::filesystem::path& dir) const;
};

// The run in `dir`, if it holds one (a snapshots/ directory with snapshots, summary.json or
// energy.csv); nullopt for a missing or empty directory or one with other files only.
std::optional<EarlierRun> findEarlierRun(const std::filesystem::path& dir);

// Removes what a run writes in `dir` (snapshots/, snapshots.xdmf, the logs, summary.json, the
// in-situ outputs fields/, images/, thermal_*/, the crater and gauge tables and charts) and
// nothing else: the user's own files there stay. Returns the entries removed.
std::size_t clearRunOutputs(const std::filesystem::path& dir);

// Removes the temporary files of writes that never completed (".NAME.tmp-XXXXXXXXXXXXXXXX",
// core/atomic_file.hpp) in `dir` and its run subdirectories, as a process killed mid-write
// leaves them. Returns how many were removed.
std::size_t removeStaleTemporaries(const std::filesystem::path& dir);

}  // namespace ejecta
