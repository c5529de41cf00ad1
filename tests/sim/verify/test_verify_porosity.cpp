// Verification of the porosity models (issue 20): porous aluminium driven by a piston (the
// compaction test of Jutzi, Benz & Michel 2008) under P-alpha and under epsilon-alpha, and
// iSALE's sand under epsilon-alpha, against the exact precursor and compaction jumps of
// sim/exact/porous_compaction.hpp on the scene's own model. Two levels, 0.1 and 0.05 mm (300 to
// 800 particles, ~1 s each problem).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "sim/verify/verification.hpp"

namespace ejecta::verify {
namespace {

TEST(VerifyPorosity, FullCompactionAt458MetresPerSecondMatchesTheJumps) {
  const Report r = runProblem("compaction_1d", Options{});
  ASSERT_EQ(r.runs.size(), 2u);
  const ResolutionRun& run = r.runs.back();
  // The shocked slab is fully compacted (P ~ 1.96 GPa > Ps): density, pressure and energy of
  // the plateau on the matrix's Hugoniot from the precursor state. Measured 5e-5, 2.2e-3 and
  // 3e-4: the bounds allow for the plateau's post-shock ringing (~0.5% in P).
  EXPECT_LT(std::abs(run.metric("compacted_density_error")), 1e-3);
  EXPECT_LT(std::abs(run.metric("compacted_pressure_error")), 0.01);
  EXPECT_LT(std::abs(run.metric("compacted_energy_error")), 0.005);
  EXPECT_NEAR(run.metric("compacted_distention"), 1.0, 1e-6);
  // The elastic precursor stops at the elastic limit (alpha_e, Pe) exactly: a weak, smooth wave
  // (measured 1e-7).
  EXPECT_LT(std::abs(run.metric("elastic_density_error")), 1e-5);
  EXPECT_LT(std::abs(run.metric("elastic_pressure_error")), 1e-4);
  EXPECT_NEAR(run.metric("elastic_distention"), run.metric("elastic_distention_exact"), 1e-5);
  // The fronts where the exact speeds put them: the shock to 0.5% (measured -0.2%), the
  // precursor, a ramp whose midpoint leads by ~1 h, to 2% (measured +1.2%).
  EXPECT_LT(std::abs(run.metric("shock_position_error")), 0.005);
  EXPECT_LT(std::abs(run.metric("precursor_position_error")), 0.02);
  // The density profile converges at first order, as a shock does (measured L1 2.0e-3 ->
  // 1.0e-3, order 1.0).
  EXPECT_LT(run.metric("L1_density"), 2e-3);
  ASSERT_FALSE(r.orders.empty());
  EXPECT_GT(r.orders.front().value, 0.8);
  // Total energy: the leapfrog's error at the shock (measured 1.5e-4).
  EXPECT_LT(std::abs(run.energyError), 1e-3);
}

TEST(VerifyPorosity, PartialCompactionAt150MetresPerSecondEndsOnTheCrushCurve) {
  const Report r = runProblem("compaction_partial_1d", Options{});
  const ResolutionRun& run = r.runs.back();
  // Below Ps the slab keeps pores: alpha behind the wave is the crush curve's at its pressure,
  // 1.0835 (measured 1.0852, +0.15%).
  EXPECT_GT(run.metric("compacted_distention"), 1.05);
  EXPECT_NEAR(run.metric("compacted_distention"), run.metric("compacted_distention_exact"), 0.005);
  // This weak wave has a long foot (the porous material is soft just above Pe) and the plateau
  // sampled is the material shocked during the start-up at the wall, so the bounds are wider
  // than at 458 m/s: density and pressure measured -0.16% and -0.95%, the energy (small,
  // 15.7 kJ/kg, and heated at the wall) +5.5%, the shock position -1.4%.
  EXPECT_LT(std::abs(run.metric("compacted_density_error")), 0.005);
  EXPECT_LT(std::abs(run.metric("compacted_pressure_error")), 0.02);
  EXPECT_LT(std::abs(run.metric("compacted_energy_error")), 0.08);
  EXPECT_LT(std::abs(run.metric("shock_position_error")), 0.03);
  EXPECT_LT(run.metric("L1_density"), 6e-3);  // measured 3.8e-3
  EXPECT_LT(std::abs(run.energyError), 1e-3);
}

// Individual time steps (docs/time_steps.md) carry the distention as every other kicked field:
// the same wave to the same bounds (measured: density +1.8e-4 low, pressure -3e-4, shock
// position +0.1%, L1 1.35e-3).
TEST(VerifyPorosity, IndividualTimeStepsCompactAsGlobalStepsDo) {
  Options o;
  o.overrides = {"time.stepping=individual"};
  const ResolutionRun run = runProblem("compaction_1d", o).runs.back();
  EXPECT_LT(std::abs(run.metric("compacted_density_error")), 1e-3);
  EXPECT_LT(std::abs(run.metric("compacted_pressure_error")), 0.01);
  EXPECT_NEAR(run.metric("compacted_distention"), 1.0, 1e-6);
  EXPECT_LT(std::abs(run.metric("shock_position_error")), 0.005);
  EXPECT_LT(run.metric("L1_density"), 2e-3);
  EXPECT_LT(std::abs(run.energyError), 1e-3);
}

// epsilon-alpha (sim/solid/strain_porosity.hpp): the aluminium slab at 458 m/s through every
// regime (elastic to eps_e with chi = 0.78, exponential, power law), 400 and 800 particles.
TEST(VerifyPorosity, EpsilonAlphaAluminiumMatchesThePrecursorAndTheCompactionShock) {
  const Report r = runProblem("compaction_epsalpha_1d", Options{});
  ASSERT_EQ(r.runs.size(), 2u);
  const ResolutionRun& run = r.runs.back();
  // The elastic precursor stops at the elastic strain exactly (measured 1e-7 in density, 5e-7
  // in pressure) and runs at the porous sound speed (its front +1.0%, a ramp ~1 h ahead).
  EXPECT_LT(std::abs(run.metric("elastic_density_error")), 1e-5);
  EXPECT_LT(std::abs(run.metric("elastic_pressure_error")), 1e-4);
  EXPECT_NEAR(run.metric("elastic_distention"), run.metric("elastic_distention_exact"), 1e-5);
  EXPECT_LT(std::abs(run.metric("precursor_position_error")), 0.02);
  // Behind the compaction shock, measured at both resolutions alike: density +0.22%, pressure
  // -0.54%, energy +0.05%, alpha 1.0208 against 1.0232. The offset is the SPH shock's density
  // overshoot kept by the irreversible model: each particle's strain passes its final value by
  // ~3e-3 inside the front, so its pores stay as crushed as at that peak (docs/porosity.md).
  // The bounds are 1.5-2x those (alpha: 0.004 of the 0.023 it has left).
  EXPECT_LT(std::abs(run.metric("compacted_density_error")), 0.004);
  EXPECT_LT(std::abs(run.metric("compacted_pressure_error")), 0.01);
  EXPECT_LT(std::abs(run.metric("compacted_energy_error")), 1e-3);
  EXPECT_NEAR(run.metric("compacted_distention"), run.metric("compacted_distention_exact"), 0.004);
  EXPECT_GT(run.metric("compacted_distention"), 1.01);  // still porous: the power-law regime
  EXPECT_LT(std::abs(run.metric("shock_position_error")), 0.02);  // measured -1.1%
  // L1 falls with the spacing (measured 2.5e-3 -> 2.0e-3; the plateau's offset sets its floor).
  EXPECT_LT(run.metric("L1_density"), 3e-3);
  EXPECT_LT(run.metric("L1_density"), r.runs.front().metric("L1_density"));
  EXPECT_LT(std::abs(run.energyError), 1e-4);  // measured -1.0e-5
}

// iSALE's 44%-porous sand (alpha_0 = 1.80, kappa = 0.988, alpha_x = 1.29, chi = 0.33) on a
// granite matrix at 500 m/s: one compaction shock from rest (eps_e = 0), 300 and 600 particles.
// Measured: density +0.55%, pressure +0.37%, energy +4e-5, alpha 1.0595 against 1.0655 (the
// overshoot above), shock position -0.6%, L1 8.8e-3 -> 6.8e-3, energy error 2.4e-5. Bounds
// 1.5-2x those (the energy's, which is tiny, 5e-4).
TEST(VerifyPorosity, EpsilonAlphaSandCompactsInOneShock) {
  const Report r = runProblem("compaction_sand_1d", Options{});
  const ResolutionRun& run = r.runs.back();
  EXPECT_LT(std::abs(run.metric("compacted_density_error")), 0.009);
  EXPECT_LT(std::abs(run.metric("compacted_pressure_error")), 0.007);
  EXPECT_LT(std::abs(run.metric("compacted_energy_error")), 5e-4);
  EXPECT_NEAR(run.metric("compacted_distention"), run.metric("compacted_distention_exact"), 0.009);
  EXPECT_GT(run.metric("compacted_distention"), 1.04);
  EXPECT_LT(std::abs(run.metric("shock_position_error")), 0.012);
  EXPECT_LT(run.metric("L1_density"), 0.01);
  EXPECT_LT(run.metric("L1_density"), r.runs.front().metric("L1_density"));
  EXPECT_LT(std::abs(run.energyError), 1e-4);
}

// Individual time steps carry the strain and its history as every other kicked field: the
// aluminium (every regime, an elastic precursor) gives the plateau of global steps (measured:
// alpha 5e-5 apart, the density, pressure and front errors within 2e-4 of global steps', the
// energy error 7.5e-5).
TEST(VerifyPorosity, EpsilonAlphaWithIndividualTimeStepsCompactsAsGlobalStepsDo) {
  Options o;
  o.resolutions = 1;
  const ResolutionRun global = runProblem("compaction_epsalpha_1d", o).runs.back();
  o.overrides = {"time.stepping=individual"};
  const ResolutionRun individual = runProblem("compaction_epsalpha_1d", o).runs.back();
  for (const char* metric : {"compacted_distention", "elastic_distention"})
    EXPECT_NEAR(individual.metric(metric), global.metric(metric), 2e-4) << metric;
  for (const char* metric : {"compacted_density_error", "compacted_pressure_error",
                             "shock_position_error", "precursor_position_error"})
    EXPECT_NEAR(individual.metric(metric), global.metric(metric), 1e-3) << metric;
  EXPECT_LT(std::abs(individual.energyError), 5e-4);
}

// Strength of porous material: the bulk carries its matrix's stress over alpha, as it carries
// the matrix's pressure over alpha (docs/porosity.md): shear modulus G/alpha, flow stress
// Y(alpha P)/alpha. Al-2024 with rigid pores (alpha_0 = 1.25, Pe = 10 GPa far above these
// waves) at its bulk density 2785/1.25: the elastic wave then runs at the matrix's c_L (K and G
// both fall by alpha, as the density does) with the stress rho_bulk c_L u_p, and the Hugoniot
// elastic limit is the matrix's over alpha. Without the 1/alpha on G the wave would run 3.6%
// fast and the HEL sit 20% high.
std::vector<std::string> rigidPores() {
  return {"materials[0].porosity.model=\"p_alpha\"", "materials[0].porosity.initial_distention=1.25",
          "materials[0].porosity.elastic_pressure=\"10 GPa\"",
          "materials[0].porosity.solid_pressure=\"20 GPa\"", "bodies[0].density=\"2228 kg/m^3\"",
          "bodies[1].density=\"2228 kg/m^3\""};
}

TEST(VerifyPorosity, PorousSolidsCarryTheirMatrixStressOverTheDistention) {
  Options porous;
  porous.overrides = rigidPores();
  const ResolutionRun solid = runProblem("elastic_wave_1d", Options{}).runs.back();
  const ResolutionRun pores = runProblem("elastic_wave_1d", porous).runs.back();
  // Measured: speed ratio 1.0000, stress ratio 0.8000.
  EXPECT_NEAR(pores.metric("wave_speed") / solid.metric("wave_speed"), 1.0, 1e-3);
  EXPECT_NEAR(pores.metric("stress") / solid.metric("stress"), 0.8, 0.8 * 5e-3);
  const ResolutionRun plasticSolid = runProblem("elastic_plastic_1d", Options{}).runs.back();
  const ResolutionRun plasticPores = runProblem("elastic_plastic_1d", porous).runs.back();
  EXPECT_NEAR(plasticPores.metric("hel") / plasticSolid.metric("hel"), 0.8, 0.8 * 0.01);  // 0.7995
}

}  // namespace
}  // namespace ejecta::verify
