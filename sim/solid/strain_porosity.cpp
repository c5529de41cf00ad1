#include "sim/solid/strain_porosity.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sim/eos/eos.hpp"

namespace ejecta {

namespace {

[[noreturn]] void fail(const std::string& what) {
  throw std::invalid_argument("porosity (epsilon_alpha): " + what);
}

}  // namespace

EpsilonAlphaModel::EpsilonAlphaModel(const EpsilonAlphaParameters& parameters) : par_(parameters) {
  const EpsilonAlphaParameters& p = par_;
  if (!(p.initialDistention > 1.0) || !std::isfinite(p.initialDistention))
    fail("initial_distention must exceed 1 (porosity > 0): alpha_0 = 1 / (1 - porosity)");
  if (!(p.elasticStrain <= 0.0) || !std::isfinite(p.elasticStrain))
    fail("the elastic strain eps_e must be zero or negative (compression)");
  // kappa >= 1 would close the pores faster than the bulk compresses: the matrix would expand,
  // and its pressure fall, under compression (alpha rho grows as exp((1 - kappa)|eps|)), and
  // the compaction shock would lose its unique state.
  if (!(p.kappa > 0.0 && p.kappa < 1.0)) fail("kappa must lie in (0, 1)");
  if (!(p.soundSpeedRatio > 0.0 && p.soundSpeedRatio <= 1.0))
    fail("sound_speed_ratio (chi = c_0 / c_s0) must lie in (0, 1]");
  if (!(p.solidDensity > 0.0))
    fail("no matrix density: give solid_density, or a matrix eos with a reference density "
         "(tillotson, mie_gruneisen)");
  if (!(p.solidSoundSpeed > 0.0)) fail("the matrix sound speed must be positive");
  if (!(p.solidGruneisen >= 0.0) || !std::isfinite(p.solidGruneisen))
    fail("the matrix's Grüneisen parameter must be finite and not negative");
  if (!(p.maxChangePerStep > 0.0)) fail("max_distention_change must be positive");
  k_ = (p.soundSpeedRatio - 1.0) / (p.initialDistention - 1.0);
  thermal_ = p.thermalStrain
                 ? p.solidGruneisen / (p.solidSoundSpeed * p.solidSoundSpeed)
                 : 0.0;
  alphaE_ = elasticDistention(p.initialDistention, p.elasticStrain);
  if (!(alphaE_ > 1.0))
    fail("the elastic law closes the pores (to round-off) before the elastic strain: lower its "
         "magnitude or raise sound_speed_ratio");
  if (!(p.transitionDistention >= 1.0 && p.transitionDistention <= alphaE_))
    fail("transition_distention (alpha_x) must lie in [1, alpha_e = " + std::to_string(alphaE_) +
         "]");
  // The same bound on the power law: its (dalpha/deps)/alpha = kappa alpha_x x/(1 + (alpha_x -
  // 1) x^2), x = (eps_c - eps)/(eps_c - eps_x) in [0, 1], peaks at kappa inside the segment
  // only for alpha_x <= 2; above, at kappa alpha_x / (2 sqrt(alpha_x - 1)).
  const double ax = p.transitionDistention;
  if (ax > 2.0 && !(p.kappa * ax < 2.0 * std::sqrt(ax - 1.0)))
    fail("kappa alpha_x / (2 sqrt(alpha_x - 1)) must be below 1 (alpha_x = " + std::to_string(ax) +
         "): the power law would close the pores faster than the bulk compresses");
  epsX_ = p.elasticStrain + std::log(p.transitionDistention / alphaE_) / p.kappa;
  epsC_ = epsX_ + 2.0 * (1.0 - p.transitionDistention) / (p.kappa * p.transitionDistention);
}

EpsilonAlphaModel EpsilonAlphaModel::onMatrix(EpsilonAlphaParameters p,
                                              const EquationOfState& matrix) {
  if (!(p.solidDensity > 0.0)) p.solidDensity = matrix.referenceDensity();
  if (p.solidDensity > 0.0) {
    p.solidSoundSpeed = matrix.soundSpeed(p.solidDensity, 0.0);
    p.solidGruneisen = matrix.pressureSlopes(p.solidDensity, 0.0).dU / p.solidDensity;
  }
  return EpsilonAlphaModel(p);
}

double EpsilonAlphaModel::soundSpeed(double matrixSoundSpeed, double alpha) const {
  return porousSoundSpeed(matrixSoundSpeed, alpha, par_.initialDistention,
                          par_.soundSpeedRatio * par_.solidSoundSpeed);
}

double EpsilonAlphaModel::strainOf(double rho, double u) const {
  const double rho0 = par_.solidDensity / par_.initialDistention;
  return std::log(rho0 / rho) - thermal_ * u;
}

double EpsilonAlphaModel::elasticSlope(double alpha) const {
  const double r = 1.0 + k_ * (alpha - 1.0);  // c(alpha) / c_s0
  return alpha * (1.0 - r * r);
}

// 1/(alpha (1 - r^2)) = -1/(k alpha (alpha - 1)(2 + k (alpha - 1))), in partial fractions:
// F = -(1/k) [-ln(alpha)/(2 - k) + ln(alpha - 1)/2 + k ln(2 + k (alpha - 1))/(2 (2 - k))].
double EpsilonAlphaModel::elasticIntegral(double alpha) const {
  const double k = k_;
  return -(-std::log(alpha) / (2.0 - k) + 0.5 * std::log(alpha - 1.0) +
           k * std::log(2.0 + k * (alpha - 1.0)) / (2.0 * (2.0 - k))) /
         k;
}

double EpsilonAlphaModel::elasticDistention(double alpha, double dEps) const {
  const double alpha0 = par_.initialDistention;
  if (k_ == 0.0 || alpha <= 1.0 || dEps == 0.0) return std::clamp(alpha, 1.0, alpha0);
  // F rises with alpha from -infinity at 1: Newton's method on F(a) = F(alpha) + dEps,
  // bracketed in (1, alpha_0], from the first-order guess (a few iterations).
  const double target = elasticIntegral(alpha) + dEps;
  if (target >= elasticIntegral(alpha0)) return alpha0;
  double lo = 1.0, hi = alpha0;
  double a = std::clamp(alpha + elasticSlope(alpha) * dEps, 1.0, alpha0);
  for (int it = 0; it < 100; ++it) {
    if (!(a > lo && a < hi)) a = 0.5 * (lo + hi);
    const double f = elasticIntegral(a) - target;
    (f > 0.0 ? hi : lo) = a;
    const double next = a - f * elasticSlope(a);
    if (std::abs(next - a) <= 1e-15 * a || hi - lo <= 1e-15 * hi) return std::clamp(next, lo, hi);
    a = next;
  }
  return a;
}

double EpsilonAlphaModel::loadingDistention(double eps) const {
  const EpsilonAlphaParameters& p = par_;
  if (eps >= p.elasticStrain) return elasticDistention(p.initialDistention, eps);
  if (eps >= epsX_) return alphaE_ * std::exp(p.kappa * (eps - p.elasticStrain));
  if (eps >= epsC_) {
    const double x = (epsC_ - eps) / (epsC_ - epsX_);
    return 1.0 + (p.transitionDistention - 1.0) * x * x;
  }
  return 1.0;
}

double EpsilonAlphaModel::loadingSlope(double eps) const {
  const EpsilonAlphaParameters& p = par_;
  if (eps >= p.elasticStrain) return elasticSlope(loadingDistention(eps));
  if (eps >= epsX_) return p.kappa * loadingDistention(eps);
  if (eps >= epsC_) {
    const double span = epsC_ - epsX_;
    return 2.0 * (p.transitionDistention - 1.0) * (eps - epsC_) / (span * span);
  }
  return 0.0;
}

double EpsilonAlphaModel::distention(double eps, double epsMin) const {
  const double reached = std::min(eps, epsMin);
  // Within the elastic range the law is reversible: the loading curve is the state.
  if (reached >= par_.elasticStrain || eps == reached) return loadingDistention(eps);
  return elasticDistention(loadingDistention(reached), eps - reached);
}

double EpsilonAlphaModel::signedDistentionRate(double eps, double epsMin, double epsRate) const {
  const bool loading = epsRate < 0.0 && eps <= epsMin;
  return (loading ? loadingSlope(eps) : elasticSlope(distention(eps, epsMin))) * epsRate;
}

double EpsilonAlphaModel::distentionRate(double eps, double epsMin, double epsRate) const {
  const bool loading = epsRate < 0.0 && eps <= epsMin;
  if (!loading) return std::abs(elasticSlope(distention(eps, epsMin)) * epsRate);
  // Loading in the elastic range the next step may cross eps_e, where the slope jumps to
  // kappa alpha_e: the vote takes the larger (the elastic range is ~1e-3 of strain, so this costs
  // nothing there).
  double slope = loadingSlope(eps);
  if (eps >= par_.elasticStrain) slope = std::max(slope, par_.kappa * alphaE_);
  return std::abs(slope * epsRate);
}

}  // namespace ejecta
