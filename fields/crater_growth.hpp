#pragma once
// Whether a crater was still growing when its run stopped: its volume (planar: area) at the end
// against its volume at the last output at or before 80% of the run's time, from the rows of
// crater_history.csv. Issue 20's criterion for a crater that has stopped: a change of less than
// 2% over the last fifth of the run (docs/crater.md, "Has the crater stopped growing?").
#include <optional>
#include <string>
#include <vector>

namespace ejecta::fields {

struct CraterGrowth {
  double since = 0.0;   // the time compared with the end [s]
  double change = 0.0;  // V_end / V_since - 1
  bool growing = false;
};

// The threshold of the criterion.
inline constexpr double kCraterGrowthThreshold = 0.02;

// From the history's rows (time in column 0, found in 1, volume or area in 6), the crater's
// growth over the last fifth of the run; none when no crater was found at both times or the
// history does not reach back that far (a run whose first output is past 0.8 t_end).
std::optional<CraterGrowth> craterGrowth(const std::vector<std::string>& historyRows);

}  // namespace ejecta::fields
