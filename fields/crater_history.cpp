#include "fields/crater_history.hpp"

namespace fs = std::filesystem;

namespace ejecta::fields {

namespace {
std::string kind(bool planar) { return planar ? "planar crater history" : "volumetric crater history"; }
constexpr auto number = shortestNumber;
}  // namespace

std::string craterHistoryHeader(bool planar) {
  return planar ? "time_s,found,depth_m,apparent_diameter_m,rim_diameter_m,rim_height_m,"
                  "area_m2,excavated_mass_kg_per_m"
                : "time_s,found,depth_m,apparent_diameter_m,rim_diameter_m,rim_height_m,"
                  "volume_m3,excavated_mass_kg,elongation";
}

std::string craterHistoryRow(double time, const CraterMetrics& m, bool planar) {
  std::string row = number(time) + ',' + (m.found ? "1" : "0") + ',' + number(m.depth) + ',' +
                    number(m.apparentDiameter) + ',' + number(m.rimDiameter) + ',' +
                    number(m.rimHeight) + ',' + number(m.volume) + ',' + number(m.excavatedMass);
  if (!planar) row += ',' + number(m.elongation);
  return row;
}

std::vector<std::string> readCraterHistoryRows(const fs::path& file, bool planar, double before) {
  return readHistoryRows(file, craterHistoryHeader(planar), kind(planar), before);
}

CraterHistory::CraterHistory(fs::path file, bool planar)
    : history_(std::move(file), craterHistoryHeader(planar), kind(planar)), planar_(planar) {}

void CraterHistory::record(double time, const CraterMetrics& m) {
  history_.record(time, craterHistoryRow(time, m, planar_));
}

}  // namespace ejecta::fields
