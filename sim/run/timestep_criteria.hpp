#pragma once
// The per-particle time-step criteria of the hydrodynamics, shared by global steps (the smallest
// over all particles) and individual steps (each particle's own).
#include <algorithm>
#include <cmath>
#include <limits>

#include "sim/sph/sph_options.hpp"

namespace ejecta {

// Seed eq. (1.8), with |div v| (the printed h div v can be negative) and the denominator floored
// at c so that alpha = 0 still respects the sound-crossing limit. Infinity when nothing limits.
inline double courantTimestep(const SphOptions& sph, double h, double c, double divv) {
  const double div = std::abs(divv);
  const double denom = h * div + std::max(1.2 * (sph.alpha * c + sph.beta * h * div), c);
  return denom > 0.0 ? sph.courant * h / denom : std::numeric_limits<double>::infinity();
}

// The force criterion f sqrt(h / |a|) (Monaghan 1992), `a2` = |a|^2. Infinity for a = 0.
inline double forceTimestep(const SphOptions& sph, double h, double a2) {
  return a2 > 0.0 ? sph.forceFactor * std::sqrt(h / std::sqrt(a2))
                  : std::numeric_limits<double>::infinity();
}

}  // namespace ejecta
