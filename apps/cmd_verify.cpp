// `ejecta verify`: run a verification problem and print its errors against the exact solution.
#include <cstdio>
#include <exception>

#include "apps/commands.hpp"
#include "coupling/verify_charts.hpp"
#include "sim/verify/verification.hpp"

namespace ejecta::app {

using namespace ejecta::coupling;  // the in-situ chain (coupling/)

namespace {

// With --out: the convergence table and the charts beside the profiles. A machine without
// matplotlib gets the CSVs and a note on stderr; a chart that fails does not lose the report.
void writeOutputs(const VerifyArgs& args, const verify::Report& report, render::ChartRunner& charts) {
  if (args.outDir.empty()) return;
  const std::string table = writeConvergenceTable(report, args.outDir);
  std::fprintf(stderr, "ejecta: %s/%s", args.outDir.c_str(), table.c_str());
  if (!args.noCharts && charts.chartsAvailable()) {
    try {
      const std::vector<std::string> written = writeVerificationCharts(charts, report, args.outDir);
      if (!written.empty()) std::fprintf(stderr, "; charts:");
      for (const std::string& w : written) std::fprintf(stderr, " %s", w.c_str());
    } catch (const std::exception& e) {
      std::fprintf(stderr, "; charts failed: %s", e.what());
    }
  } else if (!args.noCharts) {
    std::fprintf(stderr, "; no charts: %s", charts.unavailableReason().c_str());
  }
  std::fprintf(stderr, "\n");
}

}  // namespace

int verifyCommand(const VerifyArgs& args) {
  if (args.list || args.name.empty()) {
    for (const verify::Problem& p : verify::problems())
      std::printf("%-12s %s\n", p.name.c_str(), p.description.c_str());
    return args.list ? 0 : 1;
  }
  render::ChartRunner charts;
  verify::Options options;
  options.threads = args.threads;
  options.resolutions = args.resolutions;
  options.overrides = args.overrides;
  options.outDir = args.outDir;
  if (args.name == "all") {
    // Every problem at its default resolutions; one markdown row each (the README's table).
    std::fputs(verify::markdownHeader().c_str(), stdout);
    for (const verify::Problem& p : verify::problems()) {
      const verify::Report report = verify::runProblem(p.name, options);
      std::fputs(verify::markdownRow(report).c_str(), stdout);
      std::fflush(stdout);
      writeOutputs(args, report, charts);
    }
    return 0;
  }
  options.progress = !args.json && interactive();
  const verify::Report report = verify::runProblem(args.name, options);
  std::fputs((args.json ? verify::reportJson(report) : verify::reportTable(report)).c_str(), stdout);
  std::fflush(stdout);
  writeOutputs(args, report, charts);
  return 0;
}

}  // namespace ejecta::app
