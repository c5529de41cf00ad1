// Verification of the integral-approach gradients (sph.gradients = "iad", sim/sph/iad_matrix.hpp;
// label `verification`): against the exact Sedov and Sod solutions and against the kernel
// gradient on the same runs. docs/verification.md ("Sharper shocks") has the full comparison,
// including where the option does worse (the 2D and 3D Sedov shock runs ahead).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "sim/verify/verification.hpp"
#include "support/option_verification.hpp"

namespace ejecta::verify {
namespace {

Report run(const std::string& problem, const std::string& gradients, int resolutions = 0) {
  Options options;
  options.resolutions = resolutions;
  options.overrides = {"sph.gradients=" + gradients};
  return runProblem(problem, options);
}

// 1D Sedov, the problem's four levels (0.02 to 0.0025 m). Measured at the finest: L1(rho) 0.0427
// with IAD against 0.0879 with the kernel gradient, shock radius -0.36% against -1.07%, energy
// error 2.3e-4 against 4.0e-4. (Without omega in the pressure terms the shock ran 4% fast and the
// L1 did not fall with refinement: sim/sph/hydro_force.cpp.) Bounds: IAD at least a third below
// the kernel's L1 (measured: half), and its shock no further off than the kernel's.
TEST(VerifyIad, Sedov1DHalvesTheDensityError) {
  const auto runs = test::blastWithAndWithout("sedov_1d", {}, "sph.gradients=iad", "kernel");
  const ResolutionRun &i = runs.finestOption(), &k = runs.finestStandard();
  EXPECT_LT(i.metric("L1_density"), 0.67 * k.metric("L1_density"));
  EXPECT_LE(std::abs(i.metric("shock_radius_error")), std::abs(k.metric("shock_radius_error")));
  // Converges: each level's error below the one before it.
  test::expectEachLevelBelowTheLast(runs.option, "L1_density");
  // Pairwise antisymmetric: energy kept to the time integration's error (as the kernel's, 1e-3).
  EXPECT_LT(std::abs(i.energyError), 1e-3);
}

// Sod 1D, three levels. Measured L1(rho) 0.0117, 0.0062, 0.0043 (kernel 0.0131, 0.0066, 0.0037):
// first order, as shock-capturing SPH is; within 20% of the kernel gradient's at each level.
TEST(VerifyIad, Sod1DConvergesAsTheKernelGradientDoes) {
  const Report kernel = run("sod_1d", "kernel"), iad = run("sod_1d", "iad");
  ASSERT_EQ(kernel.runs.size(), iad.runs.size());
  for (std::size_t n = 0; n < iad.runs.size(); ++n) {
    const double li = iad.runs[n].metric("L1_density"), lk = kernel.runs[n].metric("L1_density");
    std::printf("  sod_1d level %zu: L1 %.4g (kernel %.4g)\n", n, li, lk);
    EXPECT_LT(li, 1.2 * lk);
    EXPECT_LT(std::abs(iad.runs[n].energyError), 1e-4);  // measured 5e-6 to 2e-5
  }
  test::expectEachLevelBelowTheLast(iad, "L1_density");
}

// 2D Sedov at 0.01 m (11,443 particles): the shell is sharper but the shock runs 1.4% ahead of
// the similarity solution (the kernel gradient's is 1.4% behind), which doubles L1 (measured
// 0.588 against 0.277). What is asserted is what the option promises everywhere: conservation
// and a shock within the 3% the Sedov tests allow at these resolutions.
TEST(VerifyIad, Sedov2DConservesAndPlacesTheShock) {
  Options options;
  options.resolutions = 1;
  options.overrides = test::kSedov2DAtOneCentimetre;
  options.overrides.push_back("sph.gradients=iad");
  const ResolutionRun r = runProblem("sedov_2d", options).runs.back();
  std::printf("  sedov_2d 0.01 m: L1 %.4g, shock %.3g, peak %.3g, dE/E %.3g, momentum %.3g\n",
              r.metric("L1_density"), r.metric("shock_radius_error"), r.metric("peak_density_ratio"),
              r.energyError, r.momentumError);
  EXPECT_LT(std::abs(r.metric("shock_radius_error")), 0.03);
  EXPECT_LT(std::abs(r.energyError), 1e-3);
  EXPECT_LT(r.momentumError, 1e-4);
}

}  // namespace
}  // namespace ejecta::verify
