// The view-factor report of a geometry file: text for the terminal, JSON (nlohmann_json: NaN and
// infinities become null, strings are escaped) and the flux series CSV (core/csv.hpp).
#include <algorithm>
#include <cstdio>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/csv.hpp"
#include "radiation/format_number.hpp"
#include "radiation/geometry_file.hpp"

namespace ejecta::radiation {

namespace {

std::string fmt(const char* format, double x) { return formatNumber(format, x); }

}  // namespace

std::string formatViewFactorText(const ViewFactorReport& rep) {
  std::ostringstream out;
  out << "view factors: " << (rep.name.empty() ? rep.source : rep.name) << "\n";
  out << "  " << rep.patchNames.size() << " surface patches, " << rep.emitterCount << " emitters in "
      << rep.groupNames.size() << " groups" << (rep.occluder ? ", an occluder" : "") << "\n";
  const SamplingOptions& o = rep.sampling;
  out << "  sampling: " << (o.sampler == sampling::Sampler::Sobol ? "scrambled Sobol'" : "random") << ", "
      << o.replicates << " replicates, "
      << (o.rays > 0 ? "fixed " + std::to_string(o.rays) + " rays"
                     : "adaptive to std error " + fmt("%.2g", o.absoluteTolerance) +
                           (o.relativeTolerance > 0.0 ? " (flux " + fmt("%.2g", o.relativeTolerance) + " relative)" : ""))
      << "; " << rep.threads << " threads, " << fmt("%.2f", rep.seconds) << " s\n";
  for (const ReceiverReport& r : rep.receivers) {
    const ReceiverResult& res = r.result;
    out << "\n" << (r.point ? "point " : "patch ") << r.receiver << "  t = " << fmt("%g", r.time) << " s";
    if (!r.point) out << "  area " << fmt("%.6g", r.area) << " m^2";
    out << "  rays " << res.rays << (res.converged ? "" : "  (NOT converged: max rays reached)") << "\n";
    auto line = [&out](const std::string& label, const Estimate& e, const char* unit) {
      out << "  " << label;
      for (std::size_t k = label.size(); k < 28; ++k) out << ' ';
      out << fmt("%12.6g", e.value) << " +- " << fmt("%.2g", e.standardError) << unit << "\n";
    };
    if (!rep.groupNames.empty() || rep.occluder) {
      line("incident flux", res.flux, " W/m^2");
      if (r.baseline)
        out << "  seed baseline (eq. 4.8)     " << fmt("%12.6g", r.baseline->flux) << " W/m^2 from "
            << r.baseline->counted << " emitters, sum Omega " << fmt("%.4g", r.baseline->solidAngleSum) << "\n";
    }
    for (std::size_t p = 0; p < res.toPatch.size(); ++p)
      if (res.toPatch[p].value > 0.0) line("F -> " + rep.patchNames[p], res.toPatch[p], "");
    for (std::size_t g = 0; g < res.toGroup.size(); ++g)
      line("F -> emitters " + rep.groupNames[g], res.toGroup[g], "");
    if (rep.occluder) line("F -> occluder", res.toOccluder, "");
    line("F -> space", res.toSpace, "");
    if (res.toBackFace.value > 0.0) line("F -> back faces (check!)", res.toBackFace, "");
  }
  return out.str();
}

std::string formatViewFactorJson(const ViewFactorReport& rep) {
  using Json = nlohmann::ordered_json;  // keys in the order users' scripts know
  auto estimate = [](const Estimate& e) { return Json{{"value", e.value}, {"std_error", e.standardError}}; };
  const SamplingOptions& o = rep.sampling;
  Json doc;
  doc["name"] = rep.name;
  doc["source"] = rep.source;
  doc["patches"] = rep.patchNames;
  doc["emitter_groups"] = rep.groupNames;
  doc["emitters"] = rep.emitterCount;
  doc["occluder"] = rep.occluder;
  doc["sampling"] = {{"sampler", o.sampler == sampling::Sampler::Sobol ? "sobol" : "random"},
                     {"replicates", o.replicates},
                     {"rays", o.rays},
                     {"tolerance", o.absoluteTolerance},
                     {"relative_tolerance", o.relativeTolerance},
                     {"seed", o.seed}};
  doc["threads"] = rep.threads;
  doc["seconds"] = rep.seconds;
  Json receivers = Json::array();
  for (const ReceiverReport& r : rep.receivers) {
    const ReceiverResult& res = r.result;
    Json j;
    j["name"] = r.receiver;
    j["kind"] = r.point ? "point" : "patch";
    j["time"] = r.time;
    j["area"] = r.area;
    j["rays"] = res.rays;
    j["converged"] = res.converged;
    j["flux"] = estimate(res.flux);
    Json factors = Json::object();
    for (std::size_t p = 0; p < res.toPatch.size(); ++p) factors["patch:" + rep.patchNames[p]] = estimate(res.toPatch[p]);
    for (std::size_t g = 0; g < res.toGroup.size(); ++g)
      factors["emitters:" + rep.groupNames[g]] = estimate(res.toGroup[g]);
    factors["occluder"] = estimate(res.toOccluder);
    factors["space"] = estimate(res.toSpace);
    factors["back_faces"] = estimate(res.toBackFace);
    j["view_factors"] = std::move(factors);
    Json byGroup = Json::object();
    for (std::size_t g = 0; g < res.fluxFromGroup.size(); ++g) byGroup[rep.groupNames[g]] = estimate(res.fluxFromGroup[g]);
    j["flux_by_group"] = std::move(byGroup);
    j["flux_from_occluder"] = estimate(res.fluxFromOccluder);
    if (r.baseline)
      j["seed_baseline"] = {{"flux", r.baseline->flux},
                            {"solid_angle_sum", r.baseline->solidAngleSum},
                            {"emitters", r.baseline->counted}};
    receivers.push_back(std::move(j));
  }
  doc["receivers"] = std::move(receivers);
  return doc.dump(2) + "\n";
}

std::string formatFluxSeriesCsv(const ViewFactorReport& rep) {
  std::vector<std::string> patches;
  std::vector<double> times;
  for (const ReceiverReport& r : rep.receivers) {
    if (r.point) continue;
    if (std::find(patches.begin(), patches.end(), r.receiver) == patches.end()) patches.push_back(r.receiver);
    if (std::find(times.begin(), times.end(), r.time) == times.end()) times.push_back(r.time);
  }
  std::vector<std::string> header{"time_s"};
  header.insert(header.end(), patches.begin(), patches.end());
  CsvWriter csv(header);
  for (const double t : times) {
    csv.number(t);
    for (const std::string& p : patches) {
      double q = 0.0;
      for (const ReceiverReport& r : rep.receivers)
        if (!r.point && r.time == t && r.receiver == p) q = r.result.flux.value;
      csv.number(q);
    }
    csv.endRow();
  }
  return csv.str();
}

}  // namespace ejecta::radiation
