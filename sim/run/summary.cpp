#include "sim/run/summary.hpp"

#include <stdexcept>

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

const SummaryValue* findExtra(const RunSummary& s, const std::string& key) {
  const SummaryValue* found = nullptr;
  for (const auto& [k, v] : s.extras)
    if (k == key) found = &v;
  return found;
}

template <typename T>
const T& extraAs(const RunSummary& s, const std::string& key, const char* type) {
  const SummaryValue* v = findExtra(s, key);
  if (!v) throw std::out_of_range("run summary: no extra '" + key + "'");
  if (!std::holds_alternative<T>(*v))
    throw std::out_of_range("run summary: extra '" + key + "' is not " + type);
  return std::get<T>(*v);
}

const char* statusName(RunSummary::Status status) {
  switch (status) {
    case RunSummary::Status::Completed: return "completed";
    case RunSummary::Status::Failed: return "failed";
    case RunSummary::Status::Interrupted: return "interrupted";
  }
  return "failed";
}

}  // namespace

bool RunSummary::has(const std::string& key) const { return findExtra(*this, key) != nullptr; }
double RunSummary::number(const std::string& key) const {
  return extraAs<double>(*this, key, "a number");
}
std::int64_t RunSummary::integer(const std::string& key) const {
  return extraAs<std::int64_t>(*this, key, "an integer");
}
bool RunSummary::flag(const std::string& key) const { return extraAs<bool>(*this, key, "a flag"); }
const std::string& RunSummary::text(const std::string& key) const {
  return extraAs<std::string>(*this, key, "a text");
}

void writeSummaryJson(const std::string& path, const RunSummary& s) {
  Json doc;
  doc["ejecta_version"] = std::string(kEjectaVersion);
  doc["scene"] = s.scene;
  doc["status"] = statusName(s.status);
  doc["message"] = s.message;
  doc["particles"] = s.particles;
  doc["steps"] = s.steps;
  doc["t_end"] = s.tEnd;
  doc["wall_seconds"] = s.wallSeconds;
  doc["total_wall_seconds"] = s.totalWallSeconds;
  doc["threads"] = s.threads;
  if (s.ranks > 1) doc["ranks"] = s.ranks;
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
