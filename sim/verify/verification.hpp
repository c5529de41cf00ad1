#pragma once
// Verification problems: each runs one of the scenes in scenes/verification/ (compiled in) at
// one or more resolutions and measures its error against an exact solution. The same code backs
// `ejecta verify NAME` and the CTest verification tests, so the README's error tables come from
// a command anyone can rerun.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace ejecta::verify {

struct Metric {
  std::string name;   // e.g. "L1_density"
  double value = 0.0;
  std::string unit;   // SI unit or "1"
};

// One run of a problem at one resolution.
struct ResolutionRun {
  double spacing = 0.0;       // lattice spacing of the first body [m]
  std::size_t particles = 0;
  long steps = 0;
  std::uint64_t particleUpdates = 0;  // particle-steps: particles x steps with global steps
  double wallSeconds = 0.0;
  double energyError = 0.0;   // relative total energy change over the run
  double momentumError = 0.0; // |P_final - P_initial| / (M * characteristic speed)
  std::vector<Metric> metrics;
  double metric(const std::string& name) const;
};

struct Report {
  std::string problem;
  std::string description;
  std::string reference;              // what the exact solution is, with its source
  std::vector<ResolutionRun> runs;    // coarsest first
  std::vector<Metric> orders;         // observed convergence orders between successive runs
};

struct Options {
  int threads = 0;
  int resolutions = 0;                // 0 = the problem's default
  // The spacing factors of a convergence study (relative to the scene's own spacing), in place of
  // the problem's powers of two (`ejecta converge verify:NAME`); empty: the problem's own.
  std::vector<double> factors;
  std::vector<std::string> overrides; // --set on the problem's scene
  bool progress = false;
  std::string outDir;                 // non-empty: write profile CSVs here
};

struct Problem {
  std::string name;
  std::string description;
  int defaultResolutions = 1;
  std::function<Report(const Options&)> run;
};

const std::vector<Problem>& problems();
// Runs a problem by name; throws std::invalid_argument for an unknown name.
Report runProblem(const std::string& name, const Options& options);
// JSON text of a report.
std::string reportJson(const Report& report);
// One row per resolution, coarsest first: spacing_m, particles, steps, wall_s, energy_error,
// momentum_error, every metric; then, for every L1_ metric, its value over the coarsest run's
// (NAME_relative), and spacing_m over the coarsest spacing (first_order: where a first-order
// method's relative error would be). What `ejecta verify --out` charts as error against
// resolution and against run time.
std::string convergenceCsv(const Report& report);
// Human-readable table of a report.
std::string reportTable(const Report& report);
// Markdown table header and one row per report (its finest run), for the README.
std::string markdownHeader();
std::string markdownRow(const Report& report);

}  // namespace ejecta::verify
