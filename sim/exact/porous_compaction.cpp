#include "sim/exact/porous_compaction.hpp"

#include <cmath>
#include <functional>
#include <stdexcept>

namespace ejecta::exact {

namespace {

// The root of f on [lo, hi] where f(lo) > 0 > f(hi), to round-off (200 halvings always get
// there from a finite bracket; a residual that is not a number is refused).
double bisect(const std::function<double(double)>& f, double lo, double hi) {
  for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; ++it) {
    const double mid = 0.5 * (lo + hi);
    const double value = f(mid);
    if (std::isnan(value)) throw std::domain_error("compactionWave: the jump's residual is not a number");
    (value > 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// The state behind a jump from `ahead` whose distention is alpha(P) of the state behind it,
// with either the pressure behind it given (the precursor: P_b = Pe) or its velocity (the
// compaction shock: v_b = u_p). Returns the state and the front's speed.
struct Jump {
  PorousState behind;
  double speed = 0.0;
};

Jump jumpToPressure(const EquationOfState& matrix, const PorousState& a, double P, double alpha) {
  // P - P_a = rho_a (D - v_a)^2 (1 - rho_a / rho_b): D and v_b from rho_b.
  auto state = [&](double rho) {
    Jump j;
    const double x = 1.0 - a.rho / rho;
    const double relative = std::sqrt((P - a.P) / (a.rho * x));  // D - v_a
    j.speed = a.v + relative;
    j.behind = {rho, a.u + 0.5 * (a.P + P) * (1.0 / a.rho - 1.0 / rho), P, a.v + relative * x, alpha};
    return j;
  };
  auto residual = [&](double rho) {
    const Jump j = state(rho);
    return alpha * P - matrix.pressure(alpha * rho, j.behind.u);
  };
  double hi = a.rho * 1.01;
  while (residual(hi) > 0.0) hi = a.rho + 2.0 * (hi - a.rho);
  return state(bisect(residual, a.rho * (1.0 + 1e-14), hi));
}

// The distention behind a compaction shock, from the state behind it (alpha not yet set).
using Closure = std::function<double(const PorousState&)>;

Jump jumpToVelocity(const EquationOfState& matrix, const Closure& alphaBehind, const PorousState& a,
                    double v) {
  const double w = v - a.v;
  auto state = [&](double rho) {
    Jump j;
    const double relative = rho * w / (rho - a.rho);  // D - v_a
    const double P = a.P + a.rho * relative * w;
    j.speed = a.v + relative;
    j.behind = {rho, a.u + 0.5 * (a.P + P) * (1.0 / a.rho - 1.0 / rho), P, v, 1.0};
    j.behind.alpha = alphaBehind(j.behind);
    return j;
  };
  auto residual = [&](double rho) {
    const Jump j = state(rho);
    return j.behind.alpha * j.behind.P - matrix.pressure(j.behind.alpha * rho, j.behind.u);
  };
  double lo = a.rho * (1.0 + 1e-12);
  while (!(residual(lo) > 0.0)) lo = a.rho + 0.5 * (lo - a.rho);  // P_b grows without bound
  double hi = a.rho * 1.1;
  while (residual(hi) > 0.0) hi = a.rho + 2.0 * (hi - a.rho);
  return state(bisect(residual, lo, hi));
}

// The epsilon-alpha precursor: the jump whose end state has the strain eps_e (alpha = alpha_e).
// Its energy jump, u_b = u_a + (P_a + P_b)(1/rho_a - 1/rho_b)/2 with P_b = P_s(alpha_e rho_b,
// u_b)/alpha_e, is a contraction in u_b (the pressure's energy slope times the strain, ~1e-3), so
// each density's state is found by fixed point; the strain then falls with the density.
Jump jumpToStrain(const EquationOfState& matrix, const EpsilonAlphaModel& model, const PorousState& a) {
  const double alpha = model.elasticDistention();
  const double strain = model.parameters().elasticStrain;
  auto behind = [&](double rho) {
    PorousState b{rho, a.u, a.P, 0.0, alpha};
    for (int it = 0;; ++it) {
      if (it == 100) throw std::domain_error("compactionWave: the precursor's energy did not settle");
      b.P = matrix.pressure(alpha * rho, b.u) / alpha;
      const double u = a.u + 0.5 * (a.P + b.P) * (1.0 / a.rho - 1.0 / rho);
      const bool settled = std::abs(u - b.u) <= 1e-15 * std::abs(u) + 1e-300;
      b.u = u;
      if (settled) break;
    }
    b.P = matrix.pressure(alpha * rho, b.u) / alpha;
    return b;
  };
  auto residual = [&](double rho) {
    const PorousState b = behind(rho);
    return model.strainOf(rho, b.u) - strain;
  };
  double hi = a.rho * 1.01;
  while (residual(hi) > 0.0) hi = a.rho + 2.0 * (hi - a.rho);
  Jump j;
  j.behind = behind(bisect(residual, a.rho * (1.0 + 1e-14), hi));
  const double x = 1.0 - a.rho / j.behind.rho;
  const double relative = std::sqrt((j.behind.P - a.P) / (a.rho * x));  // D - v_a
  j.speed = a.v + relative;
  j.behind.v = a.v + relative * x;
  return j;
}

// The compaction shock to the piston's velocity behind an optional precursor; a shock faster
// than the precursor overruns it (one shock from rest).
CompactionWave assemble(const EquationOfState& matrix, const PorousState& initial,
                        const Jump* precursor, const Closure& alphaBehind, double pistonSpeed) {
  CompactionWave wave;
  wave.initial = initial;
  wave.elastic = initial;
  if (precursor) {
    if (pistonSpeed <= precursor->behind.v)
      throw std::domain_error("compactionWave: the piston is too slow to compact (the elastic "
                              "precursor alone carries it)");
    wave.elastic = precursor->behind;
    wave.precursorSpeed = precursor->speed;
  }
  Jump shock = jumpToVelocity(matrix, alphaBehind, wave.elastic, pistonSpeed);
  if (wave.twoWaves() && shock.speed >= wave.precursorSpeed) {
    wave.elastic = wave.initial;
    wave.precursorSpeed = 0.0;
    shock = jumpToVelocity(matrix, alphaBehind, wave.initial, pistonSpeed);
  }
  wave.compacted = shock.behind;
  wave.shockSpeed = shock.speed;
  return wave;
}

// Porous material at rest at zero pressure: its matrix at its reference density.
PorousState atRest(double solidDensity, double initialDistention) {
  return {solidDensity / initialDistention, 0.0, 0.0, 0.0, initialDistention};
}

void checkPiston(double pistonSpeed) {
  if (!(pistonSpeed > 0.0)) throw std::invalid_argument("compactionWave: piston speed must be positive");
}

}  // namespace

CompactionWave compactionWave(const EquationOfState& matrix, const PalphaModel& model,
                              double pistonSpeed) {
  checkPiston(pistonSpeed);
  const PalphaParameters& par = model.parameters();
  const PorousState initial = atRest(par.solidDensity, par.initialDistention);
  const auto alphaBehind = [&](const PorousState& b) { return model.crushDistention(b.P); };
  if (!(par.elasticPressure > 0.0))
    return assemble(matrix, initial, nullptr, alphaBehind, pistonSpeed);
  const Jump precursor =
      jumpToPressure(matrix, initial, par.elasticPressure, model.elasticDistention());
  return assemble(matrix, initial, &precursor, alphaBehind, pistonSpeed);
}

CompactionWave compactionWave(const EquationOfState& matrix, const EpsilonAlphaModel& model,
                              double pistonSpeed) {
  checkPiston(pistonSpeed);
  const EpsilonAlphaParameters& par = model.parameters();
  const PorousState initial = atRest(par.solidDensity, par.initialDistention);
  // A first compression: alpha is the loading curve's at the state's strain.
  const auto alphaBehind = [&](const PorousState& b) {
    return model.loadingDistention(model.strainOf(b.rho, b.u));
  };
  if (!(par.elasticStrain < 0.0)) return assemble(matrix, initial, nullptr, alphaBehind, pistonSpeed);
  const Jump precursor = jumpToStrain(matrix, model, initial);
  return assemble(matrix, initial, &precursor, alphaBehind, pistonSpeed);
}

}  // namespace ejecta::exact
