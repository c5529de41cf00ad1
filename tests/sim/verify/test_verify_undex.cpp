// Verification of underwater explosions in 1D (label `verification`), against the exact
// impedance match of the C-J products and water (sim/exact/impedance_match.hpp): the supported
// detonation (products at the C-J state against water: the Riemann problem itself) and the TNT
// slab lit at its far end (the seed's 1D UNDEX case). Numbers: docs/undex.md.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "sim/verify/verification.hpp"

namespace ejecta::verify {
namespace {

TEST(VerifyUndex, SupportedDetonationMatchesTheExactRiemannSolution) {
  const Report r = runProblem("undex_riemann_1d", Options{});
  ASSERT_EQ(r.runs.size(), 3u);
  const ResolutionRun& fine = r.runs.back();  // dx = 0.2 mm, h = 0.4 mm, 800 particles
  // The shocked water's plateau against p* = 14.55 GPa and u* = 2487 m/s: measured -1.8e-5 and
  // -3.5e-5 (-7e-4 and -1.4e-4 at 0.8 mm). The plateau is uniform in the exact solution, so only
  // the scheme's consistency error remains there; 1e-3 is 5x the coarsest run's error and would
  // catch a 0.1% error in the EOS, the Hugoniot or the isentrope.
  EXPECT_LT(std::abs(fine.metric("interface_pressure_error")), 1e-3);
  EXPECT_LT(std::abs(fine.metric("interface_velocity_error")), 1e-3);
  // The shock at 47 mm: measured +0.07% (0.09 h); 0.5% is 0.6 h.
  EXPECT_LT(std::abs(fine.metric("shock_position_error")), 5e-3);
  // Whole profile, in units of the star state: measured 0.76% (P), 0.41% (v), 0.27% (rho).
  EXPECT_LT(fine.metric("L1_pressure"), 0.012);
  EXPECT_LT(fine.metric("L1_velocity"), 0.006);
  EXPECT_LT(fine.metric("L1_density"), 0.004);
  // A shock, a contact and a fan's kinks: first order at best. Measured 0.85-1.0 over the three
  // runs; asserted > 0.7.
  for (const Metric& m : r.orders) EXPECT_GT(m.value, 0.7) << m.name;
  // No burn: the energy error is the time integrator's alone (measured 2.6e-5).
  for (const ResolutionRun& run : r.runs) EXPECT_LT(std::abs(run.energyError), 1e-4);
}

TEST(VerifyUndex, DetonatedSlabLaunchesTheImpedanceMatchShockIntoWater) {
  const Report r = runProblem("undex_1d", Options{});
  ASSERT_EQ(r.runs.size(), 3u);
  const ResolutionRun& fine = r.runs.back();  // dx = 0.2 mm: the slab is 500 spacings long
  // The gauges' peaks from 4 to 20 mm, extrapolated to the interface, against p* = 14.55 GPa:
  // measured -14.6%, -11.6%, -8.0% at dx = 0.8, 0.4, 0.2 mm (with the compression burn; -12.3%,
  // -10.4%, -7.4% without it). The programmed burn rounds the C-J crest over ~3 h and the Taylor
  // wave right behind it starts the decay at once, so the transmitted peak converges slowly.
  // 10% is the criterion.
  EXPECT_LT(std::abs(fine.metric("peak_pressure_error")), 0.10);
  double previous = 1e300;
  for (const ResolutionRun& run : r.runs) {
    EXPECT_LT(std::abs(run.metric("peak_pressure_error")), previous) << run.spacing;
    previous = std::abs(run.metric("peak_pressure_error"));
  }
  // Rankine-Hugoniot in the water: the shock's mean speed over the gauges against the water
  // Hugoniot at the particle velocities the gauges read at their peaks: measured +0.43% (and
  // +1.18%, +0.54% coarser). 1.5% is what a 2.5% error in the gauges' up gives (dUs/dup = 1.5).
  EXPECT_LT(std::abs(fine.metric("shock_speed_error")), 0.015);
  // The shock line traced back to the interface meets it when the detonation arrives, L/D
  // = 14.43 us: measured -0.25%. 0.5% is 0.07 us, 0.5 mm (1.25 h) of detonation travel.
  EXPECT_LT(std::abs(fine.metric("shock_launch_time_error")), 5e-3);
  // The burn's energy error (docs/sources.md: 7-8e-4 at every resolution); 2e-3 bounds it.
  for (const ResolutionRun& run : r.runs) EXPECT_LT(std::abs(run.energyError), 2e-3);
}

TEST(VerifyUndex, DetonatedSlabKeepsConvergingPastTheOverdriveLimit) {
  // Before the compression burn the front overdrove beyond ~500 spacings of travel (dx = 0.1 mm
  // reached 2710 kg/m^3 behind the front, 0.05 mm collapsed). One level finer than the scene:
  // dx = 0.4, 0.2, 0.1 mm, the slab 1000 spacings long at the finest.
  Options o;
  o.overrides = {"bodies[0].spacing=\"0.1 mm\"", "bodies[1].spacing=\"0.1 mm\""};
  const Report r = runProblem("undex_1d", o);
  ASSERT_EQ(r.runs.size(), 3u);
  // Measured -11.6%, -8.0%, -5.3% (and -3.6% at 0.05 mm, 18 s, not run here): still converging
  // toward p*, at observed order 0.59. 6.5% fails unless the 0.1 mm run improves on the 0.2 mm
  // run's 8.0% by at least 1.5 points; order > 0.4 (measured 0.57-0.59) fails if it stalls.
  EXPECT_LT(std::abs(r.runs.back().metric("peak_pressure_error")), 0.065);
  for (const Metric& m : r.orders) {
    if (m.name.rfind("order_peak_pressure_error", 0) == 0) {
      EXPECT_GT(m.value, 0.4) << m.name;
    }
  }
  // No overdrive: an overdriven front launches a stronger, faster water shock early. The shock
  // speed against the water Hugoniot (measured +0.46%) and the launch time against L/D
  // (measured -0.27%) hold as at the scene's resolution.
  EXPECT_LT(std::abs(r.runs.back().metric("shock_speed_error")), 0.015);
  EXPECT_LT(std::abs(r.runs.back().metric("shock_launch_time_error")), 5e-3);
}

}  // namespace
}  // namespace ejecta::verify
