#include "fields/crater_history.hpp"

#include <charconv>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include "core/atomic_file.hpp"

namespace fs = std::filesystem;

namespace ejecta::fields {

namespace {

// Shortest text that reads back to the same double (std::to_chars), so that the CSV and the
// summary's JSON agree to the last bit.
std::string number(double value) {
  char buf[32];
  const auto result = std::to_chars(buf, buf + sizeof buf, value);
  return std::string(buf, result.ptr);
}

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
  std::vector<std::string> kept;
  std::ifstream in(file);
  if (!in) return kept;
  std::string line;
  if (!std::getline(in, line)) return kept;  // empty file: nothing to keep
  if (line != craterHistoryHeader(planar))
    throw std::runtime_error(file.string() + ":1: not a " + (planar ? "planar" : "volumetric") +
                             " crater history (header '" + line + "', expected '" +
                             craterHistoryHeader(planar) + "')");
  for (long lineNumber = 2; std::getline(in, line); ++lineNumber) {
    if (line.empty()) continue;
    double time = 0.0;
    const char* end = line.data() + line.size();
    const auto [ptr, ec] = std::from_chars(line.data(), end, time);
    if (ec != std::errc() || ptr == end || *ptr != ',')
      throw std::runtime_error(file.string() + ":" + std::to_string(lineNumber) +
                               ": time_s is not a number in '" + line + "'");
    if (time < before) kept.push_back(line);
  }
  return kept;
}

CraterHistory::CraterHistory(fs::path file, bool planar) : file_(std::move(file)), planar_(planar) {}

void CraterHistory::record(double time, const CraterMetrics& m) {
  if (!started_) {
    started_ = true;
    // A fresh run's first output is at t = 0: an old file in the directory is simply replaced.
    if (time > 0.0) rows_ = readCraterHistoryRows(file_, planar_, time);
  }
  rows_.push_back(craterHistoryRow(time, m, planar_));
  std::string text = craterHistoryHeader(planar_) + '\n';
  for (const std::string& row : rows_) text += row + '\n';
  writeFileAtomically(file_, text);
}

}  // namespace ejecta::fields
