// Verification of the generalised volume elements (sph.volume_elements = "generalised",
// X = (m / rho)^p of the step before; label `verification`): against the exact Sedov solutions and
// against the standard (mass) volumes on the same runs. docs/verification.md ("Generalised volume
// elements") has the full comparison, including what p = 1 costs (a noisier shell in 2D and 3D, so
// a larger L1 there).
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
constexpr const char* kGeneralised = "sph.volume_elements=generalised";

// 1D Sedov, the problem's levels (0.01 to 0.0025 m), with the default p = 0.7. Measured at the
// finest: L1(rho) 0.0796 against 0.0879 with mass volumes (0.0730 with p = 1), the same shock
// radius (-1.07%), energy error -9e-5. Bounds: below 0.95 of the mass volumes' L1 (measured 0.91),
// the shock within a bin of theirs, converging level by level, energy to the 1e-3 of the other
// Sedov tests.
TEST(VerifyVolumeElements, Sedov1DLowersTheDensityError) {
  const auto runs = blastWithAndWithout("sedov_1d", {}, kGeneralised, "mass volumes");
  const ResolutionRun &g = runs.finestOption(), &m = runs.finestStandard();
  EXPECT_LT(g.metric("L1_density"), 0.95 * m.metric("L1_density"));
  // The shock radius is a bin's centre (one spacing wide, 0.71% of it at this level): no more
  // than a bin further off.
  EXPECT_LT(std::abs(g.metric("shock_radius_error")),
            std::abs(m.metric("shock_radius_error")) + 0.0075);
  test::expectEachLevelBelowTheLast(runs.option, "L1_density");
  EXPECT_LT(std::abs(g.energyError), 1e-3);
}

// 2D Sedov at 0.01 m (11,443 particles), both volumes. Measured with the default p = 0.7: L1(rho)
// 0.222 against 0.277, peak density 0.765 of the jump (0.703), centre pressure 1.32 of exact
// (1.60), the same shock radius (-1.43%), 273 steps (319). Bounds: L1 below 0.9 of the mass
// volumes' (measured 0.80), the peak above 0.74 and the centre below 1.45 (the gains, with
// margins of 3% and 10%), the shock within the 3% of the Sedov tests. (With p = 1 the peak is
// 0.807 and the centre 1.13 but L1 0.436: docs/verification.md.)
TEST(VerifyVolumeElements, Sedov2DSharpensTheShellAndEmptiesTheCentre) {
  const auto runs =
      blastWithAndWithout("sedov_2d", kSedov2DAtOneCentimetre, kGeneralised, "mass volumes", 1);
  const ResolutionRun &r = runs.finestOption(), &m = runs.finestStandard();
  EXPECT_LT(r.metric("L1_density"), 0.9 * m.metric("L1_density"));
  EXPECT_GT(r.metric("peak_density_ratio"), 0.74);
  EXPECT_LT(r.metric("centre_pressure_ratio"), 1.45);
  EXPECT_GT(r.metric("centre_pressure_ratio"), 0.7);
  EXPECT_LT(std::abs(r.metric("shock_radius_error")), 0.03);
  EXPECT_LT(std::abs(r.energyError), 1e-3);
  EXPECT_LT(r.momentumError, 1e-4);
}

}  // namespace
}  // namespace ejecta::verify
