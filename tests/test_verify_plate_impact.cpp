// Verification (issue 3, hydrodynamic part): Al-2024 plate impact against the published Hugoniot.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/verify/verification.hpp"

namespace ejecta::verify {
namespace {

TEST(VerifyPlateImpact, ShockSpeedAndPressureFollowTheAl2024Hugoniot) {
  const Report r = runProblem("plate_impact_al", Options{});
  const ResolutionRun& run = r.runs.back();
  // Symmetric impact at 2 km/s: the shocked material moves at exactly half the impact speed.
  EXPECT_NEAR(run.metric("particle_velocity"), 1000.0, 1.0);
  // The bound: shock speed within 3% of Us = C0 + s up (Steinberg 1996, from Marsh 1980).
  // Measured +1.7%, resolution independent: continuity density drifts 1.3% from the particle
  // spacing across the shock (docs/verification.md), so the tracked front runs slightly ahead.
  EXPECT_LT(std::abs(run.metric("shock_speed_error")), 0.03);
  // The shocked state itself sits on the Hugoniot: P = rho0 Us up to 0.2% (measured 0.18%).
  EXPECT_LT(std::abs(run.metric("shock_pressure_error")), 0.005);
  EXPECT_LT(std::abs(run.energyError), 1e-4);
}

}  // namespace
}  // namespace ejecta::verify
