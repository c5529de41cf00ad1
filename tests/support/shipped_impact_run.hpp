#pragma once
// A shipped scene run as `ejecta run` runs it, with its in-situ field outputs (grids, the crater
// measured into the summary), in a temporary folder removed afterwards: the run's summary.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>
#include <unistd.h>

#include "fields/run_outputs.hpp"
#include "sim/run/run.hpp"
#include "sim/setup/scene.hpp"

namespace ejecta::test {

// `file` under scenes/, with --set `overrides`; `tag` keeps two runs of one test apart. Throws
// std::runtime_error with the run's diagnosis when it fails (the test fails with it, rather than
// on the missing numbers of an empty summary).
inline RunSummary runShippedScene(const std::string& file,
                                  const std::vector<std::string>& overrides,
                                  const std::string& tag) {
  namespace fs = std::filesystem;
  const fs::path dir =
      fs::temp_directory_path() / ("ejecta_" + tag + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const Scene scene = loadScene(std::string(EJECTA_SOURCE_DIR) + "/scenes/" + file, overrides);
  RunOptions options;
  options.outDir = dir.string();
  options.configure = [](const Scene& s, RunOptions& o) { fields::addFieldOutputs(o, s); };
  const RunOutcome r = runScene(scene, options);
  fs::remove_all(dir);
  if (!r.ok) throw std::runtime_error(file + ": the run failed: " + r.error);
  return r.summary;
}

}  // namespace ejecta::test
