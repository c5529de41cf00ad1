// Verification: Sod shock tube against the exact Riemann solution (label `verification`).
#include <gtest/gtest.h>

#include "sim/verify/verification.hpp"

namespace ejecta::verify {
namespace {

TEST(VerifySod1D, ConvergesToTheExactRiemannSolution) {
  const Report r = runProblem("sod_1d", Options{});
  ASSERT_EQ(r.runs.size(), 3u);
  const ResolutionRun& fine = r.runs.back();
  // At 450 particles (dx = 1.25 mm left, 10 mm right) M4 SPH with alpha = 1 smears each
  // discontinuity over ~3 h; published SPH results at this resolution have L1(rho) ~ 3-5e-3
  // (e.g. Price 2012, J. Comput. Phys. 231, sec. 5.1). Bounds: 1.5x the measured values, so a
  // real regression fails while platform round-off does not.
  EXPECT_LT(fine.metric("L1_density"), 0.0055);
  EXPECT_LT(fine.metric("L1_velocity"), 0.019);
  EXPECT_LT(fine.metric("L1_pressure"), 0.0065);
  // Shocks and contacts limit any scheme to first order in L1 (Leveque 2002, sec. 8.7); the
  // observed order over 4x refinement must be at least 0.7 for every variable.
  for (const Metric& m : r.orders) EXPECT_GT(m.value, 0.7) << m.name;
  // Energy: leapfrog truncation at Courant 0.3, second order in dt; measured ~2.6e-6.
  for (const ResolutionRun& run : r.runs) EXPECT_LT(std::abs(run.energyError), 3e-5);
}

}  // namespace
}  // namespace ejecta::verify

namespace ejecta::verify {
namespace {

TEST(VerifySod2D, CircularShockTubeOfTheSeedConverges) {
  const Report r = runProblem("sod_2d", Options{});
  ASSERT_EQ(r.runs.size(), 3u);
  const ResolutionRun& fine = r.runs.back();
  // Reduced resolution as the seed ran it (9,756 particles, 81 across the disc). Measured
  // L1 = 0.0105 (rho), 0.041 (v_r), 0.0116 (P) against the converged radial solution; bounds at
  // 1.5x guard against regressions.
  EXPECT_LT(fine.metric("L1_density"), 0.016);
  EXPECT_LT(fine.metric("L1_velocity"), 0.061);
  EXPECT_LT(fine.metric("L1_pressure"), 0.0175);
  // Discontinuities limit the order to one. The coarsest run (20 particles across the disc) is
  // not yet asymptotic (order ~0.5 from it); between the two finest runs the measured order is
  // ~0.75, and 0.6 is asserted there.
  std::string finest = "_";  // (built in two steps: GCC 12 warns falsely on "_" + to_string)
  finest += std::to_string(r.runs.size() - 1);
  for (const Metric& m : r.orders) {
    if (m.name.ends_with(finest)) {
      EXPECT_GT(m.value, 0.6) << m.name;
    }
  }
  // Energy: measured ~1.5e-5 (time-step truncation at Courant 0.3).
  EXPECT_LT(std::abs(fine.energyError), 2e-4);
}

}  // namespace
}  // namespace ejecta::verify
