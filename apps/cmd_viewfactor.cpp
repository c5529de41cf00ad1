// `ejecta viewfactor GEOMETRY.toml`: view factors between a spacecraft's patches, or from its
// patches to hot emitters, by Monte Carlo ray casting (radiation/geometry_file.hpp,
// docs/view_factors.md). With --convergence DIR: the same at growing ray counts, the error (or
// standard error) against rays and against wall time, as CSV and charts.
#include <cstdio>
#include <exception>
#include <filesystem>
#include <stdexcept>

#include "apps/commands.hpp"
#include "core/atomic_file.hpp"
#include "radiation/geometry_file.hpp"
#include "radiation/view_factor_convergence.hpp"
#include "render/charts.hpp"
#include "sim/setup/scene_catalog.hpp"

namespace fs = std::filesystem;

namespace ejecta::app {

namespace {

// viewfactor_convergence.png (against rays) and viewfactor_cost.png (against wall time): each
// factor's error where it has an exact value, else its standard error, and the N^-1/2 line.
std::vector<std::string> writeConvergenceCharts(const radiation::ViewFactorConvergence& study,
                                                const fs::path& dir) {
  render::ChartRunner charts;
  if (!charts.chartsAvailable()) {
    std::fprintf(stderr, "ejecta: no charts: %s\n", charts.unavailableReason().c_str());
    return {};
  }
  bool exact = false;
  for (const radiation::TrackedFactor& f : study.factors) exact = exact || f.exact.has_value();
  std::vector<render::ChartSeries> series;
  for (const radiation::TrackedFactor& f : study.factors) {
    if (exact && !f.exact) continue;
    const std::string c = radiation::convergenceColumn(f);
    const std::string label = f.from + " -> " + f.to;
    if (f.exact) series.push_back({.y = c + "_error", .label = label + ": |error|", .markers = true});
    series.push_back({.y = c + "_stderr", .label = label + ": standard error", .markers = true});
  }
  const fs::path csv = dir / "viewfactor_convergence.csv";
  render::ChartSpec rays{.csv = csv, .x = "rays", .series = series, .xlog = true, .ylog = true,
                         .xlabel = "rays per receiver", .ylabel = "view factor error",
                         .title = study.name + ": convergence with rays",
                         .out = dir / "viewfactor_convergence.png"};
  rays.series.push_back({.y = "inverse_sqrt", .label = "N^-1/2", .reference = true});
  charts.writeChart(rays);
  render::ChartSpec cost{.csv = csv, .x = "wall_s", .series = series, .xlog = true, .ylog = true,
                         .xlabel = "wall time [s]", .ylabel = "view factor error",
                         .title = study.name + ": accuracy against run time",
                         .out = dir / "viewfactor_cost.png"};
  charts.writeChart(cost);
  return {"viewfactor_convergence.png", "viewfactor_cost.png"};
}

int convergenceCommand(const ViewfactorArgs& args, const radiation::GeometryConfig& config) {
  if (args.minRays <= 0 || args.maxRays <= 0)
    throw std::invalid_argument("--min-rays and --max-rays must be positive");
  const radiation::ViewFactorConvergence study = radiation::studyViewFactorConvergence(
      config, static_cast<std::uint64_t>(args.minRays), static_cast<std::uint64_t>(args.maxRays));
  const fs::path dir = args.convergenceDir;
  fs::create_directories(dir);
  writeFileAtomically(dir / "viewfactor_convergence.csv", radiation::formatConvergenceCsv(study));
  std::fputs(radiation::formatConvergenceText(study).c_str(), stdout);
  std::string written = "viewfactor_convergence.csv";
  if (!args.noCharts) {
    try {
      for (const std::string& c : writeConvergenceCharts(study, dir)) written += ", " + c;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "ejecta: charts failed: %s\n", e.what());
    }
  }
  std::printf("wrote %s/{%s}\n", dir.string().c_str(), written.c_str());
  return 0;
}

}  // namespace

int viewfactorCommand(const ViewfactorArgs& args) {
  // A file, or a shipped geometry's name ("geometry/seed_follower", `ejecta scenes`).
  const SceneText text = readSceneArgument(args.geometry, "geometry");
  const radiation::GeometryConfig config =
      radiation::parseGeometryConfig(text.text, text.label, text.directory);
  if (!args.convergenceDir.empty()) return convergenceCommand(args, config);
  radiation::ViewFactorRunOptions run;
  if (args.rays > 0) run.rays = static_cast<std::uint64_t>(args.rays);
  if (args.tolerance > 0) run.tolerance = args.tolerance;
  const radiation::ViewFactorReport report = radiation::computeViewFactors(config, run);
  std::fputs((args.json ? radiation::formatViewFactorJson(report)
                        : radiation::formatViewFactorText(report)).c_str(), stdout);
  return 0;
}

}  // namespace ejecta::app
