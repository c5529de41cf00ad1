#include "sim/sources/gauge_decay.hpp"

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "core/csv.hpp"

namespace ejecta {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Time at which the straight line through (t0, p0) and (t1, p1) crosses level.
double crossing(double t0, double p0, double t1, double p1, double level) {
  return t0 + (level - p0) / (p1 - p0) * (t1 - t0);
}

std::vector<std::string> splitCsv(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream s(line);
  std::string field;
  while (std::getline(s, field, ',')) fields.push_back(field);
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

}  // namespace

ShockPulse measureShockPulse(const std::vector<double>& time, const std::vector<double>& pressure,
                             double ambient) {
  if (time.size() != pressure.size())
    throw std::invalid_argument("measureShockPulse: " + std::to_string(time.size()) +
                                " times but " + std::to_string(pressure.size()) + " pressures");
  if (time.size() < 2) throw std::invalid_argument("measureShockPulse: fewer than 2 samples");
  for (std::size_t k = 1; k < time.size(); ++k)
    if (!(time[k] > time[k - 1]))
      throw std::invalid_argument("measureShockPulse: times not increasing at sample " +
                                  std::to_string(k));
  std::vector<double> over(pressure.size());
  for (std::size_t k = 0; k < pressure.size(); ++k)
    over[k] = std::isnan(pressure[k]) ? 0.0 : pressure[k] - ambient;

  ShockPulse pulse;
  std::size_t peak = 0;
  for (std::size_t k = 1; k < over.size(); ++k)
    if (over[k] > over[peak]) peak = k;
  if (!(over[peak] > 0.0))
    throw std::invalid_argument("measureShockPulse: the pressure never rises above ambient");
  pulse.peakPressure = over[peak];
  pulse.peakTime = time[peak];

  // Arrival: the last rise through half the peak before it (the front, not an earlier ripple
  // that fell back), interpolated.
  const double half = 0.5 * pulse.peakPressure;
  pulse.arrival = time[peak];
  for (std::size_t k = peak; k > 0; --k)
    if (over[k - 1] < half && over[k] >= half) {
      pulse.arrival = crossing(time[k - 1], over[k - 1], time[k], over[k], half);
      break;
    }

  // The first fall through P_max / e after the peak.
  const double level = pulse.peakPressure / std::exp(1.0);
  std::size_t below = 0;
  for (std::size_t k = peak + 1; k < over.size(); ++k)
    if (over[k] <= level) {
      below = k;
      break;
    }
  if (below == 0) {
    pulse.eFoldTime = pulse.fitTime = kNaN;
    return pulse;
  }
  pulse.eFoldTime =
      crossing(time[below - 1], over[below - 1], time[below], over[below], level) - pulse.peakTime;

  // Log-linear least squares over [peak, below): every sample there is above P_max / e > 0.
  const std::size_t n = below - peak;
  if (n < 3) {
    pulse.fitTime = kNaN;
    return pulse;
  }
  double st = 0, sy = 0, stt = 0, sty = 0;
  for (std::size_t k = peak; k < below; ++k) {
    const double t = time[k] - pulse.peakTime, y = std::log(over[k]);
    st += t;
    sy += y;
    stt += t * t;
    sty += t * y;
  }
  const double count = static_cast<double>(n);
  const double slope = (count * sty - st * sy) / (count * stt - st * st);
  pulse.fitTime = slope < 0.0 ? -1.0 / slope : kNaN;
  return pulse;
}

GaugePressures readGaugePressures(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open the gauge history");
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(path + ":1: empty file, no header");
  const std::vector<std::string> header = splitCsv(line);
  const std::string suffix = "_pressure_Pa";
  std::size_t timeColumn = header.size();
  std::vector<std::size_t> columns;
  GaugePressures g;
  for (std::size_t c = 0; c < header.size(); ++c) {
    const std::string& h = header[c];
    if (h == "time_s") timeColumn = c;
    if (h.size() > suffix.size() && h.compare(h.size() - suffix.size(), suffix.size(), suffix) == 0) {
      columns.push_back(c);
      g.names.push_back(h.substr(0, h.size() - suffix.size()));
    }
  }
  if (timeColumn == header.size())
    throw std::runtime_error(path + ":1: the header has no time_s column");
  if (columns.empty())
    throw std::runtime_error(path + ":1: the header has no <gauge>_pressure_Pa column");
  g.pressure.resize(columns.size());

  auto number = [&](const std::string& field, std::size_t lineNo, std::size_t c) {
    double v = 0.0;
    if (!parseCsvNumber(field, v))
      throw std::runtime_error(path + ":" + std::to_string(lineNo) + ": column '" + header[c] +
                               "': '" + field + "' is not a number");
    return v;
  };
  std::size_t lineNo = 1;
  while (std::getline(in, line)) {
    ++lineNo;
    if (line.empty()) continue;
    const std::vector<std::string> fields = splitCsv(line);
    if (fields.size() != header.size())
      throw std::runtime_error(path + ":" + std::to_string(lineNo) + ": " +
                               std::to_string(fields.size()) + " fields, the header has " +
                               std::to_string(header.size()));
    g.time.push_back(number(fields[timeColumn], lineNo, timeColumn));
    for (std::size_t k = 0; k < columns.size(); ++k)
      g.pressure[k].push_back(number(fields[columns[k]], lineNo, columns[k]));
  }
  return g;
}

}  // namespace ejecta
