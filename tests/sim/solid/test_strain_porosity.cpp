// The epsilon-alpha model (sim/solid/strain_porosity.hpp): its loading curve's regimes and
// their joins, the elastic law against an independent integration and against the porous
// sound speed it is built to give, the history (unloading, reloading) and its refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "sim/eos/tillotson.hpp"
#include "sim/solid/strain_porosity.hpp"
#include "support/strain_porosity_sets.hpp"

namespace ejecta {
namespace {

// The shared sets (tests/support/strain_porosity_sets.hpp) on a library matrix: iSALE's sand on
// granite, the every-regime aluminium on aluminium.
EpsilonAlphaModel onLibrary(const EpsilonAlphaParameters& p, const char* material) {
  return EpsilonAlphaModel::onMatrix(p, Tillotson(tillotsonLibrary(material)));
}

TEST(EpsilonAlphaModel, LoadingCurveOfTheSandFromItsPublishedParameters) {
  const EpsilonAlphaModel m = onLibrary(test::isaleSand(), "granite");
  // No elastic range: the exponential starts at once from alpha_0.
  EXPECT_DOUBLE_EQ(m.elasticDistention(), 1.80);
  // eps_x = ln(alpha_x / alpha_0) / kappa, eps_c = eps_x + 2 (1 - alpha_x)/(kappa alpha_x), by
  // hand: ln(1.29/1.8) = -0.333144, / 0.988 = -0.337191; 2 (-0.29)/(0.988 x 1.29) = -0.455073.
  EXPECT_NEAR(m.transitionStrain(), -0.337191, 1e-6);
  EXPECT_NEAR(m.compactionStrain(), -0.792264, 1e-6);
  EXPECT_DOUBLE_EQ(m.loadingDistention(0.0), 1.80);
  EXPECT_NEAR(m.loadingDistention(-0.1), 1.80 * std::exp(-0.0988), 1e-14);
  EXPECT_NEAR(m.loadingDistention(m.transitionStrain()), 1.29, 1e-12);
  EXPECT_DOUBLE_EQ(m.loadingDistention(m.compactionStrain()), 1.0);
  EXPECT_DOUBLE_EQ(m.loadingDistention(-1.0), 1.0);
  // Halfway down the power law: 1 + 0.29 / 4.
  EXPECT_NEAR(m.loadingDistention(0.5 * (m.transitionStrain() + m.compactionStrain())),
              1.0 + 0.29 / 4.0, 1e-12);
}

TEST(EpsilonAlphaModel, RegimesJoinWithContinuousValueAndSlope) {
  const EpsilonAlphaModel m = onLibrary(test::strainPorousAluminium(), "aluminium");
  const double eE = -2e-3, eX = m.transitionStrain(), eC = m.compactionStrain();
  ASSERT_LT(eC, eX);
  ASSERT_LT(eX, eE);
  const double d = 1e-9;
  for (double e : {eE, eX}) {
    EXPECT_NEAR(m.loadingDistention(e - d), m.loadingDistention(e + d), 1e-8) << e;
  }
  // The slope is continuous at eps_x (eps_c is chosen so) and vanishes at eps_c; at eps_e it
  // jumps from the elastic law's to kappa alpha_e (the pores start to crush).
  EXPECT_NEAR(m.loadingSlope(eX - d), m.loadingSlope(eX + d), 1e-6 * m.loadingSlope(eX));
  EXPECT_NEAR(m.loadingSlope(eC + d), 0.0, 1e-6);
  EXPECT_NEAR(m.loadingSlope(eE - d), 0.98 * m.elasticDistention(), 1e-6);
  // The slopes are the derivatives of the curve (central differences, 1e-6 of the slope).
  for (double e : {0.5 * eE, 0.5 * (eE + eX), 0.5 * (eX + eC)}) {
    const double h = 1e-6;
    const double numeric = (m.loadingDistention(e + h) - m.loadingDistention(e - h)) / (2.0 * h);
    EXPECT_NEAR(m.loadingSlope(e), numeric, 1e-6 * numeric) << e;
  }
}

// The elastic law dalpha/deps = alpha (1 - r^2), r = 1 + k (alpha - 1), integrated by RK4 with
// 1e5 steps (error ~h^4, far below the tolerance) against the closed form's inverse.
double integrateElasticLaw(double alpha0, double chi, double alpha, double dEps) {
  const double k = (chi - 1.0) / (alpha0 - 1.0);
  auto f = [&](double a) {
    const double r = 1.0 + k * (a - 1.0);
    return a * (1.0 - r * r);
  };
  const int n = 100000;
  const double h = dEps / n;
  for (int s = 0; s < n; ++s) {
    const double k1 = f(alpha), k2 = f(alpha + 0.5 * h * k1), k3 = f(alpha + 0.5 * h * k2);
    const double k4 = f(alpha + h * k3);
    alpha += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  return alpha;
}

TEST(EpsilonAlphaModel, ElasticLawIsItsClosedFormInverted) {
  const EpsilonAlphaModel m = onLibrary(test::strainPorousAluminium(), "aluminium");
  for (double dEps : {-2e-3, -0.05, -0.3}) {
    const double expected = integrateElasticLaw(1.275, 0.78, 1.275, dEps);
    EXPECT_NEAR(m.elasticDistention(1.275, dEps), expected, 1e-12) << dEps;
  }
  // Reversible, and composable in strain.
  const double a = m.elasticDistention(1.2, -0.04);
  EXPECT_NEAR(m.elasticDistention(a, 0.04), 1.2, 1e-13);
  EXPECT_NEAR(m.elasticDistention(m.elasticDistention(1.2, -0.01), -0.03), a, 1e-13);
  // alpha_e is the law carried from alpha_0 to eps_e; the pores never reopen past alpha_0.
  EXPECT_NEAR(m.elasticDistention(), integrateElasticLaw(1.275, 0.78, 1.275, -2e-3), 1e-13);
  EXPECT_DOUBLE_EQ(m.elasticDistention(1.2, 1.0), 1.275);
  EXPECT_DOUBLE_EQ(m.elasticDistention(1.0, 0.5), 1.0);  // compacted material has no pores
}

// The closed form where it could lose digits: chi next to 1 (k -> 0 divides the bracket), a
// distention next to 1 (ln(alpha - 1) -> -infinity), a very porous, very soft set.
TEST(EpsilonAlphaModel, ElasticLawHoldsAtItsEdges) {
  auto model = [](double alpha0, double chi) {
    EpsilonAlphaParameters p = test::strainPorousAluminium();
    p.initialDistention = alpha0;
    p.soundSpeedRatio = chi;
    p.transitionDistention = 1.0;
    return onLibrary(p, "aluminium");
  };
  const EpsilonAlphaModel nearlyRigid = model(1.275, 0.999999);
  EXPECT_NEAR(nearlyRigid.elasticDistention(1.2, -0.3), integrateElasticLaw(1.275, 0.999999, 1.2, -0.3),
              1e-11);
  const EpsilonAlphaModel al = model(1.275, 0.78);
  EXPECT_NEAR(al.elasticDistention(1.0 + 1e-6, -0.2), integrateElasticLaw(1.275, 0.78, 1.0 + 1e-6, -0.2),
              1e-12);
  EXPECT_NEAR(al.elasticDistention(1.0 + 1e-6, 0.2), integrateElasticLaw(1.275, 0.78, 1.0 + 1e-6, 0.2),
              1e-12);
  const EpsilonAlphaModel soft = model(3.0, 0.1);
  EXPECT_NEAR(soft.elasticDistention(2.5, -0.4), integrateElasticLaw(3.0, 0.1, 2.5, -0.4), 1e-11);
}

// alpha_x = 1: the exponential runs to full compaction at eps_x = eps_c (no power law);
// alpha_x = alpha_e: the power law starts at eps_e (no exponential).
TEST(EpsilonAlphaModel, DegenerateRegimesJoinContinuously) {
  EpsilonAlphaParameters p = test::strainPorousAluminium();
  p.transitionDistention = 1.0;
  const EpsilonAlphaModel exponentialOnly = onLibrary(p, "aluminium");
  EXPECT_DOUBLE_EQ(exponentialOnly.transitionStrain(), exponentialOnly.compactionStrain());
  EXPECT_NEAR(exponentialOnly.loadingDistention(exponentialOnly.transitionStrain() + 1e-12), 1.0, 1e-10);
  EXPECT_DOUBLE_EQ(exponentialOnly.loadingDistention(exponentialOnly.transitionStrain() - 1e-12), 1.0);
  p.transitionDistention = onLibrary(test::strainPorousAluminium(), "aluminium").elasticDistention();
  const EpsilonAlphaModel powerOnly = onLibrary(p, "aluminium");
  EXPECT_NEAR(powerOnly.transitionStrain(), -2e-3, 1e-15);
  const double d = 1e-9;
  EXPECT_NEAR(powerOnly.loadingDistention(-2e-3 - d), powerOnly.loadingDistention(-2e-3 + d), 1e-8);
  EXPECT_NEAR(powerOnly.loadingSlope(-2e-3 - d), 0.98 * powerOnly.elasticDistention(), 1e-6);
}

TEST(EpsilonAlphaModel, ElasticPoresCarrySoundAtTheGivenRatioOfTheMatrixs) {
  // The law's purpose: material at rest compressed in its elastic range has
  // dP/drho = c(alpha)^2 = (r c_s0)^2, with P = P_s(alpha rho, 0)/alpha (r = chi at alpha_0).
  // Without the thermal strain (u = 0 here anyway), eps = ln(rho_0 / rho). Central differences
  // about eps = -1e-4, inside the elastic range (above eps = 0 the pores stay at alpha_0, rigid):
  // the pressure there (~1e-4 of the bulk modulus) adds ~1e-4 of c^2, hence 1e-3 of c.
  EpsilonAlphaParameters p = test::strainPorousAluminium();
  p.thermalStrain = false;
  const Tillotson matrix(tillotsonLibrary("aluminium"));
  const EpsilonAlphaModel m = EpsilonAlphaModel::onMatrix(p, matrix);
  const double rho0 = matrix.referenceDensity();
  const double bulk0 = rho0 / 1.275;
  auto pressure = [&](double rho) {
    const double alpha = m.loadingDistention(std::log(bulk0 / rho));
    return matrix.pressure(alpha * rho, 0.0) / alpha;
  };
  const double rho = bulk0 * std::exp(1e-4), d = 1e-6 * bulk0;
  const double c2 = (pressure(rho + d) - pressure(rho - d)) / (2.0 * d);
  const double cs0 = matrix.soundSpeed(rho0, 0.0);
  const double alpha = m.loadingDistention(-1e-4);
  const double r = 1.0 + (0.78 - 1.0) * (alpha - 1.0) / 0.275;
  EXPECT_NEAR(std::sqrt(c2), r * cs0, 1e-3 * cs0);
  // The porous sound speed the runs use (viscosity, time step) is that c at the state's alpha.
  EXPECT_NEAR(m.soundSpeed(cs0, alpha), r * cs0, 1e-9 * cs0);
  // Rigid pores (chi = 1) carry the matrix's own sound speed.
  p.soundSpeedRatio = 1.0;
  const EpsilonAlphaModel rigid = EpsilonAlphaModel::onMatrix(p, matrix);
  EXPECT_DOUBLE_EQ(rigid.loadingDistention(-1e-3), 1.275);
}

TEST(EpsilonAlphaModel, CompactionIsIrreversibleAndUnloadingElastic) {
  const EpsilonAlphaModel m = onLibrary(test::strainPorousAluminium(), "aluminium");
  const double least = -0.1;  // in the exponential regime
  const double onCurve = m.loadingDistention(least);
  EXPECT_DOUBLE_EQ(m.distention(least, least), onCurve);
  // Unloaded, the pores reopen by the elastic law only, far less than the curve would give.
  const double unloaded = m.distention(-0.09, least);
  EXPECT_NEAR(unloaded, m.elasticDistention(onCurve, 0.01), 1e-15);
  EXPECT_GT(unloaded, onCurve);
  EXPECT_LT(unloaded - onCurve, 0.3 * (m.loadingDistention(-0.09) - onCurve));
  // Reloaded past the strain reached, the curve goes on.
  EXPECT_DOUBLE_EQ(m.distention(-0.12, least), m.loadingDistention(-0.12));
  // Within the elastic range nothing is irreversible: the state unloaded from -1.5e-3 is the law
  // carried back from there.
  EXPECT_NEAR(m.distention(-1e-3, -1.5e-3), m.elasticDistention(m.loadingDistention(-1.5e-3), 5e-4),
              1e-14);
  // Fully compacted material stays so.
  EXPECT_DOUBLE_EQ(m.distention(0.0, 2.0 * m.compactionStrain()), 1.0);
  // The step vote: the curve's slope while loading past the history, the elastic law's else.
  EXPECT_NEAR(m.distentionRate(least, least, -100.0), 100.0 * m.loadingSlope(least), 1e-12);
  EXPECT_NEAR(m.distentionRate(-0.09, least, -100.0), 100.0 * m.elasticSlope(unloaded), 1e-12);
  // Loading in the elastic range the vote already takes the exponential's kappa alpha_e (2.5x
  // the elastic slope here): the step may cross eps_e.
  EXPECT_NEAR(m.distentionRate(-1e-3, -1e-3, -100.0), 100.0 * 0.98 * m.elasticDistention(), 1e-12);
  EXPECT_GT(0.98 * m.elasticDistention(), 2.0 * m.loadingSlope(-1e-3));
}

TEST(EpsilonAlphaModel, ThermalStrainIsTheMatrixsGruneisenOverItsSoundSpeedSquared) {
  // Tillotson at its reference state: dP/du = (a + b) rho_0, so Gamma_0 = a + b, and
  // c_s0^2 = A / rho_0 (the library's aluminium: a = 0.5, b = 1.63, A = 75.2 GPa, 2700 kg/m^3).
  const EpsilonAlphaModel m = onLibrary(test::strainPorousAluminium(), "aluminium");
  const TillotsonParameters& t = tillotsonLibrary("aluminium");
  EXPECT_NEAR(m.thermalStrainCoefficient(), (t.a + t.b) / (t.A / t.rho0), 1e-6 * m.thermalStrainCoefficient());
  EXPECT_NEAR(m.strainOf(2700.0 / 1.275, 1e5), -1e5 * m.thermalStrainCoefficient(), 1e-15);
  EpsilonAlphaParameters p = test::strainPorousAluminium();
  p.thermalStrain = false;
  EXPECT_EQ(onLibrary(p, "aluminium").thermalStrainCoefficient(), 0.0);
  EXPECT_DOUBLE_EQ(onLibrary(p, "aluminium").strainRate(-2.0, 1e6), -2.0);
}

TEST(EpsilonAlphaModel, RefusesParametersItCannotFollow) {
  auto refused = [](EpsilonAlphaParameters p) {
    EXPECT_THROW(onLibrary(p, "aluminium"), std::invalid_argument);
  };
  EpsilonAlphaParameters p = test::strainPorousAluminium();
  p.kappa = 1.0;  // the matrix would expand under compression
  refused(p);
  p = test::strainPorousAluminium();
  p.soundSpeedRatio = 1.2;
  refused(p);
  p = test::strainPorousAluminium();
  p.transitionDistention = 1.3;  // above alpha_e
  refused(p);
  // A power law from alpha_x = 3 at kappa = 0.98 would close the pores faster than the bulk
  // compresses (its (dalpha/deps)/alpha peaks at 0.98 x 3 / (2 sqrt 2) = 1.04); at 0.9, 0.95.
  p = test::strainPorousAluminium();
  p.initialDistention = 3.5;
  p.transitionDistention = 3.0;
  refused(p);
  p.kappa = 0.9;
  EXPECT_NO_THROW(onLibrary(p, "aluminium"));
  p = test::strainPorousAluminium();
  p.elasticStrain = 1e-3;
  refused(p);
  p = test::strainPorousAluminium();
  p.initialDistention = 1.0;
  refused(p);
}

}  // namespace
}  // namespace ejecta
