#pragma once
// [time] of a scene: the end time and the limits on the step.

namespace ejecta {

struct TimeOptions {
  double tEnd = 0.0;          // [s], required
  double dtMax = 0.0;         // [s], 0 = unlimited
  double dtMin = 0.0;         // [s], dt below this stops the run (0 = 1e-12 * tEnd)
  long maxSteps = 0;          // 0 = unlimited
};

}  // namespace ejecta
