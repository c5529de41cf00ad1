#include "sim/run/run_directory.hpp"

#include <cstdio>
#include <regex>
#include <system_error>
#include <vector>

#include "sim/io/snapshot.hpp"

namespace fs = std::filesystem;

namespace ejecta {

namespace {

bool isSnapshotName(const std::string& name) {
  static const std::regex pattern(R"(snap_\d{4,}\.h5)");
  return std::regex_match(name, pattern);
}

// Top-level files and directories a run writes (sim/run/run.cpp, fields/run_outputs.cpp,
// fields/shield_outputs.cpp, fields/fragment_outputs.cpp,
// coupling/run_images.cpp, coupling/run_thermal.cpp, the charts).
bool isRunOutput(const fs::directory_entry& entry) {
  static const std::regex names(
      R"((snapshots|fields|images|fragments)|thermal_[A-Za-z0-9_.]+|snapshots\.xdmf|summary\.json|)"
      R"(energy(_partition)?\.(csv|png)|gauges\.(csv|png)|gauges_reference\.csv|coupling\.png|)"
      R"(crater_(profile|history|growth|volume)\.(csv|png)|shield_history\.(csv|png)|)"
      R"(fragments\.csv|size_frequency\.(csv|png)|fragment_speeds\.png)");
  return std::regex_match(entry.path().filename().string(), names);
}

bool isStaleTemporary(const std::string& name) {
  static const std::regex pattern(R"(\..+\.tmp-[0-9a-f]{16})");
  return std::regex_match(name, pattern);
}

}  // namespace

std::string EarlierRun::describe(const fs::path& dir) const {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", lastTime);
  std::string text = "'";  // built stepwise: GCC 12 gives a false -Wrestrict on "'" + string
  text += dir.string();
  text += "' holds an earlier run";
  if (!scene.empty()) text += " of scene '" + scene + "'";
  text += " (" + std::to_string(snapshots) + " snapshot(s)";
  if (snapshots > 0) text += std::string(", the last at t = ") + buf + " s";
  return text + ")";
}

std::optional<EarlierRun> findEarlierRun(const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return std::nullopt;
  EarlierRun run;
  fs::path last;
  long lastIndex = -1;
  if (fs::is_directory(dir / "snapshots", ec))
    for (const auto& entry : fs::directory_iterator(dir / "snapshots", ec)) {
      const std::string name = entry.path().filename().string();
      if (!isSnapshotName(name)) continue;
      ++run.snapshots;
      const long index = std::stol(name.substr(5));
      if (index > lastIndex) lastIndex = index, last = entry.path();
    }
  const bool logs = fs::exists(dir / "summary.json", ec) || fs::exists(dir / "energy.csv", ec);
  if (run.snapshots == 0 && !logs) return std::nullopt;
  if (!last.empty()) {
    try {
      const SnapshotInfo info = readSnapshotInfo(last.string());
      run.scene = info.scene;
      run.lastTime = info.time;
    } catch (const std::exception&) {
      // A damaged snapshot still marks the directory as a run's.
    }
  }
  return run;
}

std::size_t clearRunOutputs(const fs::path& dir) {
  std::error_code ec;
  std::vector<fs::path> doomed;
  for (const auto& entry : fs::directory_iterator(dir, ec))
    if (isRunOutput(entry) || isStaleTemporary(entry.path().filename().string()))
      doomed.push_back(entry.path());
  for (const fs::path& p : doomed) {
    fs::remove_all(p, ec);
    if (ec) throw std::runtime_error("--overwrite: cannot remove '" + p.string() + "': " + ec.message());
  }
  return doomed.size();
}

std::size_t removeStaleTemporaries(const fs::path& dir) {
  std::error_code ec;
  std::size_t removed = 0;
  std::vector<fs::path> dirs{dir};
  for (const auto& entry : fs::directory_iterator(dir, ec))
    if (entry.is_directory(ec) && isRunOutput(entry)) dirs.push_back(entry.path());
  for (const fs::path& d : dirs) {
    std::vector<fs::path> stale;
    for (const auto& entry : fs::directory_iterator(d, ec))
      if (isStaleTemporary(entry.path().filename().string())) stale.push_back(entry.path());
    for (const fs::path& p : stale) removed += fs::remove(p, ec) ? 1 : 0;
  }
  return removed;
}

}  // namespace ejecta
