// `ejecta converge SCENE --factors 1,0.7,0.5 --quantity Q [...]`: a scene at successively finer
// spacings, each quantity's observed order, extrapolated value and GCI uncertainty
// (coupling/convergence_study.hpp, docs/convergence.md). Writes levels.csv, convergence.csv,
// convergence.json and, with matplotlib, one chart per quantity against spacing and cost.
#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>

#include "apps/commands.hpp"
#include "core/atomic_file.hpp"
#include "coupling/convergence_study.hpp"
#include "render/charts.hpp"
#include "sim/setup/scene.hpp"
#include "sim/setup/scene_catalog.hpp"

namespace fs = std::filesystem;

namespace ejecta::app {

namespace {

// <quantity>.png: the value against the spacing, with the finest value's band dotted and, where
// the levels are in the asymptotic range, the extrapolated value solid (an extrapolation from an
// order out of range or from oscillating changes claims nothing, so none is drawn); and
// <quantity>_cost.png against the wall time. Returns why not, or "".
std::string drawCharts(const fs::path& out, const coupling::ConvergenceResult& r) {
  render::ChartRunner charts;
  if (!charts.chartsAvailable()) return charts.unavailableReason();
  try {
    for (const coupling::QuantityConvergence& q : r.quantities) {
      std::vector<render::ChartLine> lines;
      const verify::GridConvergence& g = q.convergence;
      char label[96];
      if (g.asymptotic) {
        std::snprintf(label, sizeof label, "extrapolated (Richardson, p = %.2f)", g.order);
        lines.push_back({g.extrapolated, label, render::LineStyle::Solid});
      }
      if (g.basis != verify::UncertaintyBasis::None) {
        // The band as the table gives it: clipped to what the quantity can be (--range).
        const std::string clipped = q.bandClipped ? ", clipped to the quantity's range" : "";
        lines.push_back({q.bandHigh, "finest value +- " + verify::describeBand(g, r.levels.size()) + clipped,
                         render::LineStyle::Dotted});
        lines.push_back({q.bandLow, "", render::LineStyle::Dotted});
      }
      charts.writeChart({.csv = out / "levels.csv", .x = "spacing_m",
                         .series = {{.y = q.name, .label = "SPH", .markers = true}},
                         .xlabel = "particle spacing [m]", .ylabel = q.name,
                         .title = r.scene + ": " + q.name + " against resolution", .hlines = lines,
                         .out = out / (q.name + ".png")});
      charts.writeChart({.csv = out / "levels.csv", .x = "wall_seconds",
                         .series = {{.y = q.name, .label = "SPH", .markers = true}},
                         .xlog = true, .xlabel = "wall time [s]", .ylabel = q.name,
                         .title = r.scene + ": " + q.name + " against cost", .hlines = lines,
                         .out = out / (q.name + "_cost.png")});
    }
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace

int convergeCommand(const ConvergeArgs& args) {
  // verify:NAME: a verification problem, whose metrics have exact answers (ejecta verify --list).
  const std::string verifyPrefix = "verify:";
  const bool problem = args.scene.rfind(verifyPrefix, 0) == 0;
  coupling::ConvergenceOptions o;
  o.factors = args.factors;
  o.quantities = args.quantities;
  o.scaledKeys = args.keys;
  o.overrides = args.overrides;
  o.threads = args.threads;
  o.formalOrder = args.formalOrder;
  for (const std::string& text : args.ranges) {
    const auto [quantity, range] = coupling::parseQuantityRange(text);
    if (!o.ranges.emplace(quantity, range).second)
      throw std::invalid_argument("converge: --range '" + quantity + "' is given twice");
  }
  const std::string name = problem ? args.scene.substr(verifyPrefix.size()) : "";
  const SceneText scene = problem ? SceneText{} : readSceneArgument(args.scene);
  const std::string sceneName = problem ? name : parseScene(scene.text, scene.label, args.overrides).name;
  o.outDir = args.outDir.empty() ? fs::path("runs") / (sceneName + "_converge") : fs::path(args.outDir);
  fs::create_directories(o.outDir);
  o.onLevel = [](double factor, std::size_t particles, double seconds) {
    if (seconds < 0.0)
      std::fprintf(stderr, "ejecta: level x%.4g: %zu particles (run before; read back)\n", factor, particles);
    else
      std::fprintf(stderr, "ejecta: level x%.4g: %zu particles, %.1f s\n", factor, particles, seconds);
  };
  const coupling::ConvergenceResult r = problem ? coupling::runVerificationConvergence(name, o)
                                                : coupling::runConvergenceStudy(scene.text, scene.label, o);
  writeFileAtomically(o.outDir / "levels.csv", coupling::levelsCsv(r));
  writeFileAtomically(o.outDir / "convergence.csv", coupling::convergenceCsv(r));
  nlohmann::ordered_json json;
  json["scene"] = r.scene;
  for (const coupling::ConvergenceLevel& l : r.levels)
    json["levels"].push_back({{"factor", l.factor}, {"spacing_m", l.spacing}, {"particles", l.particles},
                              {"wall_seconds", l.wallSeconds}, {"values", l.values}});
  for (const coupling::QuantityConvergence& q : r.quantities) {
    const verify::GridConvergence& g = q.convergence;
    nlohmann::ordered_json j{{"quantity", q.name}, {"finest", r.levels.back().values.at(q.name)}, {"valid", g.valid},
                             {"asymptotic", g.asymptotic}, {"formal_order", g.formalOrder}};
    if (g.valid) {
      j["observed_order"] = g.order;
      j["oscillatory"] = g.oscillatory;
    }
    if (g.asymptotic) j["extrapolated"] = g.extrapolated;  // claimed only there
    j["uncertainty_basis"] = verify::uncertaintyBasisName(g.basis);
    if (g.basis != verify::UncertaintyBasis::None) {
      j["band_order"] = g.bandOrder;
      j["band_at_half_spread"] = g.bandAtHalfSpread;
      j["gci"] = g.gci;
      j["uncertainty"] = g.uncertainty;
      j["band_low"] = q.bandLow;
      j["band_high"] = q.bandHigh;
      j["band_clipped"] = q.bandClipped;  // to the range --range gave
    }
    const verify::LeastSquaresUncertainty& ls = g.leastSquares;
    if (ls.available)
      j["least_squares"] = {{"order", ls.order},
                            {"order_at_search_bound", ls.orderAtSearchBound},
                            {"estimate_order", ls.estimateOrder},
                            {"weighted", ls.weighted},
                            {"extrapolated", ls.extrapolated},
                            {"error_estimate", ls.errorEstimate},
                            {"standard_deviation", ls.standardDeviation},
                            {"data_range", ls.dataRange},
                            {"good_fit", ls.goodFit},
                            {"safety_factor", ls.safetyFactor},
                            {"uncertainty", ls.uncertainty},
                            {"note", ls.note}};
    if (!g.note.empty()) j["note"] = g.note;
    json["quantities"].push_back(j);
  }
  writeFileAtomically(o.outDir / "convergence.json", json.dump(2) + "\n");
  const std::string noChart = args.charts ? drawCharts(o.outDir, r) : "";
  if (!noChart.empty()) std::fprintf(stderr, "ejecta converge: no charts: %s\n", noChart.c_str());

  std::printf("ejecta converge: %s, %zu levels (spacing %.4g to %.4g m, %zu to %zu particles)\n", r.scene.c_str(),
              r.levels.size(), r.levels.front().spacing, r.levels.back().spacing, r.levels.front().particles,
              r.levels.back().particles);
  for (const coupling::QuantityConvergence& q : r.quantities) {
    const verify::GridConvergence& g = q.convergence;
    const double fine = r.levels.back().values.at(q.name);
    char order[48] = "";
    if (g.valid) std::snprintf(order, sizeof order, "observed order %.3g: ", g.order);
    const std::string note = g.note.empty() ? "" : "; " + std::string(order) + g.note;
    std::string band = verify::describeBand(g, r.levels.size());
    if (q.bandClipped) {
      char range[96];
      std::snprintf(range, sizeof range, "; clipped to the quantity's range: %.6g to %.6g", q.bandLow, q.bandHigh);
      band += range;
    }
    if (g.asymptotic) {
      // Celik et al. (2008): the GCI band is the finest solution's uncertainty, so it is printed
      // about the finest value; the extrapolation is the estimate it brackets. (The GCI band's
      // name gives the observed order already.)
      char observed[48] = "";
      if (g.basis != verify::UncertaintyBasis::ObservedOrder)
        std::snprintf(observed, sizeof observed, ", observed order %.3g", g.order);
      std::printf("  %s: finest %.6g +- %.3g (%.3g%%: the %s), extrapolated %.6g%s\n", q.name.c_str(), fine,
                  g.uncertainty, 100 * g.gci, band.c_str(), g.extrapolated, observed);
    } else if (g.basis != verify::UncertaintyBasis::None)
      // Not in the asymptotic range: no extrapolation is claimed, only the wider band.
      std::printf("  %s: finest %.6g +- %.3g (%.3g%%: the %s)%s\n", q.name.c_str(), fine, g.uncertainty,
                  100 * g.gci, band.c_str(), note.c_str());
    else
      std::printf("  %s: finest %.6g; %s\n", q.name.c_str(), fine, g.note.c_str());
  }
  std::printf("  outputs: %s/{levels.csv, convergence.csv, convergence.json%s, level_*/}\n", o.outDir.string().c_str(),
              noChart.empty() && args.charts ? ", <quantity>.png" : "");
  return 0;
}

}  // namespace ejecta::app
