// Verification of the Riemann-solver dissipation (sph.dissipation = "riemann", Godunov SPH; label
// `verification`): against the exact Sod and Sedov solutions (1D, 2D, RZ) and against the
// artificial viscosity on the same runs. docs/verification.md ("Riemann-solver dissipation") has
// the full comparison.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "sim/verify/verification.hpp"
#include "support/option_verification.hpp"

namespace ejecta::verify {
namespace {

using test::blastWithAndWithout;
using test::kSedov2DAtOneCentimetre;
using test::runVerification;
constexpr const char* kRiemann = "sph.dissipation=riemann";

// Sod's tube at 112, 225 and 450 particles. Measured at 450: L1 of rho, v, P 0.00474, 0.0151,
// 0.00468 (the viscosity's 0.0037, 0.0127, 0.0043: the rarefaction's head and the contact carry
// more error). Bounds: each about 1.3x its measured value and each level below the coarser one.
TEST(VerifyRiemannDissipation, SodConvergesToTheExactSolution) {
  const Report r = runVerification("sod_1d", {kRiemann});
  const ResolutionRun& f = r.runs.back();
  std::printf("  sod_1d 450: L1 rho %.4g, v %.4g, P %.4g, dE/E %.3g\n", f.metric("L1_density"),
              f.metric("L1_velocity"), f.metric("L1_pressure"), f.energyError);
  EXPECT_LT(f.metric("L1_density"), 0.0062);
  EXPECT_LT(f.metric("L1_velocity"), 0.020);
  EXPECT_LT(f.metric("L1_pressure"), 0.0061);
  for (const char* m : {"L1_density", "L1_velocity", "L1_pressure"})
    test::expectEachLevelBelowTheLast(r, m);
  EXPECT_LT(std::abs(f.energyError), 1e-4);  // walls, no deposit: the integrator's 2e-6
}

// 1D Sedov, the problem's levels (0.01 to 0.0025 m). Measured at the finest: L1(rho) 0.0590
// against the viscosity's 0.0879, the same shock radius (-1.07%), peak 0.92 (0.94), centre 1.00
// (0.99); orders 1.17 and 1.79. Bounds: below 0.8 of the viscosity's L1 (measured 0.67), the shock
// within a bin of the viscosity's, the peak above 0.88, converging level by level, energy to the
// 1e-3 of the other Sedov tests (measured 2.4e-4).
TEST(VerifyRiemannDissipation, Sedov1DLowersTheDensityError) {
  const auto runs = blastWithAndWithout("sedov_1d", {}, kRiemann, "viscosity");
  const ResolutionRun &g = runs.finestOption(), &v = runs.finestStandard();
  EXPECT_LT(g.metric("L1_density"), 0.8 * v.metric("L1_density"));
  // The shock radius is a bin's centre (one spacing wide, 0.71% of it at this level).
  EXPECT_LT(std::abs(g.metric("shock_radius_error")),
            std::abs(v.metric("shock_radius_error")) + 0.0075);
  EXPECT_GT(g.metric("peak_density_ratio"), 0.88);
  test::expectEachLevelBelowTheLast(runs.option, "L1_density");
  EXPECT_LT(std::abs(g.energyError), 1e-3);
}

// 2D Sedov at 0.01 m (11,443 particles). Measured: L1(rho) 0.194 against the viscosity's 0.277,
// peak 0.674 (0.703), centre pressure 1.49 of exact (1.60), the same shock radius (-1.43%), 347
// steps (319). Bounds: L1 below 0.8 of the viscosity's (measured 0.70), the peak above 0.65 and
// the centre below 1.6 (margins of 4% and 7%), the shock within the 3% of the other Sedov tests,
// energy to 1e-3 (measured 8e-5).
TEST(VerifyRiemannDissipation, Sedov2DLowersTheDensityError) {
  const auto runs =
      blastWithAndWithout("sedov_2d", kSedov2DAtOneCentimetre, kRiemann, "viscosity", 1);
  const ResolutionRun &g = runs.finestOption(), &v = runs.finestStandard();
  EXPECT_LT(g.metric("L1_density"), 0.8 * v.metric("L1_density"));
  EXPECT_GT(g.metric("peak_density_ratio"), 0.65);
  EXPECT_LT(g.metric("centre_pressure_ratio"), 1.6);
  EXPECT_LT(std::abs(g.metric("shock_radius_error")), 0.03);
  EXPECT_LT(std::abs(g.energyError), 1e-3);
}

// The seed's RZ Sedov at its levels (0.1 and 0.05 m) without the scene's artificial
// conductivity, which the viscosity needs on the axis (tests/sim/verify/test_verify_sedov.cpp:
// without it the rings within two spacings of the axis peak at 1.72x and 3.71x the jump, growing
// with refinement). Measured with the Riemann dissipation: near the axis 0.68x and 0.92x the jump
// (1.20x at 0.0707 m, 1.04x at 0.035 m: it does not grow), off it 0.99x and 1.11x; L1(rho) 0.351
// and 0.176 (the viscosity with the conductivity 0.2369 at 0.05 m), peak 0.65 and 0.737 (0.700).
// Bounds: the axis within the 1.3x of the jump and of the off-axis peak (as the
// viscosity's own test), L1 at 0.05 m below 0.2 (0.85 of the viscosity's) and falling, the peak
// above 0.72, the shock within the 3% of the other Sedov tests, energy to 1e-3 (measured 3.8e-4).
TEST(VerifyRiemannDissipation, SedovRzHoldsTheAxisWithoutConductivity) {
  const Report r = runVerification("sedov_rz", {kRiemann, "sph.conductivity.alpha=0"});
  for (const ResolutionRun& level : r.runs) {
    const double nearAxis = level.metric("near_axis_peak_pressure_ratio"),
                 offAxis = level.metric("off_axis_peak_pressure_ratio");
    std::printf("  sedov_rz %.3g m: L1 %.4g, peak %.3g, near axis %.3g, off axis %.3g, shock "
                "%.3g, dE/E %.3g\n",
                level.spacing, level.metric("L1_density"), level.metric("peak_density_ratio"),
                nearAxis, offAxis, level.metric("shock_radius_error"), level.energyError);
    EXPECT_LT(nearAxis, 1.3) << level.spacing;
    EXPECT_LT(nearAxis, 1.3 * offAxis) << level.spacing;
    EXPECT_LT(std::abs(level.metric("shock_radius_error")), 0.03) << level.spacing;
  }
  const ResolutionRun& fine = r.runs.back();
  EXPECT_LT(fine.metric("L1_density"), 0.2);
  EXPECT_LT(fine.metric("L1_density"), r.runs.front().metric("L1_density"));
  EXPECT_GT(fine.metric("peak_density_ratio"), 0.72);
  // The shell's binned peak pressure: 0.813 of the jump (the viscosity's 0.785); 0.78 bounds it.
  EXPECT_GT(fine.metric("peak_pressure_ratio"), 0.78);
  EXPECT_LT(std::abs(fine.energyError), 1e-3);
}

// The TNT bar (JWL products behind a programmed burn, 1,000 particles, summation density: the
// option's own) against the viscosity on the same scene: the solver takes any equation of state
// through its sound speed. Measured: L1 of P, v, rho 0.00457, 0.00628, 0.00350 (viscosity 0.00490,
// 0.00716, 0.00370), front -0.057% (-0.024%), peak 1.003 of C-J (1.007). Bounds: each L1 within
// 1.05x of the viscosity's (measured 0.88-0.95), the front within half a spacing (0.1% of its
// position), the peak within 5% of C-J.
TEST(VerifyRiemannDissipation, TntBarWithTheDetonationProducts) {
  const std::vector<std::string> summation = {"sph.density=summation"};
  std::vector<std::string> withRiemann = summation;
  withRiemann.push_back(kRiemann);
  const ResolutionRun v = runVerification("tnt_bar_1d", summation, 1).runs.back(),
                      g = runVerification("tnt_bar_1d", withRiemann, 1).runs.back();
  std::printf("  tnt_bar_1d: L1 P %.4g (%.4g), v %.4g (%.4g), rho %.4g (%.4g), front %.3g, "
              "peak %.4g\n",
              g.metric("L1_pressure"), v.metric("L1_pressure"), g.metric("L1_velocity"),
              v.metric("L1_velocity"), g.metric("L1_density"), v.metric("L1_density"),
              g.metric("front_position_error"), g.metric("peak_pressure_over_cj"));
  for (const char* m : {"L1_pressure", "L1_velocity", "L1_density"})
    EXPECT_LT(g.metric(m), 1.05 * v.metric(m)) << m;
  EXPECT_LT(std::abs(g.metric("front_position_error")), 1e-3);
  EXPECT_NEAR(g.metric("peak_pressure_over_cj"), 1.0, 0.05);
}

}  // namespace
}  // namespace ejecta::verify
