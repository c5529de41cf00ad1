#pragma once
// The per-particle time-step criteria of the hydrodynamics, shared by global steps (the smallest
// over all particles) and individual steps (each particle's own).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "sim/sph/sph_options.hpp"

namespace ejecta {

// Seed eq. (1.8), with |div v| (the printed h div v can be negative) and the denominator floored
// at c so that alpha = 0 still respects the sound-crossing limit. Infinity when nothing limits.
// h |div v| stands for the speed at which the neighbours close in; `approach`, where given, is
// that speed measured pair by pair (closingSpeed below), and the larger of the two is used: at a
// one-sided contact (a lone particle reaching a body) the kernel sum dilutes div v while a
// neighbour closes at the full impact speed.
inline double courantTimestep(const SphOptions& sph, double h, double c, double divv,
                              double approach = 0.0) {
  const double closing = std::max(h * std::abs(divv), approach);
  const double denom = closing + std::max(1.2 * (sph.alpha * c + sph.beta * closing), c);
  return denom > 0.0 ? sph.courant * h / denom : std::numeric_limits<double>::infinity();
}

// The fastest closing speed of a pair: max over j of -(v_i - v_j) . (x_i - x_j) / |x_i - x_j|,
// 0 when no neighbour approaches (the approach part of Monaghan's (1997) signal velocity).
// `pairs`: i's partners; positions and velocities in the particle set's columns.
template <class Pairs, class Columns>
double closingSpeed(std::size_t i, const Pairs& pairs, const Columns& x, const Columns& v, int dim) {
  double fastest = 0.0;
  for (const auto j : pairs) {
    double r2 = 0.0, vdotx = 0.0;
    for (int d = 0; d < dim; ++d) {
      const double dx = x[d][i] - x[d][j];
      r2 += dx * dx;
      vdotx += (v[d][i] - v[d][j]) * dx;
    }
    if (vdotx < 0.0 && r2 > 0.0) fastest = std::max(fastest, -vdotx / std::sqrt(r2));
  }
  return fastest;
}

// Individual time steps with artificial conductivity: the step of a particle that its pairs heat
// at signal speed v_sig^u (Price 2008; the fastest of the pairs with u_j > u_i) is held to
// courant h / (kConductionSignalFactor alpha_u v_sig^u). With global steps every pair's exchange
// is summed by both sides over the same step and conserved; on time bins the two sides of a pair
// integrate it over steps of different lengths, and energy appears unless the particle that
// takes the heat, whose u it changes the most, steps at the conduction's own pace. Measured on
// the seed's RZ Sedov (docs/time_steps.md; global steps L1(rho) 0.237): factor 4 gives 0.242 and
// an energy error of 9e-4 at 0.15 of the global run's particle-steps. Limiting both sides of
// every pair instead gave 0.248 and 2.1e-3 for more particle-steps; the particle's own
// coupling, dt < 0.3 / sum_j kappa_ij (an explicit diffusion's stability is 1 / sum), never
// bound.
constexpr double kConductionSignalFactor = 4.0;  // docs/time_steps.md: 1, 2, 3, 4, 6 measured

inline double conductionTimestep(const SphOptions& sph, double h, double signal) {
  const double speed = kConductionSignalFactor * sph.conductivity * signal;
  return speed > 0.0 ? sph.courant * h / speed : std::numeric_limits<double>::infinity();
}

// The force criterion f sqrt(h / |a|) (Monaghan 1992), `a2` = |a|^2. Infinity for a = 0.
inline double forceTimestep(const SphOptions& sph, double h, double a2) {
  return a2 > 0.0 ? sph.forceFactor * std::sqrt(h / std::sqrt(a2))
                  : std::numeric_limits<double>::infinity();
}

}  // namespace ejecta
