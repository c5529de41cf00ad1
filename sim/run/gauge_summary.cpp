#include "sim/run/gauge_summary.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace ejecta {

std::vector<GaugeSummary> gaugeSummaries(const GaugePressures& history) {
  std::vector<GaugeSummary> out;
  for (std::size_t g = 0; g < history.names.size(); ++g) {
    const std::vector<double>& p = history.pressure[g];
    double ambient = std::numeric_limits<double>::quiet_NaN();
    for (double v : p)
      if (std::isfinite(v)) {
        ambient = v;
        break;
      }
    if (!std::isfinite(ambient)) continue;  // no particle ever reached the gauge
    const auto peak = std::max_element(p.begin(), p.end(), [](double a, double b) {
      return std::isnan(a) || (!std::isnan(b) && b > a);
    });
    GaugeSummary s;
    s.name = history.names[g];
    s.peakPressure = *peak;
    s.peakTime = history.time[static_cast<std::size_t>(peak - p.begin())];
    if (history.time.size() >= 2 && *peak > ambient) {
      try {
        const ShockPulse pulse = measureShockPulse(history.time, p, ambient);
        s.arrival = pulse.arrival;
        if (std::isfinite(pulse.eFoldTime)) s.decayTime = pulse.eFoldTime;
        if (std::isfinite(pulse.fitTime)) s.decayFit = pulse.fitTime;
      } catch (const std::invalid_argument& e) {  // e.g. a history whose times repeat
        s.decayNote = e.what();
      }
    }
    out.push_back(std::move(s));
  }
  return out;
}

void addToSummary(const std::vector<GaugeSummary>& gauges, RunSummary& summary) {
  auto& x = summary.extras;
  for (const GaugeSummary& g : gauges) {
    const std::string key = "gauge_" + g.name;
    x.push_back({key + "_peak_pressure_Pa", g.peakPressure});
    x.push_back({key + "_peak_time_s", g.peakTime});
    if (g.arrival) x.push_back({key + "_arrival_s", *g.arrival});
    if (g.decayTime) x.push_back({key + "_decay_time_s", *g.decayTime});
    if (g.decayFit) x.push_back({key + "_decay_fit_s", *g.decayFit});
    if (g.decayNote) x.push_back({key + "_decay_note", *g.decayNote});
  }
}

}  // namespace ejecta
