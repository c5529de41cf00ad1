#include "coupling/convergence_study.hpp"

#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/csv.hpp"
#include "core/join.hpp"
#include "coupling/run_thermal.hpp"
#include "fields/fragment_outputs.hpp"
#include "fields/history_csv.hpp"
#include "fields/run_outputs.hpp"
#include "fields/shield_outputs.hpp"
#include "sim/run/run.hpp"
#include "sim/setup/scene.hpp"
#include "sim/verify/verification.hpp"

namespace fs = std::filesystem;

namespace ejecta::coupling {

namespace {

// The shortest text that reads back to the same double: "0.000625", not "0.00062500000000000001".
std::string number(double x) { return fields::shortestNumber(x); }

std::string factorName(double factor) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "level_%.6g", factor);
  return buf;
}

// A scene value times `factor`, as --set takes it: a number, a quantity string with its unit
// kept ("0.25 m" -> "0.125 m"), or an array of either. Empty when the value is none of these.
std::optional<std::string> scaledValue(const toml::node& node, double factor) {
  if (const auto* i = node.as_integer()) return number(factor * static_cast<double>(i->get()));
  if (const auto* f = node.as_floating_point()) return number(factor * f->get());
  if (const auto* s = node.as_string()) {
    const std::string& text = s->get();
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (end == text.c_str()) return std::nullopt;
    return "\"" + number(factor * v) + std::string(end) + "\"";
  }
  if (const auto* a = node.as_array()) {
    std::string out = "[";
    for (std::size_t k = 0; k < a->size(); ++k) {
      const auto item = scaledValue(*a->get(k), factor);
      if (!item) return std::nullopt;
      out += (k ? ", " : "") + *item;
    }
    return out + "]";
  }
  return std::nullopt;
}

// The level's summary.json, read back: the run completed and holds every quantity.
nlohmann::json readSummary(const fs::path& dir) {
  std::ifstream in(dir / "summary.json");
  if (!in) return nullptr;
  try {
    nlohmann::json j = nlohmann::json::parse(in);
    return j.value("status", "") == "completed" ? j : nullptr;
  } catch (const std::exception&) {
    return nullptr;  // half written or another kind of file: run the level again
  }
}

double quantityOf(const nlohmann::json& summary, const std::string& name, const fs::path& dir) {
  const nlohmann::json& extras = summary.at("extras");
  if (extras.contains(name) && extras[name].is_number()) return extras[name].get<double>();
  if (name == "energy_relative_error") return summary.at("energy").at("relative_error").get<double>();
  if (summary.contains(name) && summary[name].is_number()) return summary[name].get<double>();
  std::string known = "energy_relative_error, wall_seconds, particles, steps";
  for (const auto& [key, value] : extras.items())
    if (value.is_number()) known += ", " + key;
  throw std::runtime_error((dir / "summary.json").string() + ": no number '" + name + "'; its numbers: " + known);
}

void analyse(ConvergenceResult& result, const ConvergenceOptions& o) {
  for (const std::string& q : o.quantities) {
    QuantityConvergence qc;
    qc.name = q;
    if (result.levels.size() < 3) {
      qc.convergence.formalOrder = o.formalOrder;
      qc.convergence.note = "fewer than three levels: no order or extrapolation";
    } else {
      std::vector<double> h, v;
      for (const ConvergenceLevel& l : result.levels) h.push_back(l.spacing), v.push_back(l.values.at(q));
      qc.convergence = verify::gridConvergence(h, v, o.formalOrder);
    }
    const verify::GridConvergence& g = qc.convergence;
    if (g.basis != verify::UncertaintyBasis::None) {
      const double fine = result.levels.back().values.at(q);
      qc.bandLow = fine - g.uncertainty;
      qc.bandHigh = fine + g.uncertainty;
      const auto range = o.ranges.find(q);
      if (range != o.ranges.end() && !(fine >= range->second.minimum && fine <= range->second.maximum)) {
        // The range cannot be what the quantity can be: say so, and leave the band whole.
        std::string& note = qc.convergence.note;
        note += std::string(note.empty() ? "" : "; ") + "the finest value " + number(fine) +
                " lies outside --range " + number(range->second.minimum) + " to " + number(range->second.maximum) +
                ": the band is not clipped";
      } else if (range != o.ranges.end()) {
        qc.bandClipped = qc.bandLow < range->second.minimum || qc.bandHigh > range->second.maximum;
        qc.bandLow = std::max(qc.bandLow, range->second.minimum);
        qc.bandHigh = std::min(qc.bandHigh, range->second.maximum);
      }
    }
    result.quantities.push_back(std::move(qc));
  }
}

std::vector<double> checkedFactors(const ConvergenceOptions& o) {
  if (o.factors.empty()) throw std::invalid_argument("converge: no --factors");
  if (o.quantities.empty()) throw std::invalid_argument("converge: no --quantity");
  // Checked before any level runs, not when the levels are analysed.
  if (!(o.formalOrder > 0.0) || !std::isfinite(o.formalOrder))
    throw std::invalid_argument("converge: the formal order must be a positive number");
  for (const auto& [name, range] : o.ranges) {
    if (std::find(o.quantities.begin(), o.quantities.end(), name) == o.quantities.end())
      throw std::invalid_argument("converge: --range '" + name + "': not one of the --quantity given");
    if (!(range.minimum < range.maximum))
      throw std::invalid_argument("converge: --range '" + name + "': the minimum must be below the maximum");
  }
  std::vector<double> factors = o.factors;
  std::sort(factors.begin(), factors.end(), std::greater<>());
  for (std::size_t k = 0; k < factors.size(); ++k) {
    if (!(factors[k] > 0.0) || !std::isfinite(factors[k]))
      throw std::invalid_argument("converge: the factors must be positive");
    if (k > 0 && factors[k] == factors[k - 1]) throw std::invalid_argument("converge: a factor is given twice");
  }
  return factors;
}

}  // namespace

std::pair<std::string, QuantityRange> parseQuantityRange(const std::string& text) {
  const auto fail = [&](const std::string& why) {
    return std::invalid_argument("converge: --range '" + text + "': " + why + " (QUANTITY=MIN:MAX, e.g. " +
                                 "target_share_of_yield=0:1; either side may be empty)");
  };
  const std::size_t equals = text.find('=');
  if (equals == std::string::npos || equals == 0) throw fail("no quantity before '='");
  const std::string bounds = text.substr(equals + 1);
  const std::size_t colon = bounds.find(':');
  if (colon == std::string::npos) throw fail("no ':' between the minimum and the maximum");
  const auto bound = [&](const std::string& part, double none) {
    if (part.empty()) return none;
    std::size_t used = 0;
    double value = 0.0;
    try {
      value = std::stod(part, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != part.size() || !std::isfinite(value)) throw fail("'" + part + "' is not a finite number");
    return value;
  };
  QuantityRange range;
  range.minimum = bound(bounds.substr(0, colon), -std::numeric_limits<double>::infinity());
  range.maximum = bound(bounds.substr(colon + 1), std::numeric_limits<double>::infinity());
  if (!(range.minimum < range.maximum)) throw fail("the minimum must be below the maximum");
  return {text.substr(0, equals), range};
}

std::vector<std::string> levelOverrides(const std::string& sceneText, const std::string& label,
                                        const ConvergenceOptions& o, double factor) {
  const Scene scene = parseScene(sceneText, label, o.overrides);
  std::vector<std::string> out = o.overrides;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const int entry = scene.bodies[i].entry >= 0 ? scene.bodies[i].entry : static_cast<int>(i);
    out.push_back("bodies[" + std::to_string(entry) + "].spacing=" + number(factor * scene.bodies[i].spacing));
  }
  for (std::size_t j = 0; j < scene.deposits.size(); ++j)
    if (scene.deposits[j].profile == DepositProfile::Gaussian)
      out.push_back("energy_deposits[" + std::to_string(j) + "].width=" + number(factor * scene.deposits[j].width));
  if (o.scaledKeys.empty()) return out;
  toml::table doc = toml::parse(sceneText, label);
  for (const std::string& key : o.scaledKeys) {
    // A key the study's --set gives takes that value; else the scene's.
    std::optional<toml::table> fromSet;
    for (const std::string& s : o.overrides)
      if (s.rfind(key + "=", 0) == 0) fromSet = toml::parse("v = " + s.substr(key.size() + 1));
    const toml::node_view<const toml::node> node =
        fromSet ? toml::node_view<const toml::node>(fromSet->get("v")) : std::as_const(doc).at_path(key);
    if (!node) throw SceneError(label + ": --key '" + key + "': the scene has no such key");
    const std::optional<std::string> value = scaledValue(*node.node(), factor);
    if (!value) throw SceneError(label + ": --key '" + key + "': not a number, a quantity or an array of them");
    out.push_back(key + "=" + *value);
  }
  return out;
}

ConvergenceResult runConvergenceStudy(const std::string& sceneText, const std::string& label,
                                      const ConvergenceOptions& o) {
  const std::vector<double> factors = checkedFactors(o);
  ConvergenceResult result;
  const Scene base = parseScene(sceneText, label, o.overrides);
  result.scene = base.name;
  for (double factor : factors) {
    const fs::path dir = o.outDir / factorName(factor);
    nlohmann::json summary = readSummary(dir);
    double seconds = -1.0;
    if (summary.is_null()) {
      const std::vector<std::string> overrides = levelOverrides(sceneText, label, o, factor);
      RunOptions run;
      run.outDir = dir.string();
      run.threads = o.threads;
      run.sceneSource = sceneText;
      run.overrides = overrides;
      // The analyses a quantity may come from; no pictures or charts.
      run.configure = [](const Scene& s, RunOptions& ro) {
        fields::addFieldOutputs(ro, s);
        fields::addShieldOutputs(ro, s);
        fields::addFragmentOutputs(ro, s);
        addThermalOutputs(ro, s, false);
      };
      fs::create_directories(dir);
      const RunOutcome r = runScene(parseScene(sceneText, label, overrides), run);
      if (!r.ok) throw std::runtime_error(label + ": the level x" + number(factor) + " failed: " + r.error + " (" + dir.string() + ")");
      summary = readSummary(dir);
      if (summary.is_null()) throw std::runtime_error((dir / "summary.json").string() + ": not written");
      seconds = r.summary.wallSeconds;
    }
    ConvergenceLevel level;
    level.factor = factor;
    level.spacing = factor * base.bodies.front().spacing;
    level.particles = summary.at("particles").get<std::size_t>();
    level.wallSeconds = summary.at("wall_seconds").get<double>();
    for (const std::string& q : o.quantities) level.values[q] = quantityOf(summary, q, dir);
    if (o.onLevel) o.onLevel(factor, level.particles, seconds);
    result.levels.push_back(std::move(level));
  }
  analyse(result, o);
  return result;
}

ConvergenceResult runVerificationConvergence(const std::string& problem, const ConvergenceOptions& o) {
  const std::vector<double> factors = checkedFactors(o);
  verify::Options vo;
  vo.factors = factors;
  vo.threads = o.threads;
  vo.overrides = o.overrides;
  const verify::Report report = verify::runProblem(problem, vo);
  if (report.runs.size() != factors.size())
    throw std::invalid_argument("converge: verification problem '" + problem + "' runs at its own resolutions only");
  ConvergenceResult result;
  result.scene = "verify:" + problem;
  for (std::size_t k = 0; k < report.runs.size(); ++k) {
    const verify::ResolutionRun& run = report.runs[k];
    ConvergenceLevel level;
    level.factor = factors[k];
    level.spacing = run.spacing;
    level.particles = run.particles;
    level.wallSeconds = run.wallSeconds;
    for (const std::string& q : o.quantities) {
      const auto it = std::find_if(run.metrics.begin(), run.metrics.end(),
                                   [&](const verify::Metric& m) { return m.name == q; });
      if (it == run.metrics.end())
        throw std::invalid_argument("converge: verification problem '" + problem + "' has no metric '" + q +
                                    "'; its metrics: " + joinList(run.metrics, &verify::Metric::name));
      level.values[q] = it->value;
    }
    result.levels.push_back(std::move(level));
  }
  analyse(result, o);
  return result;
}

std::string levelsCsv(const ConvergenceResult& r) {
  std::vector<std::string> columns = {"factor", "spacing_m", "particles", "wall_seconds"};
  for (const QuantityConvergence& q : r.quantities) columns.push_back(q.name);
  CsvWriter csv(columns);
  for (const ConvergenceLevel& l : r.levels) {
    csv.number(l.factor).number(l.spacing).count(l.particles).number(l.wallSeconds);
    for (const QuantityConvergence& q : r.quantities) csv.number(l.values.at(q.name));
    csv.endRow();
  }
  return csv.str();
}

std::string convergenceCsv(const ConvergenceResult& r) {
  CsvWriter csv({"quantity", "finest", "observed_order", "extrapolated", "gci", "uncertainty",
                 "uncertainty_basis", "band_order", "band_at_half_spread", "asymptotic", "oscillatory", "ls_order",
                 "ls_standard_deviation", "ls_uncertainty", "note"});
  for (const QuantityConvergence& q : r.quantities) {
    const verify::GridConvergence& g = q.convergence;
    csv.text(q.name).number(r.levels.back().values.at(q.name));
    // The extrapolation only where it is claimed (the levels in the asymptotic range).
    if (g.valid) csv.number(g.order);
    else csv.text("");
    if (g.asymptotic) csv.number(g.extrapolated);
    else csv.text("");
    if (g.basis != verify::UncertaintyBasis::None) csv.number(g.gci).number(g.uncertainty);
    else csv.text("").text("");
    csv.text(verify::uncertaintyBasisName(g.basis));
    if (g.basis != verify::UncertaintyBasis::None) csv.number(g.bandOrder);
    else csv.text("");
    csv.flag(g.bandAtHalfSpread).flag(g.asymptotic).flag(g.oscillatory);
    // Eca & Hoekstra's fit over all levels, where there are four or more.
    const verify::LeastSquaresUncertainty& ls = g.leastSquares;
    if (ls.available) csv.number(ls.order).number(ls.standardDeviation).number(ls.uncertainty);
    else csv.text("").text("").text("");
    csv.quoted(g.note).endRow();
  }
  return csv.str();
}

}  // namespace ejecta::coupling
