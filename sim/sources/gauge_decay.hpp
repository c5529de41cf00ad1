#pragma once
// The shock pulse a pressure gauge recorded: peak, arrival and decay constant (docs/undex.md).
// Cole's similitude form for an underwater shock (R. H. Cole, "Underwater Explosions", 1948,
// ch. 7) is P(t) = P_max exp(-(t - t_a) / theta) behind the front; theta is defined there as the
// time the pressure takes to fall from its peak to P_max / e. A computed shock has a rise of a
// few smoothing lengths, so here times are measured from the peak, not from the first rise.
//
// theta is measured two ways from the same history:
//   eFoldTime  the definition: the first time after the peak at which the overpressure has
//              fallen to 1/e of the peak's, linearly interpolated between the two samples that
//              bracket it, minus the peak's time. It needs no model of the tail.
//   fitTime    -1 / slope of a least-squares line through ln(overpressure) against time over the
//              samples from the peak to that e-fold point: the exponential that best matches the
//              whole first e-fold, which is less sensitive to one noisy sample.
// On an exact exponential both equal theta; they differ where the pulse is not exponential (a
// rounded crest, a slower tail), and the difference says how far Cole's form holds.
#include <string>
#include <vector>

namespace ejecta {

struct ShockPulse {
  double peakPressure = 0.0;  // largest overpressure [Pa]
  double peakTime = 0.0;      // when it occurred [s]
  double arrival = 0.0;       // first rise through half the peak overpressure, interpolated [s]
  double eFoldTime = 0.0;     // theta from the 1/e crossing [s]; NaN if the record ends first
  double fitTime = 0.0;       // theta from the log-linear fit over the first e-fold [s]; NaN
                              // if the record ends first or fewer than 3 samples span it
};

// Measures the pulse in a pressure history p(t) (t strictly increasing, same length, at least 2
// samples); ambient is subtracted first (Cole's P is the overpressure). NaN samples (a gauge no
// particle reaches) count as ambient. Throws std::invalid_argument for mismatched lengths,
// non-increasing times or a history that never rises above ambient.
ShockPulse measureShockPulse(const std::vector<double>& time, const std::vector<double>& pressure,
                             double ambient = 0.0);

// The pressure columns of a run's gauges.csv (sim/sources/gauges.hpp: step,time_s, then per gauge
// <name>_pressure_Pa and its density and velocity columns).
struct GaugePressures {
  std::vector<double> time;                    // [s]
  std::vector<std::string> names;              // gauge names, in column order
  std::vector<std::vector<double>> pressure;   // [gauge][row] [Pa]; "nan" reads as NaN
};

// Throws std::runtime_error naming the file, the line and the reason for a missing file, a
// header without time_s or pressure columns, a row with the wrong number of fields or a field
// that is not a number.
GaugePressures readGaugePressures(const std::string& path);

}  // namespace ejecta
