#include "sim/run/summary.hpp"

#include <nlohmann/json.hpp>

#include "core/atomic_file.hpp"
#include "sim/io/snapshot.hpp"

namespace ejecta {

namespace {

using Json = nlohmann::ordered_json;  // keeps the documented key order in the file

Json toJson(const SummaryValue& value) {
  return std::visit([](const auto& v) { return Json(v); }, value);
}

Json toJson(const std::array<double, 3>& v) { return Json::array({v[0], v[1], v[2]}); }

}  // namespace

void writeSummaryJson(const std::string& path, const RunSummary& s) {
  Json doc;
  doc["ejecta_version"] = std::string(kEjectaVersion);
  doc["scene"] = s.scene;
  doc["status"] = s.status == RunSummary::Status::Completed ? "completed" : "failed";
  doc["message"] = s.message;
  doc["particles"] = s.particles;
  doc["steps"] = s.steps;
  doc["t_end"] = s.tEnd;
  doc["wall_seconds"] = s.wallSeconds;
  doc["threads"] = s.threads;
  doc["energy"] = {{"initial", s.energy.initial},
                   {"final", s.energy.final},
                   {"relative_error", s.energy.relativeError}};
  doc["momentum"] = {{"initial", toJson(s.momentum.initial)},
                     {"final", toJson(s.momentum.final)}};
  Json extras = Json::object();
  for (const auto& [key, value] : s.extras) extras[key] = toJson(value);
  doc["extras"] = std::move(extras);
  // `replace`: a scene name that is not valid UTF-8 must not abort the run's last write.
  writeFileAtomically(path, doc.dump(2, ' ', false, Json::error_handler_t::replace) + "\n");
}

}  // namespace ejecta
