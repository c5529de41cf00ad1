// Verification of the energy sources (label `verification`): the programmed burn of TNT against
// the exact C-J detonation and Taylor wave (sim/exact/taylor_wave.hpp).
#include <gtest/gtest.h>

#include <cmath>

#include "sim/verify/verification.hpp"

namespace ejecta::verify {
namespace {

TEST(VerifyTntBar, DetonationAndTaylorWaveMatchTheExactSolution) {
  const Report r = runProblem("tnt_bar_1d", Options{});
  ASSERT_EQ(r.runs.size(), 3u);
  const ResolutionRun& fine = r.runs.back();  // 1000 particles, dx = 0.2 mm, h = 0.4 mm
  // The front: the last particle above P_CJ/2 against the exact D t (measured -0.04% with the
  // compression burn, -0.24% without): 1% is 4 h.
  EXPECT_LT(std::abs(fine.metric("front_position_error")), 0.01);
  // The von Neumann spike is absent in a programmed burn; SPH smears the C-J peak over ~2 h.
  // Measured 0.969 P_CJ at 0.2 mm and 0.929 at 0.4 mm: within 10% of P_CJ = 21 GPa.
  EXPECT_NEAR(fine.metric("peak_pressure_over_cj"), 1.0, 0.10);
  // The products at rest behind the Taylor wave: measured 0.25% above the exact 5.64 GPa. The
  // wall state depends only on the isentrope through the C-J point, so 1% tests the EOS, burn
  // and momentum balance together.
  EXPECT_LT(std::abs(fine.metric("rest_pressure_error")), 0.01);
  // Whole-profile errors, in units of the C-J state: measured 0.48% (P), 0.64% (v), 0.25% (rho);
  // the compression burn lights the particles squeezed just ahead of the front, which rounds the
  // front over ~h (0.42%, 0.49%, 0.23% without it, which however collapses at 0.05 mm). 1.5x the
  // measured values.
  EXPECT_LT(fine.metric("L1_pressure"), 0.0075);
  EXPECT_LT(fine.metric("L1_velocity"), 0.0095);
  EXPECT_LT(fine.metric("L1_density"), 0.004);
  // Convergence: the C-J kink and the front limit L1 to first order; over the three runs the
  // velocity converges at ~0.95 (asserted > 0.7).
  for (const Metric& m : r.orders)
    if (m.name.find("L1_velocity") != std::string::npos) {
      EXPECT_GT(m.value, 0.7) << m.name;
    }
  // Energy: the burn switches each particle's pressure on within ~3 time steps, a leapfrog error
  // that does not shrink with h (measured 7.2e-4 at every resolution); 2e-3 bounds it.
  for (const ResolutionRun& run : r.runs) EXPECT_LT(std::abs(run.energyError), 2e-3);
}

}  // namespace
}  // namespace ejecta::verify
