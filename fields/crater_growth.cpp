#include "fields/crater_growth.hpp"

#include <cstdlib>
#include <sstream>

namespace ejecta::fields {

namespace {

struct Sample {
  double time = 0.0;
  bool found = false;
  double volume = 0.0;
};

std::optional<Sample> parseRow(const std::string& row) {
  std::vector<std::string> cells;
  std::stringstream s(row);
  for (std::string cell; std::getline(s, cell, ',');) cells.push_back(cell);
  if (cells.size() < 7) return std::nullopt;
  char* end = nullptr;
  Sample out;
  out.time = std::strtod(cells[0].c_str(), &end);
  if (end == cells[0].c_str()) return std::nullopt;
  out.found = cells[1] == "1";
  out.volume = std::strtod(cells[6].c_str(), &end);
  return out;
}

}  // namespace

std::optional<CraterGrowth> craterGrowth(const std::vector<std::string>& historyRows) {
  std::vector<Sample> samples;
  for (const std::string& row : historyRows)
    if (const std::optional<Sample> s = parseRow(row)) samples.push_back(*s);
  if (samples.size() < 2) return std::nullopt;
  const Sample& last = samples.back();
  const Sample* since = nullptr;
  for (const Sample& s : samples)
    if (s.time <= 0.8 * last.time && s.time < last.time) since = &s;
  if (!since || !since->found || !last.found || !(since->volume > 0.0)) return std::nullopt;
  CraterGrowth g;
  g.since = since->time;
  g.change = last.volume / since->volume - 1.0;
  g.growing = g.change >= kCraterGrowthThreshold;
  return g;
}

}  // namespace ejecta::fields
