#pragma once
// The ejecta subcommands, each a thin shell over the libraries. main.cpp parses the command line
// (CLI11 lives in that one translation unit) and calls these.
#include <string>
#include <vector>

namespace ejecta::app {

struct RunArgs {
  std::string scene;                  // path; empty = the embedded default scene
  std::string outDir;                 // empty = runs/<scene name>
  std::vector<std::string> overrides; // --set key=value
  int threads = 0;
  std::string restartDir;             // --restart RUN_DIR
  bool quiet = false;
};
int runCommand(const RunArgs& args);

struct VerifyArgs {
  std::string name;
  bool list = false;
  bool json = false;
  int threads = 0;
  std::vector<std::string> overrides;  // applied to the problem's scene
  int resolutions = 0;                 // 0 = the problem's default
  std::string outDir;                  // optional: write the problem's profile CSVs here
};
int verifyCommand(const VerifyArgs& args);

// True when stderr is a terminal and CI is not set: show progress lines.
bool interactive();

}  // namespace ejecta::app
