// Verification of solid mechanics (issue 3): elastic and elastic-plastic waves against theory,
// colliding rubber rings (tensile instability) and the Taylor bar against a published benchmark.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/verify/verification.hpp"

namespace ejecta::verify {
namespace {

TEST(VerifyStrength, ElasticWaveRunsAtTheLongitudinalSpeed) {
  const ResolutionRun run = runProblem("elastic_wave_1d", Options{}).runs.back();
  // Linear elasticity: c_L = sqrt((K + 4G/3)/rho) and sigma = -rho c_L u_p. At h = 2 dx the SPH
  // gradient's lattice error is 0.35% (measured for both), so 1% bounds them.
  EXPECT_LT(std::abs(run.metric("wave_speed_error")), 0.01);
  EXPECT_LT(std::abs(run.metric("stress_error")), 0.01);
  EXPECT_NEAR(run.metric("particle_velocity"), 20.0, 0.05);
}

TEST(VerifyStrength, ElasticPrecursorStopsAtTheHugoniotElasticLimit) {
  const ResolutionRun run = runProblem("elastic_plastic_1d", Options{}).runs.back();
  // The 3% for wave speeds; measured +1.0% (precursor speed), +2.1% (HEL, sampled on a
  // plateau only ~40 particles long), 0.14% (S_xx = -2Y/3 behind the plastic wave).
  EXPECT_LT(std::abs(run.metric("precursor_speed_error")), 0.03);
  EXPECT_LT(std::abs(run.metric("hel_error")), 0.03);
  EXPECT_LT(std::abs(run.metric("deviatoric_stress_error")), 0.01);
}

TEST(VerifyStrength, RubberRingsBounceWithoutFractureOnlyWithArtificialStress) {
  const ResolutionRun with = runProblem("rubber_rings", Options{}).runs.back();
  // Gray et al. (2001): the rings bounce apart and stay whole. Every particle of each ring stays
  // within two spacings of the rest (a crack opens wider gaps), and each ring's centre of mass
  // moves back out (measured 25% of the approach speed at 1.2 ms, the rest ringing as vibration).
  EXPECT_EQ(with.metric("intact_fraction_left"), 1.0);
  EXPECT_EQ(with.metric("intact_fraction_right"), 1.0);
  EXPECT_GT(with.metric("rebound_velocity_ratio"), 0.1);
  EXPECT_LT(std::abs(with.energyError), 1e-3);
  // The control: without artificial stress the tensile instability tears the rings apart
  // (measured: the largest piece holds 48% of a ring) and they do not bounce.
  Options off;
  off.overrides = {"sph.artificial_stress.epsilon=0"};
  const ResolutionRun without = runProblem("rubber_rings", off).runs.back();
  EXPECT_LT(without.metric("intact_fraction_left"), 0.9);
  EXPECT_LT(without.metric("rebound_velocity_ratio"), 0.0);
}

TEST(VerifyStrength, TaylorBarMatchesTheDynelaAbaqusBenchmark) {
  const ResolutionRun run = runProblem("taylor_bar", Options{}).runs.back();
  // The issue asks for 5-10% against the published result. Measured at 10 particles across the
  // radius: length +1.3%, footprint -5.8% (the footprint edge is resolved to one spacing,
  // 0.32 mm of 11.2 mm, so ~3% is its resolution alone), peak plastic strain 1.82 (reference
  // 1.78-1.81).
  EXPECT_LT(std::abs(run.metric("final_length_error")), 0.05);
  EXPECT_LT(std::abs(run.metric("footprint_diameter_error")), 0.10);
  EXPECT_NEAR(run.metric("max_plastic_strain"), 1.8, 0.2);
}

}  // namespace
}  // namespace ejecta::verify
