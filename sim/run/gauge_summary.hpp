#pragma once
// Each gauge's shock pulse at the end of a run (sim/sources/gauge_decay.hpp), typed: what
// summary.json's "gauge_<name>_*" entries hold (docs/output_format.md) and what `ejecta run`
// prints.
#include <optional>
#include <string>
#include <vector>

#include "sim/run/summary.hpp"
#include "sim/sources/gauge_decay.hpp"

namespace ejecta {

struct GaugeSummary {
  std::string name;
  double peakPressure = 0.0;  // the largest reading [Pa] (absolute, not over the ambient)
  double peakTime = 0.0;      // [s]
  // When the record holds the pulse: its arrival and Cole's decay constant theta (the 1/e time
  // from the peak, and the log-linear fit over that e-fold), each when measured.
  std::optional<double> arrival, decayTime, decayFit;  // [s]
  std::optional<std::string> decayNote;  // why the pulse could not be measured
};

// One per gauge that a particle ever reached, in column order. Overpressure is over the gauge's
// first reading, the ambient before anything arrives.
std::vector<GaugeSummary> gaugeSummaries(const GaugePressures& history);

// Writes the pulses into the summary's extras: the one place their summary.json keys are named.
void addToSummary(const std::vector<GaugeSummary>& gauges, RunSummary& summary);

}  // namespace ejecta
