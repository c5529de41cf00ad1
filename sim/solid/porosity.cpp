#include "sim/solid/porosity.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sim/eos/eos.hpp"
#include "sim/state/particles.hpp"

namespace ejecta {

namespace {

[[noreturn]] void fail(const std::string& what) { throw std::invalid_argument("porosity: " + what); }

// RK4 steps of the elastic law over [0, Pe]: its right side is smooth and the integral changes
// alpha by ~1e-3 (JBM08's aluminium), so 200 steps are exact to round-off.
constexpr int kElasticSteps = 200;

}  // namespace

PalphaModel::PalphaModel(const PalphaParameters& parameters) : par_(parameters) {
  const PalphaParameters& p = par_;
  if (!(p.initialDistention > 1.0) || !std::isfinite(p.initialDistention))
    fail("initial_distention must exceed 1 (porosity > 0): alpha_0 = 1 / (1 - porosity)");
  if (!(p.elasticPressure >= 0.0)) fail("elastic_pressure must not be negative");
  if (!(p.solidPressure > p.elasticPressure))
    fail("solid_pressure must exceed elastic_pressure (compaction runs from Pe to Ps)");
  if (!(p.crushExponent >= 1.0)) fail("crush_exponent must be at least 1");
  if (p.transitionPressure == 0.0) par_.transitionPressure = p.solidPressure;
  if (!(par_.transitionPressure > p.elasticPressure && par_.transitionPressure <= p.solidPressure))
    fail("transition_pressure must lie in (elastic_pressure, solid_pressure]");
  if (!(p.transitionExponent >= 1.0)) fail("transition_exponent must be at least 1");
  if (!(p.solidDensity > 0.0))
    fail("no matrix density: give solid_density, or a matrix eos with a reference density "
         "(tillotson, mie_gruneisen)");
  if (!(p.solidSoundSpeed > 0.0)) fail("the matrix sound speed must be positive");
  if (!(p.porousSoundSpeed > 0.0) || p.porousSoundSpeed > p.solidSoundSpeed)
    fail("porous_sound_speed must be positive and at most the matrix's sound speed (" +
         std::to_string(p.solidSoundSpeed) + " m/s)");
  bulkModulus_ = p.solidDensity * p.solidSoundSpeed * p.solidSoundSpeed;
  // alpha_e enters h, and h the integral giving alpha_e: a contraction (the integral moves alpha
  // by ~Pe/K_s), so a few iterations settle it.
  alphaE_ = p.initialDistention;
  for (int it = 0; it < 50; ++it) {
    const double next = elasticDistentionAtPe(alphaE_);
    const bool settled = std::abs(next - alphaE_) <= 1e-15 * alphaE_;
    alphaE_ = next;
    if (settled) break;
  }
  if (!(alphaE_ > 1.0))
    fail("the pores close elastically before elastic_pressure (alpha_e <= 1): lower "
         "elastic_pressure or raise porous_sound_speed");
  alphaT_ = p.transitionDistention < 0.0 ? alphaE_ : p.transitionDistention;
  if (!(alphaT_ >= 1.0 && alphaT_ <= alphaE_))
    fail("transition_distention must lie in [1, alpha_e = " + std::to_string(alphaE_) + "]");
}

double PalphaModel::elasticDistentionAtPe(double alphaE) const {
  const PalphaParameters& p = par_;
  const double cs = p.solidSoundSpeed, ce = p.porousSoundSpeed;
  auto slope = [&](double alpha) {
    const double h = 1.0 + (alpha - 1.0) * (ce - cs) / (cs * (alphaE - 1.0));
    return alpha * alpha / bulkModulus_ * (1.0 - 1.0 / (h * h));
  };
  double alpha = p.initialDistention;
  const double dP = p.elasticPressure / kElasticSteps;
  for (int s = 0; s < kElasticSteps; ++s) {
    const double k1 = slope(alpha), k2 = slope(alpha + 0.5 * dP * k1);
    const double k3 = slope(alpha + 0.5 * dP * k2), k4 = slope(alpha + dP * k3);
    alpha += dP / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  return alpha;
}

double PalphaModel::crushDistention(double P) const {
  const PalphaParameters& p = par_;
  if (P <= p.elasticPressure) return alphaE_;
  if (P >= p.solidPressure) return 1.0;
  const double x = (p.solidPressure - P) / (p.solidPressure - p.elasticPressure);
  double alpha = 1.0 + (alphaT_ - 1.0) * std::pow(x, p.crushExponent);
  if (P < p.transitionPressure && alphaE_ > alphaT_) {
    const double y = (p.transitionPressure - P) / (p.transitionPressure - p.elasticPressure);
    alpha += (alphaE_ - alphaT_) * std::pow(y, p.transitionExponent);
  }
  return alpha;
}

double PalphaModel::crushSlope(double P) const {
  const PalphaParameters& p = par_;
  if (P < p.elasticPressure || P >= p.solidPressure) return 0.0;
  const double span = p.solidPressure - p.elasticPressure;
  const double x = (p.solidPressure - P) / span;
  double slope = -p.crushExponent * (alphaT_ - 1.0) * std::pow(x, p.crushExponent - 1.0) / span;
  if (P < p.transitionPressure && alphaE_ > alphaT_) {
    const double spanT = p.transitionPressure - p.elasticPressure;
    const double y = (p.transitionPressure - P) / spanT;
    slope -= p.transitionExponent * (alphaE_ - alphaT_) * std::pow(y, p.transitionExponent - 1.0) / spanT;
  }
  return slope;
}

double PalphaModel::elasticSlope(double alpha) const {
  const PalphaParameters& p = par_;
  if (p.porousSoundSpeed == p.solidSoundSpeed || alpha <= 1.0) return 0.0;
  const double h = 1.0 + (alpha - 1.0) * (p.porousSoundSpeed - p.solidSoundSpeed) /
                             (p.solidSoundSpeed * (alphaE_ - 1.0));
  return alpha * alpha / bulkModulus_ * (1.0 - 1.0 / (h * h));
}

double PalphaModel::soundSpeed(double matrixSoundSpeed, double alpha) const {
  return porousSoundSpeed(matrixSoundSpeed, alpha, par_.initialDistention, par_.porousSoundSpeed);
}

double PalphaModel::distentionRate(double alpha, double P, double rho, double dPsdRhoS,
                                   double dPsdU, double rhoRate, double uRate) const {
  if (alpha <= 1.0) return 0.0;
  // alpha dP/dt (1 + ...) = this: the sign of the pressure's rate.
  const double drive = alpha * dPsdRhoS * rhoRate + dPsdU * uRate;
  const bool plastic = drive > 0.0 && P >= par_.elasticPressure &&
                       alpha >= crushDistention(P) * (1.0 - 1e-12);
  const double slope = std::min(0.0, plastic ? crushSlope(P) : elasticSlope(alpha));
  if (slope == 0.0) return 0.0;
  // The denominator is alpha plus a positive term for a stiff matrix (P << rho dPs/drho_s); it
  // could only vanish for a matrix softer than its own pressure, where the rate is unbounded.
  const double denominator = std::max(alpha + slope * (P - rho * dPsdRhoS), 1e-6 * alpha);
  return slope * drive / denominator;
}

double PalphaModel::returnToCrushCurve(double alpha, double rho, double u,
                                      const EquationOfState& matrix) const {
  // g(a) = a - alpha(P(a)) is positive above the curve and rises with a (a larger distention
  // compresses the matrix more, raising P and so lowering alpha(P), for any matrix stiffer than
  // its own pressure): one root in [1, alpha], found by the Illinois variant of regula falsi
  // (a few EOS calls).
  auto g = [&](double a) { return a - crushDistention(matrix.pressure(a * rho, u) / a); };
  double hi = alpha, gHi = g(hi);
  if (!(gHi > 0.0) || matrix.pressure(alpha * rho, u) / alpha < par_.elasticPressure) return alpha;
  double lo = 1.0, gLo = g(lo);
  if (gLo >= 0.0) return 1.0;  // compacted: the curve is at 1 for the state's pressure
  int side = 0;
  for (int it = 0; it < 60 && hi - lo > 1e-13 * hi; ++it) {
    const double a = (lo * gHi - hi * gLo) / (gHi - gLo);
    const double ga = g(a);
    if (ga > 0.0) {
      hi = a, gHi = ga;
      if (side == 1) gLo *= 0.5;
      side = 1;
    } else {
      lo = a, gLo = ga;
      if (side == -1) gHi *= 0.5;
      side = -1;
    }
    if (ga == 0.0) return a;
  }
  return lo;  // on or just below the curve: admissible
}

double porousSoundSpeed(double matrixSoundSpeed, double alpha, double initialDistention,
                        double initialSoundSpeed) {
  const double f = std::clamp((alpha - 1.0) / (initialDistention - 1.0), 0.0, 1.0);
  return matrixSoundSpeed + f * (initialSoundSpeed - matrixSoundSpeed);
}

const double* distentionColumn(const ParticleSet& p) {
  const Field* f = p.field(kDistentionField);
  return f ? p.column(*f, 0).data() : nullptr;
}

const double* compactionFactorColumn(const ParticleSet& p) {
  const Field* f = p.field(kCompactionFactorField);
  return f ? p.column(*f, 0).data() : nullptr;
}

}  // namespace ejecta
