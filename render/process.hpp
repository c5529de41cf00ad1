#pragma once
// Running a helper program (the chart script's python) without a shell: arguments are passed
// as they are, so no quoting can go wrong, and its output is captured.
#include <string>
#include <vector>

namespace ejecta::render {

struct ProcessResult {
  int exitCode = -1;   // the program's status; -1 if it could not be started or was killed
  std::string output;  // what it wrote to stdout and stderr together
};

// Runs argv[0] (a path, not searched in PATH) with `argv`, waits for it, and returns its exit
// code and output. Never throws for the program's failure: the caller decides.
ProcessResult runProcess(const std::vector<std::string>& argv);

}  // namespace ejecta::render
