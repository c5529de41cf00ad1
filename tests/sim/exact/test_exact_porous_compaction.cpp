// The exact compaction wave of a P-alpha or epsilon-alpha material
// (sim/exact/porous_compaction.hpp): its jump conditions, its closure on the model's state, and
// limits with closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "sim/eos/mie_gruneisen.hpp"
#include "sim/eos/tillotson.hpp"
#include "sim/exact/porous_compaction.hpp"
#include "support/strain_porosity_sets.hpp"

namespace ejecta {
namespace {

// JBM08's porous aluminium (their compaction test): alpha_0 = 1.275, Pe = 0.08 GPa,
// Ps = 0.7 GPa, c_e = 4.11 km/s, on the Tillotson aluminium of the library.
Tillotson aluminium() { return Tillotson(tillotsonLibrary("aluminium")); }

PalphaModel jutziAluminium(const EquationOfState& matrix) {
  PalphaParameters p;
  p.initialDistention = 1.275;
  p.elasticPressure = 0.08e9;
  p.solidPressure = 0.7e9;
  p.solidDensity = matrix.referenceDensity();
  p.solidSoundSpeed = matrix.soundSpeed(p.solidDensity, 0.0);
  p.porousSoundSpeed = 4110.0;
  return PalphaModel(p);
}

// Mass, momentum and energy across a front from a to b moving at D.
void expectJump(const exact::PorousState& a, const exact::PorousState& b, double D) {
  const double flux = a.rho * (D - a.v);
  EXPECT_NEAR(b.rho * (D - b.v), flux, 1e-10 * flux);
  EXPECT_NEAR(b.P - a.P, flux * (b.v - a.v), 1e-9 * b.P);
  EXPECT_NEAR(b.u - a.u, 0.5 * (a.P + b.P) * (1.0 / a.rho - 1.0 / b.rho), 1e-9 * b.u);
}

TEST(ExactPorousCompaction, JutziAluminiumSplitsIntoPrecursorAndCompactionShock) {
  const Tillotson matrix = aluminium();
  const PalphaModel model = jutziAluminium(matrix);
  const exact::CompactionWave w = exact::compactionWave(matrix, model, 458.0);
  ASSERT_TRUE(w.twoWaves());
  EXPECT_NEAR(w.initial.rho, 2700.0 / 1.275, 1e-9);
  // The precursor ends at the elastic limit, moving near the porous sound speed c_e (its strain
  // is ~1e-3, so within 1%).
  EXPECT_DOUBLE_EQ(w.elastic.P, 0.08e9);
  EXPECT_DOUBLE_EQ(w.elastic.alpha, model.elasticDistention());
  EXPECT_NEAR(w.precursorSpeed, 4110.0, 0.01 * 4110.0);
  expectJump(w.initial, w.elastic, w.precursorSpeed);
  expectJump(w.elastic, w.compacted, w.shockSpeed);
  EXPECT_DOUBLE_EQ(w.compacted.v, 458.0);
  EXPECT_LT(w.shockSpeed, w.precursorSpeed);
  // 458 m/s compacts fully (P > Ps), and the state closes on the matrix's equation of state.
  EXPECT_GT(w.compacted.P, 0.7e9);
  EXPECT_DOUBLE_EQ(w.compacted.alpha, 1.0);
  EXPECT_NEAR(matrix.pressure(w.compacted.rho, w.compacted.u), w.compacted.P, 1e-9 * w.compacted.P);
}

TEST(ExactPorousCompaction, PartialCompactionEndsOnTheCrushCurve) {
  const Tillotson matrix = aluminium();
  const PalphaModel model = jutziAluminium(matrix);
  const exact::CompactionWave w = exact::compactionWave(matrix, model, 150.0);
  ASSERT_TRUE(w.twoWaves());
  const exact::PorousState& b = w.compacted;
  EXPECT_GT(b.P, 0.08e9);
  EXPECT_LT(b.P, 0.7e9);
  EXPECT_GT(b.alpha, 1.0);
  EXPECT_DOUBLE_EQ(b.alpha, model.crushDistention(b.P));
  EXPECT_NEAR(b.alpha * b.P, matrix.pressure(b.alpha * b.rho, b.u), 1e-9 * b.alpha * b.P);
  expectJump(w.elastic, b, w.shockSpeed);
}

// The two-segment curve (alpha_t, Pt, n1) closes the jump the same way.
TEST(ExactPorousCompaction, TwoSegmentCurveEndsOnItself) {
  const Tillotson matrix = aluminium();
  PalphaParameters p = jutziAluminium(matrix).parameters();
  p.transitionPressure = 0.3e9;
  p.transitionDistention = 1.15;
  p.transitionExponent = 4.0;
  const PalphaModel model(p);
  const exact::CompactionWave w = exact::compactionWave(matrix, model, 150.0);
  const exact::PorousState& b = w.compacted;
  EXPECT_GT(b.alpha, 1.0);
  EXPECT_DOUBLE_EQ(b.alpha, model.crushDistention(b.P));
  EXPECT_NEAR(b.alpha * b.P, matrix.pressure(b.alpha * b.rho, b.u), 1e-9 * b.alpha * b.P);
  expectJump(w.elastic, b, w.shockSpeed);
}

// Nearly no pores: the wave is the matrix's own shock, Us = C0 + s up on the Mie-Grueneisen
// Hugoniot of Al-2024 (Steinberg 1996): 6666 m/s at 1 km/s.
TEST(ExactPorousCompaction, WithoutPoresIsTheMatrixHugoniot) {
  const MieGruneisen matrix(shockMaterial("Al-2024"));
  PalphaParameters p;
  p.initialDistention = 1.0 + 1e-9;
  p.elasticPressure = 0.0;
  p.solidPressure = 1.0;  // compacted at once
  p.solidDensity = matrix.referenceDensity();
  p.solidSoundSpeed = matrix.soundSpeed(p.solidDensity, 0.0);
  p.porousSoundSpeed = p.solidSoundSpeed;
  const exact::CompactionWave w = exact::compactionWave(matrix, PalphaModel(p), 1000.0);
  EXPECT_FALSE(w.twoWaves());
  EXPECT_NEAR(w.shockSpeed, 5328.0 + 1.338 * 1000.0, 1e-5 * 6666.0);
}

// Very porous material on a stiff matrix: the snowplough, where the shocked material is the
// matrix at its reference density, so mass conservation alone gives D = u_p alpha_0 /
// (alpha_0 - 1), and a single shock from rest heats by exactly u_p^2 / 2. With P/K_s ~ 1e-3 the
// matrix compresses by 0.1%, which moves D by ~0.2% (the tolerance).
TEST(ExactPorousCompaction, HighPorosityIsTheSnowplough) {
  const Tillotson matrix = aluminium();
  PalphaParameters p;
  p.initialDistention = 2.0;
  p.elasticPressure = 0.0;
  p.solidPressure = 1e6;
  p.solidDensity = matrix.referenceDensity();
  p.solidSoundSpeed = matrix.soundSpeed(p.solidDensity, 0.0);
  p.porousSoundSpeed = p.solidSoundSpeed;
  const double up = 200.0;
  const exact::CompactionWave w = exact::compactionWave(matrix, PalphaModel(p), up);
  EXPECT_FALSE(w.twoWaves());
  EXPECT_NEAR(w.shockSpeed, up * 2.0, 0.002 * up * 2.0);
  EXPECT_NEAR(w.compacted.u, 0.5 * up * up, 1e-9 * up * up);
  EXPECT_NEAR(w.compacted.rho, 2700.0, 0.002 * 2700.0);
}

TEST(ExactPorousCompaction, TooSlowAPistonIsRefused) {
  const Tillotson matrix = aluminium();
  const PalphaModel model = jutziAluminium(matrix);
  EXPECT_THROW(exact::compactionWave(matrix, model, 1.0), std::domain_error);
  EXPECT_THROW(exact::compactionWave(matrix, model, 0.0), std::invalid_argument);
}

// epsilon-alpha (sim/solid/strain_porosity.hpp): the aluminium of the compaction_epsalpha_1d
// scene, which has every regime.
EpsilonAlphaModel strainAluminium(const EquationOfState& matrix, bool thermalStrain = true) {
  EpsilonAlphaParameters p = test::strainPorousAluminium();
  p.thermalStrain = thermalStrain;
  return EpsilonAlphaModel::onMatrix(p, matrix);
}

TEST(ExactPorousCompaction, EpsilonAlphaSplitsAtTheElasticStrain) {
  const Tillotson matrix = aluminium();
  const EpsilonAlphaModel model = strainAluminium(matrix);
  const exact::CompactionWave w = exact::compactionWave(matrix, model, 458.0);
  ASSERT_TRUE(w.twoWaves());
  // The precursor ends at the elastic strain with alpha_e, at ~ the porous sound speed
  // chi c_s0 (its strain is 2e-3: within 1%).
  EXPECT_NEAR(model.strainOf(w.elastic.rho, w.elastic.u), -2e-3, 1e-12);
  EXPECT_DOUBLE_EQ(w.elastic.alpha, model.elasticDistention());
  const double cs0 = matrix.soundSpeed(matrix.referenceDensity(), 0.0);
  EXPECT_NEAR(w.precursorSpeed, 0.78 * cs0, 0.01 * 0.78 * cs0);
  expectJump(w.initial, w.elastic, w.precursorSpeed);
  EXPECT_NEAR(w.elastic.alpha * w.elastic.P, matrix.pressure(w.elastic.alpha * w.elastic.rho, w.elastic.u),
              1e-9 * w.elastic.P);
  // The compaction shock ends on the loading curve at its own strain, in the power-law regime.
  expectJump(w.elastic, w.compacted, w.shockSpeed);
  const double eps = model.strainOf(w.compacted.rho, w.compacted.u);
  EXPECT_LT(eps, model.transitionStrain());
  EXPECT_GT(eps, model.compactionStrain());
  EXPECT_DOUBLE_EQ(w.compacted.alpha, model.loadingDistention(eps));
  EXPECT_NEAR(w.compacted.alpha * w.compacted.P,
              matrix.pressure(w.compacted.alpha * w.compacted.rho, w.compacted.u), 1e-9 * w.compacted.P);
  EXPECT_LT(w.shockSpeed, w.precursorSpeed);
  // Without the thermal strain the precursor's density is rho_0 exp(2e-3) exactly.
  const exact::CompactionWave cold = exact::compactionWave(matrix, strainAluminium(matrix, false), 458.0);
  EXPECT_NEAR(cold.elastic.rho, 2700.0 / 1.275 * std::exp(2e-3), 1e-9);
  // The thermal strain compacts more for the same state: alpha lower behind the shock.
  EXPECT_LT(w.compacted.alpha, cold.compacted.alpha);
}

TEST(ExactPorousCompaction, EpsilonAlphaOverdrivenIsOneShockToFullCompaction) {
  const Tillotson matrix = aluminium();
  const EpsilonAlphaModel model = strainAluminium(matrix);
  const exact::CompactionWave w = exact::compactionWave(matrix, model, 1500.0);
  EXPECT_FALSE(w.twoWaves());
  expectJump(w.initial, w.compacted, w.shockSpeed);
  EXPECT_DOUBLE_EQ(w.compacted.alpha, 1.0);
  EXPECT_LT(model.strainOf(w.compacted.rho, w.compacted.u), model.compactionStrain());
}

}  // namespace
}  // namespace ejecta

