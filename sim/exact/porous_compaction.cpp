#include "sim/exact/porous_compaction.hpp"

#include <cmath>
#include <functional>
#include <stdexcept>

namespace ejecta::exact {

namespace {

// The root of f on [lo, hi] where f(lo) > 0 > f(hi), to round-off.
double bisect(const std::function<double(double)>& f, double lo, double hi) {
  for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; ++it) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) > 0.0 ? lo : hi) = mid;
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

Jump jumpToVelocity(const EquationOfState& matrix, const PalphaModel& model, const PorousState& a,
                    double v) {
  const double w = v - a.v;
  auto state = [&](double rho) {
    Jump j;
    const double relative = rho * w / (rho - a.rho);  // D - v_a
    const double P = a.P + a.rho * relative * w;
    j.speed = a.v + relative;
    j.behind = {rho, a.u + 0.5 * (a.P + P) * (1.0 / a.rho - 1.0 / rho), P, v,
                model.crushDistention(P)};
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

}  // namespace

CompactionWave compactionWave(const EquationOfState& matrix, const PalphaModel& model,
                              double pistonSpeed) {
  if (!(pistonSpeed > 0.0)) throw std::invalid_argument("compactionWave: piston speed must be positive");
  const PalphaParameters& par = model.parameters();
  CompactionWave wave;
  wave.initial = {par.solidDensity / par.initialDistention, 0.0, 0.0, 0.0, par.initialDistention};
  wave.elastic = wave.initial;
  if (par.elasticPressure > 0.0) {
    const Jump precursor =
        jumpToPressure(matrix, wave.initial, par.elasticPressure, model.elasticDistention());
    if (pistonSpeed <= precursor.behind.v)
      throw std::domain_error("compactionWave: the piston is too slow to compact (the elastic "
                              "precursor alone carries it)");
    wave.elastic = precursor.behind;
    wave.precursorSpeed = precursor.speed;
  }
  Jump shock = jumpToVelocity(matrix, model, wave.elastic, pistonSpeed);
  if (wave.twoWaves() && shock.speed >= wave.precursorSpeed) {
    // Overdriven: the compaction shock outruns the precursor; one shock from rest.
    wave.elastic = wave.initial;
    wave.precursorSpeed = 0.0;
    shock = jumpToVelocity(matrix, model, wave.initial, pistonSpeed);
  }
  wave.compacted = shock.behind;
  wave.shockSpeed = shock.speed;
  return wave;
}

}  // namespace ejecta::exact
