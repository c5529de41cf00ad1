#pragma once
// What sweep.png of `ejecta sweep` plots (apps/cmd_sweep.cpp): the target's share of the yield
// (or of the impactor's energy) per variant, against the varied value when it is one number per
// variant, against the depth of burst when the device moves along one coordinate, and otherwise
// as a bar per variant labelled by its values (the seed's Figs. 2.13 and 2.18 chart against the
// location). Pure functions of the sweep's axes and collected values, so they are unit-tested
// (tests/coupling/test_sweep_chart.cpp); header-only because the tests do not link the ejecta binary.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "sim/run/sweep.hpp"

namespace ejecta::coupling {

// A varied value that is a plain number ("3", "-2.5e-3"), not a quantity string or a vector.
inline std::optional<double> plainNumber(const std::string& text) {
  const auto b = text.find_first_not_of(" \t");
  if (b == std::string::npos) return std::nullopt;
  const std::string t = text.substr(b, text.find_last_not_of(" \t") - b + 1);
  char* end = nullptr;
  const double v = std::strtod(t.c_str(), &end);
  if (end != t.c_str() + t.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

// The components of a TOML array value "[a, \"b m\"]" as written (trimmed), or nothing for a
// value that is not an array. Nested arrays count as one component.
inline std::optional<std::vector<std::string>> vectorComponents(const std::string& text) {
  const auto b = text.find_first_not_of(" \t");
  const auto e = text.find_last_not_of(" \t");
  if (b == std::string::npos || text[b] != '[' || text[e] != ']') return std::nullopt;
  auto parts = splitOutsideBrackets(text.substr(b + 1, e - b - 1));
  if (!parts) return std::nullopt;
  if (parts->size() == 1 && parts->front().empty()) parts->clear();
  return parts;
}

// The tick label of a variant: its values without quotes, axes joined by "; ".
inline std::string sweepVariantLabel(const std::vector<std::string>& values) {
  std::string out;
  for (const std::string& v : values) {
    if (!out.empty()) out += "; ";
    for (char c : v)
      if (c != '"' && c != '\'') out += c;
  }
  return out;
}

struct SweepChartChoice {
  bool draw = false;      // false: nothing to chart (see `why`)
  std::string why;        // why not, when draw is false
  bool bars = false;      // a bar per variant, categories from the `label` column
  std::string x;          // line chart: the x column of sweep.csv
  std::string xlabel;
  std::string y;          // the share column
  std::string ylabel;
};

// Chooses the chart. `numeric` maps sweep.csv's summary columns to their value per variant
// (empty where a variant did not report it). Rules, in order:
//   1. the first axis's values are plain numbers: a line against that axis's column;
//   2. they are vectors that differ in exactly one component (a device moved along one line),
//      and the sweep reports a depth of burst with a distinct value per variant: a line against
//      the scaled depth of burst (m/kt^1/3) when there is one, else the depth of burst (m);
//   3. otherwise a bar per variant, labelled by its values.
// Nothing is drawn when no variant reports a share or some variant lacks the chosen columns (a
// failed run).
inline SweepChartChoice chooseSweepChart(
    const std::vector<SweepAxis>& axes,
    const std::map<std::string, std::vector<std::optional<double>>>& numeric) {
  SweepChartChoice c;
  if (axes.empty() || axes.front().values.empty()) {
    c.why = "no variants";
    return c;
  }
  const std::size_t n = axes.front().values.size();
  auto complete = [&](const std::string& column) {
    const auto it = numeric.find(column);
    if (it == numeric.end() || it->second.size() != n) return false;
    return std::all_of(it->second.begin(), it->second.end(),
                       [](const std::optional<double>& v) { return v.has_value(); });
  };
  auto present = [&](const std::string& column) {
    const auto it = numeric.find(column);
    return it != numeric.end() &&
           std::any_of(it->second.begin(), it->second.end(),
                       [](const std::optional<double>& v) { return v.has_value(); });
  };
  if (present("target_share_of_yield")) {
    c.y = "target_share_of_yield";
    c.ylabel = "share of the yield in the target";
  } else if (present("target_share_of_impactor_energy")) {
    c.y = "target_share_of_impactor_energy";
    c.ylabel = "share of the impactor's kinetic energy in the target";
  } else {
    c.why = "no variant reports a share of the yield or of the impactor's energy";
    return c;
  }
  if (!complete(c.y)) {
    c.why = "a variant did not report '" + c.y + "' (did it fail? see its run.log)";
    return c;
  }
  c.draw = true;
  const SweepAxis& axis = axes.front();
  if (std::all_of(axis.values.begin(), axis.values.end(),
                  [](const std::string& v) { return plainNumber(v).has_value(); })) {
    c.x = axis.key;
    c.xlabel = axis.key;
    return c;
  }
  // A move along one coordinate: the components of every value, and which of them change.
  std::vector<std::vector<std::string>> comps;
  for (const std::string& v : axis.values) {
    const auto parts = vectorComponents(v);
    if (!parts || (!comps.empty() && parts->size() != comps.front().size())) {
      comps.clear();
      break;
    }
    comps.push_back(*parts);
  }
  int changing = 0;
  if (!comps.empty())
    for (std::size_t k = 0; k < comps.front().size(); ++k) {
      bool differs = false;
      for (const auto& p : comps) differs = differs || p[k] != comps.front()[k];
      changing += differs ? 1 : 0;
    }
  auto distinct = [&](const std::string& column) {
    std::vector<double> v;
    for (const auto& x : numeric.at(column)) v.push_back(*x);
    std::sort(v.begin(), v.end());
    return std::adjacent_find(v.begin(), v.end()) == v.end();
  };
  if (changing == 1) {
    for (const auto& [column, label] :
         {std::pair<std::string, std::string>{"scaled_depth_of_burst_m_per_kt3",
                                              "scaled depth of burst [m/kt^(1/3)]"},
          std::pair<std::string, std::string>{"depth_of_burst_m", "depth of burst [m]"}})
      if (complete(column) && distinct(column)) {
        c.x = column;
        c.xlabel = label + " (below the original surface; negative: above it)";
        return c;
      }
  }
  c.bars = true;
  c.x = "label";
  c.xlabel = axes.size() == 1 ? axis.key : "variant";
  return c;
}

}  // namespace ejecta::coupling
