// Verification: Sedov-Taylor blasts against the similarity solution (label `verification`).
#include <gtest/gtest.h>

#include <cmath>

#include "sim/verify/verification.hpp"

namespace ejecta::verify {
namespace {

// Common checks at the problem's default (finest) resolution. The shock position is measured as
// the peak of the binned density profile, which SPH smears over ~2h behind the true front; at
// these resolutions 2h is 2-4% of the shock radius, so |error| < radiusTolerance is the
// resolution-limited bound. The peak density of a shell a few h thick is under-resolved: SPH
// reaches 60-80% of the exact jump (rho (gamma+1)/(gamma-1)) at ~100 particles across R.
//
// The hot centre (issue 19): the median pressure of the 32 innermost particles over the exact,
// within [minCentre, maxCentre] at the finest resolution (each problem's measured value and reason
// at its call).
void expectSedov(const Report& r, double radiusTolerance, double minPeak, double maxL1,
                 double minCentre, double maxCentre) {
  const ResolutionRun& fine = r.runs.back();
  EXPECT_GT(fine.metric("centre_pressure_ratio"), minCentre);
  EXPECT_LT(fine.metric("centre_pressure_ratio"), maxCentre);
  EXPECT_LT(std::abs(fine.metric("shock_radius_error")), radiusTolerance);
  EXPECT_GT(fine.metric("peak_density_ratio"), minPeak);
  EXPECT_LT(fine.metric("L1_density"), maxL1);
  // Total energy: the only losses are time-step truncation (Courant 0.3); measured 1-4e-4.
  EXPECT_LT(std::abs(fine.energyError), 1e-3);
  // Momentum: pair forces conserve it to round-off (test_simulation.cpp, periodic box), but these
  // boxes have walls, which push on the ambient gas with P0 ~ 1e-4..1e-1 Pa; where the lattice does
  // not fit the box symmetrically the wall impulses P0 L t differ by up to ~1e-5 of sum m|v|.
  // RZ checks the axial component only.
  EXPECT_LT(fine.momentumError, 1e-4);
  // Refinement must reduce the density error.
  if (r.runs.size() > 1) {
    EXPECT_LT(fine.metric("L1_density"), r.runs.front().metric("L1_density"));
  }
}

// Centre pressure measured 0.82 and 1.55 of exact at 11k and 46k particles; below the issue's
// 2x, with the lower bound for a centre that loses its pressure.
TEST(VerifySedov, Planar2D) {
  expectSedov(runProblem("sedov_2d", Options{}), 0.03, 0.65, 0.35, 0.5, 2.0);
}
TEST(VerifySedov, AxisymmetricRZTheSeedsCase) {
  const Report r = runProblem("sedov_rz", Options{});
  // Centre pressure: the scene's conductivity holds it at 1.10 and 0.97 of exact (0.1, 0.05 m).
  expectSedov(r, 0.03, 0.65, 0.3, 0.6, 1.5);
  // The axis behind the shock (docs/rz.md): the rings within two spacings of it peak no higher
  // than 1.3x the jump and than 1.3x the rings away from it, at 0.1 and at 0.05 m. Without the
  // scene's artificial conductivity their peak grows with refinement (measured 1.72x and 3.71x
  // the jump, 1.19x and 2.55x the off-axis peak); with it, 0.65x and 1.08x the jump (1.12x at
  // 0.035 m: it converges), 0.82x and 1.22x the off-axis peak (1.20x at 0.035 m). 1.3 leaves
  // room above the finest measured ratios for the lattice noise of a single largest particle.
  for (const ResolutionRun& run : r.runs) {
    const double nearAxis = run.metric("near_axis_peak_pressure_ratio");
    const double offAxis = run.metric("off_axis_peak_pressure_ratio");
    EXPECT_LT(nearAxis, 1.3) << "spacing " << run.spacing;
    EXPECT_LT(nearAxis, 1.3 * offAxis) << "spacing " << run.spacing;
  }
  // The shell's binned peak pressure (blast_metrics.hpp) at 0.05 m: measured 0.785 of the 225.4 Pa
  // jump, 177 Pa (the seed's own run read 180 Pa; issue 19's goal is 203 Pa, 0.9: not met).
  // 0.75 bounds it from below as a regression check.
  EXPECT_GT(r.runs.back().metric("peak_pressure_ratio"), 0.75);
}
TEST(VerifySedov, Spherical3D) {
  // 36 particles across the box puts the shock only R/dx = 12.6 spacings from the centre (70-80 in
  // the 2D and RZ problems), and the exact shell behind it (~R/12 thick) is thinner than one
  // spacing: the resolved peak is 40% of the jump (measured 0.40); 0.35 bounds it.
  // The centre is 4.2x exact (the deposit's ~33 particles keep their heat: issue 19's "~4x";
  // artificial conductivity alpha_u = 1 brings it to 1.59 at 9% more L1, docs/verification.md;
  // the SPH-EXA problem at 125k reads 1.48 by default). 6 is a regression bound, not a goal.
  expectSedov(runProblem("sedov_3d", Options{}), 0.05, 0.35, 0.3, 1.0, 6.0);
}

// 1D (j = 1), the deposit two spacings wide at every level: four resolutions, 0.02 to 0.0025 m
// (50 to 400 particles, 0.3 s in all). Measured L1 0.443, 0.414, 0.215, 0.088 (orders 0.10,
// 0.94, 1.29: the coarsest level, 18 particles across R, is not yet asymptotic); peak density
// 0.94 of the jump and shock radius -1.1% (half a bin of one spacing) at 0.0025 m.
TEST(VerifySedov, Plane1DConvergesMonotonicallyWithTheDepositScaledToTheSpacing) {
  Options o;
  o.resolutions = 4;
  const Report r = runProblem("sedov_1d", o);
  ASSERT_EQ(r.runs.size(), 4u);
  // Centre pressure 0.999 and 0.988 of exact at the two finest levels: 1D has no hot centre to
  // speak of at this deposit width; 15% either way is far beyond what the finest levels vary.
  expectSedov(r, 0.02, 0.9, 0.12, 0.85, 1.15);
  for (std::size_t k = 1; k < r.runs.size(); ++k)
    EXPECT_LT(r.runs[k].metric("L1_density"), r.runs[k - 1].metric("L1_density")) << k;
  ASSERT_EQ(r.orders.size(), 3u);
  EXPECT_GT(r.orders[1].value, 0.8);
  EXPECT_GT(r.orders[2].value, 0.8);
}

}  // namespace
}  // namespace ejecta::verify
