#include "sim/verify/grid_convergence.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace ejecta::verify {

GridConvergence gridConvergence(std::vector<double> spacings, std::vector<double> values) {
  if (spacings.size() != values.size())
    throw std::invalid_argument("grid convergence: as many spacings as values are needed");
  if (spacings.size() < 3)
    throw std::invalid_argument("grid convergence: at least three resolutions are needed for an order");
  std::vector<std::size_t> order(spacings.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return spacings[a] < spacings[b]; });
  for (std::size_t k = 0; k < order.size(); ++k) {
    if (!(spacings[order[k]] > 0.0) || !std::isfinite(spacings[order[k]]))
      throw std::invalid_argument("grid convergence: spacings must be positive");
    if (k > 0 && spacings[order[k]] == spacings[order[k - 1]])
      throw std::invalid_argument("grid convergence: two resolutions share a spacing");
  }
  const double h1 = spacings[order[0]], h2 = spacings[order[1]], h3 = spacings[order[2]];
  const double f1 = values[order[0]], f2 = values[order[1]], f3 = values[order[2]];
  GridConvergence g;
  const double e21 = f2 - f1, e32 = f3 - f2;
  const double r21 = h2 / h1, r32 = h3 / h2;
  g.relativeChange = f1 != 0.0 ? std::abs(e21 / f1) : std::abs(e21);
  if (e21 == 0.0) {
    g.note = "the two finest values are equal: no order (converged to the output's precision, or insensitive)";
    return g;
  }
  if (e32 == 0.0) {
    g.note = "the two coarsest values are equal: no order";
    return g;
  }
  const double s = e32 / e21 > 0.0 ? 1.0 : -1.0;
  g.oscillatory = s < 0.0;
  // Fixed point for p (Celik et al. 2008, eqs. 3a-3c), from q = 0.
  double p = std::abs(std::log(std::abs(e32 / e21))) / std::log(r21);
  bool settled = false;
  for (int it = 0; it < 200; ++it) {
    const double a = std::pow(r21, p) - s, b = std::pow(r32, p) - s;
    if (!(a > 0.0) || !(b > 0.0)) break;
    const double next = std::abs(std::log(std::abs(e32 / e21)) + std::log(a / b)) / std::log(r21);
    if (std::abs(next - p) <= 1e-12 * std::max(1.0, p)) {
      p = next;
      settled = true;
      break;
    }
    p = next;
  }
  if (!settled || !std::isfinite(p) || p <= 0.0) {
    g.note = "the observed order does not settle (the three values do not follow a power of h)";
    return g;
  }
  g.valid = true;
  g.order = p;
  const double rp = std::pow(r21, p);
  g.extrapolated = (rp * f1 - f2) / (rp - 1.0);
  g.extrapolatedError = g.extrapolated != 0.0 ? std::abs((g.extrapolated - f1) / g.extrapolated) : 0.0;
  g.gci = 1.25 * g.relativeChange / (rp - 1.0);
  g.uncertainty = g.gci * (f1 != 0.0 ? std::abs(f1) : 1.0);
  if (g.oscillatory) g.note = "oscillatory convergence (the changes alternate in sign)";
  else if (p > 4.0) g.note = "the observed order is above 4: the finest levels may not be in the asymptotic range";
  else if (p < 0.5) g.note = "the observed order is below 0.5: the resolutions are not in the asymptotic range";
  return g;
}

}  // namespace ejecta::verify
