#include "radiation/radiative_balance.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/csv.hpp"

namespace ejecta::radiation {

namespace {

void checkOptics(double absorptivity, double emissivity) {
  if (!(absorptivity >= 0.0 && absorptivity <= 1.0))
    throw std::invalid_argument("radiative balance: absorptivity must lie in [0, 1], got " +
                                std::to_string(absorptivity));
  if (!(emissivity > 0.0 && emissivity <= 1.0))
    throw std::invalid_argument("radiative balance: emissivity must lie in (0, 1], got " +
                                std::to_string(emissivity));
}

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

std::vector<std::string> splitCsv(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) cells.push_back(trim(cell));
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

}  // namespace

double equilibriumTemperature(double incidentFlux, double absorptivity, double emissivity,
                              double sinkTemperature) {
  checkOptics(absorptivity, emissivity);
  if (!(incidentFlux >= 0.0 && std::isfinite(incidentFlux)))
    throw std::invalid_argument("radiative balance: incident flux must be >= 0 and finite, got " +
                                std::to_string(incidentFlux));
  const double s2 = sinkTemperature * sinkTemperature;
  return std::pow(absorptivity * incidentFlux / (emissivity * kStefanBoltzmann) + s2 * s2, 0.25);
}

double incidentFluxForTemperature(double temperature, double absorptivity, double emissivity,
                                  double sinkTemperature) {
  checkOptics(absorptivity, emissivity);
  if (!(absorptivity > 0.0))
    throw std::invalid_argument("radiative balance: a face with zero absorptivity cannot be "
                                "held at a temperature by incident flux");
  return -netAbsorbedFlux(0.0, absorptivity, emissivity, temperature, sinkTemperature) /
         absorptivity;
}

std::vector<double> equilibriumTemperatures(const std::vector<double>& incidentFlux,
                                            double absorptivity, double emissivity,
                                            double sinkTemperature) {
  std::vector<double> t(incidentFlux.size());
  for (std::size_t i = 0; i < t.size(); ++i)
    t[i] = equilibriumTemperature(incidentFlux[i], absorptivity, emissivity, sinkTemperature);
  return t;
}

FluxSeries::FluxSeries(std::vector<double> times, std::vector<double> fluxes)
    : times_(std::move(times)), fluxes_(std::move(fluxes)) {
  if (times_.empty() || times_.size() != fluxes_.size())
    throw std::invalid_argument("flux series: needs as many fluxes as times, and at least one");
  for (std::size_t i = 0; i < times_.size(); ++i) {
    if (!std::isfinite(times_[i]) || !std::isfinite(fluxes_[i]))
      throw std::invalid_argument("flux series: sample " + std::to_string(i) + " is not finite");
    if (i > 0 && !(times_[i] > times_[i - 1]))
      throw std::invalid_argument("flux series: times must increase (sample " +
                                  std::to_string(i) + ")");
  }
}

double FluxSeries::operator()(double t) const {
  if (t <= times_.front()) return fluxes_.front();
  if (t >= times_.back()) return fluxes_.back();
  const auto hi = static_cast<std::size_t>(
      std::upper_bound(times_.begin(), times_.end(), t) - times_.begin());
  const std::size_t lo = hi - 1;
  const double w = (t - times_[lo]) / (times_[hi] - times_[lo]);
  return fluxes_[lo] + w * (fluxes_[hi] - fluxes_[lo]);
}

std::vector<FluxSeries> readFluxSeriesCsv(const std::filesystem::path& path) {
  std::ifstream in(path);
  const std::string file = path.string();
  if (!in) throw std::runtime_error("cannot read flux history '" + file + "'");
  auto fail = [&](int line, const std::string& why) {
    throw std::runtime_error(file + ":" + std::to_string(line) + ": " + why);
  };
  std::size_t columns = 0;
  std::vector<double> times;
  std::vector<std::vector<double>> fluxes;
  int lineNumber = 0;
  for (std::string raw; std::getline(in, raw);) {
    ++lineNumber;
    const std::string line = trim(raw);
    if (line.empty() || line.front() == '#') continue;
    const std::vector<std::string> cells = splitCsv(line);
    if (columns == 0) {  // the header
      if (cells.size() < 2) fail(lineNumber, "the header needs a time column and a flux column");
      columns = cells.size();
      fluxes.assign(columns - 1, {});
      continue;
    }
    if (cells.size() != columns)
      fail(lineNumber, "expected " + std::to_string(columns) + " values (as the header), got " +
                           std::to_string(cells.size()));
    std::vector<double> values(columns);
    for (std::size_t c = 0; c < columns; ++c) {
      if (!parseCsvNumber(cells[c], values[c]) || !std::isfinite(values[c]))
        fail(lineNumber, "value " + std::to_string(c + 1) + " '" + cells[c] +
                             "' is not a finite number");
    }
    if (!times.empty() && !(values[0] > times.back()))
      fail(lineNumber, "time " + cells[0] + " does not increase");
    times.push_back(values[0]);
    for (std::size_t c = 1; c < columns; ++c) fluxes[c - 1].push_back(values[c]);
  }
  if (columns == 0 || times.empty()) fail(lineNumber, "no data rows");
  std::vector<FluxSeries> series;
  series.reserve(fluxes.size());
  for (auto& q : fluxes) series.emplace_back(times, std::move(q));
  return series;
}

SurfaceFlux patchFlux(std::vector<FluxSeries> patches, std::vector<double> patchEdges) {
  if (patches.empty() || patchEdges.size() != patches.size() + 1)
    throw std::invalid_argument("patch flux: needs one more patch edge than patches");
  for (std::size_t i = 1; i < patchEdges.size(); ++i)
    if (!(patchEdges[i] > patchEdges[i - 1]))
      throw std::invalid_argument("patch flux: patch edges must increase");
  // Shared, immutable state: the returned function is thread safe.
  auto p = std::make_shared<const std::vector<FluxSeries>>(std::move(patches));
  auto e = std::make_shared<const std::vector<double>>(std::move(patchEdges));
  return [p, e](double t, double y) {
    const auto it = std::upper_bound(e->begin() + 1, e->end() - 1, y);
    return (*p)[static_cast<std::size_t>(it - (e->begin() + 1))](t);
  };
}

SurfaceFlux uniformFlux(FluxSeries series) {
  auto s = std::make_shared<const FluxSeries>(std::move(series));
  return [s](double t, double) { return (*s)(t); };
}

}  // namespace ejecta::radiation
