#include "radiation/view_factor_convergence.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "core/csv.hpp"
#include "core/join.hpp"

namespace ejecta::radiation {

namespace {

// Where factor (from -> to) is in a report: the receiver's first entry and the target's index
// among patches (kind 0) or groups (kind 1).
struct FactorIndex {
  std::size_t receiver = 0;
  int kind = 0;
  std::size_t target = 0;
};

std::optional<FactorIndex> locate(const ViewFactorReport& report, const std::string& from,
                                  const std::string& to) {
  for (std::size_t r = 0; r < report.receivers.size(); ++r) {
    if (report.receivers[r].receiver != from) continue;
    for (std::size_t p = 0; p < report.patchNames.size(); ++p)
      if (report.patchNames[p] == to) return FactorIndex{r, 0, p};
    for (std::size_t g = 0; g < report.groupNames.size(); ++g)
      if (report.groupNames[g] == to) return FactorIndex{r, 1, g};
    return std::nullopt;
  }
  return std::nullopt;
}

Estimate valueAt(const ViewFactorReport& report, const FactorIndex& at) {
  const ReceiverResult& r = report.receivers[at.receiver].result;
  return at.kind == 0 ? r.toPatch[at.target] : r.toGroup[at.target];
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

}  // namespace

std::string convergenceColumn(const TrackedFactor& factor) {
  std::string name = factor.from + "_to_" + factor.to;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') c = '_';
  return name;
}

ViewFactorConvergence studyViewFactorConvergence(const GeometryConfig& config,
                                                 std::uint64_t minRays, std::uint64_t maxRays,
                                                 int ratio) {
  if (minRays < 256) throw std::invalid_argument("--min-rays must be at least 256");
  if (maxRays < minRays) throw std::invalid_argument("--max-rays must be at least --min-rays");
  if (ratio < 2) throw std::invalid_argument("the ray count must grow by at least 2 per step");
  ViewFactorConvergence study;
  study.name = config.name.empty() ? config.source : config.name;
  std::vector<std::uint64_t> counts;
  for (std::uint64_t n = minRays; n <= maxRays; n *= static_cast<std::uint64_t>(ratio)) counts.push_back(n);

  std::vector<ViewFactorReport> reports;
  for (const std::uint64_t n : counts) {
    ViewFactorRunOptions run;
    run.rays = n;
    reports.push_back(computeViewFactors(config, run));
  }
  const ViewFactorReport& finest = reports.back();
  std::vector<FactorIndex> where;
  for (const ReferenceFactor& ref : config.references) {
    const std::optional<FactorIndex> at = locate(finest, ref.from, ref.to);
    if (!at) {
      std::vector<std::string> receivers;
      for (const ReceiverReport& r : finest.receivers) receivers.push_back(r.receiver);
      std::vector<std::string> targets = finest.patchNames;
      targets.insert(targets.end(), finest.groupNames.begin(), finest.groupNames.end());
      throw GeometryFileError(config.source + ":" + std::to_string(ref.line) +
                              ": key 'references': no factor from '" + ref.from + "' to '" + ref.to +
                              "' (receivers: " + joinList(receivers) + "; targets: " + joinList(targets) + ")");
    }
    study.factors.push_back({ref.from, ref.to, ref.value, ref.source});
    where.push_back(*at);
  }
  if (config.references.empty()) {
    const double firstTime = finest.receivers.empty() ? 0.0 : finest.receivers.front().time;
    for (std::size_t r = 0; r < finest.receivers.size(); ++r) {
      const ReceiverReport& rec = finest.receivers[r];
      if (rec.time != firstTime) continue;
      for (std::size_t p = 0; p < finest.patchNames.size(); ++p)
        if (rec.result.toPatch[p].value > 0.0) {
          study.factors.push_back({rec.receiver, finest.patchNames[p], std::nullopt, ""});
          where.push_back({r, 0, p});
        }
      for (std::size_t g = 0; g < finest.groupNames.size(); ++g)
        if (rec.result.toGroup[g].value > 0.0) {
          study.factors.push_back({rec.receiver, finest.groupNames[g], std::nullopt, ""});
          where.push_back({r, 1, g});
        }
    }
  }
  for (std::size_t k = 0; k < reports.size(); ++k) {
    ConvergenceStep step;
    step.rays = reports[k].receivers.empty() ? counts[k] : reports[k].receivers.front().result.rays;
    step.seconds = reports[k].seconds;
    for (const FactorIndex& at : where) step.factors.push_back(valueAt(reports[k], at));
    study.steps.push_back(std::move(step));
  }
  return study;
}

std::string formatConvergenceCsv(const ViewFactorConvergence& study) {
  std::vector<std::string> header{"rays", "wall_s"};
  for (const TrackedFactor& f : study.factors) {
    const std::string c = convergenceColumn(f);
    header.push_back(c);
    header.push_back(c + "_stderr");
    if (f.exact) header.push_back(c + "_error");
  }
  header.push_back("inverse_sqrt");
  CsvWriter csv(header);
  if (study.steps.empty()) return csv.str();
  const ConvergenceStep& first = study.steps.front();
  const double e0 = first.factors.empty() ? 0.0 : first.factors.front().standardError;
  for (const ConvergenceStep& s : study.steps) {
    csv.count(s.rays).number(s.seconds);
    for (std::size_t k = 0; k < study.factors.size(); ++k) {
      csv.number(s.factors[k].value).number(s.factors[k].standardError);
      if (study.factors[k].exact) csv.number(std::abs(s.factors[k].value - *study.factors[k].exact));
    }
    csv.number(e0 * std::sqrt(static_cast<double>(first.rays) / static_cast<double>(s.rays)));
    csv.endRow();
  }
  return csv.str();
}

std::string formatConvergenceText(const ViewFactorConvergence& study) {
  std::string out = "view-factor convergence: " + study.name + "\n";
  char line[256];
  for (std::size_t k = 0; k < study.factors.size(); ++k) {
    const TrackedFactor& f = study.factors[k];
    out += "  " + f.from + " -> " + f.to;
    if (f.exact) out += "  (exact " + number(*f.exact) + (f.source.empty() ? "" : ", " + f.source) + ")";
    out += "\n";
    for (const ConvergenceStep& s : study.steps) {
      std::snprintf(line, sizeof line, "    %10llu rays  %10.6f  +- %.2e", static_cast<unsigned long long>(s.rays),
                    s.factors[k].value, s.factors[k].standardError);
      out += line;
      if (f.exact) {
        std::snprintf(line, sizeof line, "  error %+.2e", s.factors[k].value - *f.exact);
        out += line;
      }
      std::snprintf(line, sizeof line, "  %.3f s\n", s.seconds);
      out += line;
    }
  }
  return out;
}

}  // namespace ejecta::radiation
