#pragma once
// What the end-to-end tests (tests/coupling/test_chain_*.cpp) share: the `ejecta` binary of this build, a
// way to run it, and small file helpers.
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace ejecta::test {

inline const std::string kEjecta = std::string(EJECTA_BINARY_DIR) + "/apps/ejecta";

// Runs a shell command; returns its exit status, with its stdout and stderr in `output`.
inline int runCommand(const std::string& command, std::string& output) {
  output.clear();
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return -1;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe)) output += buffer;
  const int status = pclose(pipe);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

inline void writeTextFile(const std::filesystem::path& p, const std::string& text) {
  std::ofstream out(p);
  out << text;
}

inline std::string readTextFile(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace ejecta::test
