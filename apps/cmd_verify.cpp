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
  if (args.name == "all") {
    // Every problem at its default resolutions; one markdown row each (the README's table).
    verify::Options options;
    options.threads = args.threads;
    options.overrides = args.overrides;
    options.resolutions = args.resolutions;
    options.outDir = args.outDir;
    std::fputs(verify::markdownHeader().c_str(), stdout);
    for (const verify::Problem& p : verify::problems()) {
      std::fputs(verify::markdownRow(verify::runProblem(p.name, options)).c_str(), stdout);
      std::fflush(stdout);
    }
    return 0;
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
