// `ejecta verify`: run a verification problem and print its errors against the exact solution.
#include <cstdio>

#include "apps/commands.hpp"
#include "sim/verify/verification.hpp"

namespace ejecta::app {

int verifyCommand(const VerifyArgs& args) {
  if (args.list || args.name.empty()) {
    for (const verify::Problem& p : verify::problems())
      std::printf("%-12s %s\n", p.name.c_str(), p.description.c_str());
    return args.list ? 0 : 1;
  }
  verify::Options options;
  options.threads = args.threads;
  options.resolutions = args.resolutions;
  options.overrides = args.overrides;
  options.progress = !args.json && interactive();
  options.outDir = args.outDir;
  const verify::Report report = verify::runProblem(args.name, options);
  std::fputs((args.json ? verify::reportJson(report) : verify::reportTable(report)).c_str(), stdout);
  return 0;
}

}  // namespace ejecta::app
