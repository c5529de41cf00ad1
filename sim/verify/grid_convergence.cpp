#include "sim/verify/grid_convergence.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <stdexcept>

namespace ejecta::verify {

namespace {

// The band relative to |phi1|, or absolute where phi1 = 0.
double bandScale(double f1) { return f1 != 0.0 ? std::abs(f1) : 1.0; }

// Half the spread of three levels: an oscillation's half amplitude (Stern et al. 2001).
double halfSpread(double f1, double f2, double f3) {
  return 0.5 * (std::max({f1, f2, f3}) - std::min({f1, f2, f3}));
}

// Roache's fallback band (grid_convergence.hpp): factor of safety 3 at the formal order, or at
// the observed order where a monotone sequence converges more slowly; where the changes
// alternate, at least half the spread of the three levels.
void fallbackBand(GridConvergence& g, double r21, double f1, double f2, double f3) {
  const bool slower = g.valid && !g.oscillatory && g.order < g.formalOrder;
  g.bandOrder = slower ? g.order : g.formalOrder;
  g.basis = UncertaintyBasis::FormalFallback;
  const double scale = bandScale(f1);
  g.gci = 3.0 * g.relativeChange / (std::pow(r21, g.bandOrder) - 1.0);
  const double half = halfSpread(f1, f2, f3) / scale;
  g.bandAtHalfSpread = g.oscillatory && half > g.gci;
  if (g.bandAtHalfSpread) g.gci = half;
  g.uncertainty = g.gci * scale;
}

// The three finest levels by Celik et al.'s procedure (the header), finest first.
GridConvergence threeFinest(const double h[3], const double f[3], double formalOrder) {
  const double f1 = f[0], f2 = f[1], f3 = f[2];
  GridConvergence g;
  g.formalOrder = formalOrder;
  if (!std::isfinite(f1) || !std::isfinite(f2) || !std::isfinite(f3)) {
    g.note = "a value is not finite: no order and no band";
    return g;
  }
  const double e21 = f2 - f1, e32 = f3 - f2;
  const double r21 = h[1] / h[0], r32 = h[2] / h[1];
  g.relativeChange = std::abs(e21) / bandScale(f1);
  if (e21 == 0.0) {
    g.note = "the two finest values are equal: no order (converged to the output's precision, or insensitive)";
    return g;
  }
  if (e32 == 0.0) {
    g.note = "the two coarsest values are equal: no order";
    fallbackBand(g, r21, f1, f2, f3);
    return g;
  }
  const double s = e32 / e21 > 0.0 ? 1.0 : -1.0;
  g.oscillatory = s < 0.0;
  // A converging power of h, phi1 + a (h^p - h1^p) with p > 0, changes by e21 / e32 =
  // (1 - r21^-p) / (r32^p - 1) < ln r21 / ln r32 (the limit p -> 0; 1 at equal ratios). A finer
  // change larger than that is monotone divergence (Stern et al. 2001: R = e21 / e32 > 1), which
  // Celik's |ln| would report as a positive order.
  if (s > 0.0 && std::abs(e21) * std::log(r32) > std::abs(e32) * std::log(r21)) {
    g.note = "the changes grow as the spacing shrinks (monotone divergence): no order";
    fallbackBand(g, r21, f1, f2, f3);
    return g;
  }
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
    fallbackBand(g, r21, f1, f2, f3);
    return g;
  }
  g.valid = true;
  g.order = p;
  const double rp = std::pow(r21, p);
  g.extrapolated = (rp * f1 - f2) / (rp - 1.0);
  g.extrapolatedError = g.extrapolated != 0.0 ? std::abs((g.extrapolated - f1) / g.extrapolated) : 0.0;
  if (g.oscillatory) {
    g.note = "oscillatory convergence (the changes alternate in sign)";
  } else if (p > 2.0 * formalOrder) {
    char limit[160];
    std::snprintf(limit, sizeof limit, "the observed order is above %.3g (twice the formal order): "
                  "the finest levels may not be in the asymptotic range", 2.0 * formalOrder);
    g.note = limit;
  } else if (p < 0.5) {
    g.note = "the observed order is below 0.5: the resolutions are not in the asymptotic range";
  }
  g.asymptotic = g.note.empty();
  if (!g.asymptotic) {
    fallbackBand(g, r21, f1, f2, f3);
    return g;
  }
  g.basis = UncertaintyBasis::ObservedOrder;
  g.bandOrder = p;
  g.gci = 1.25 * g.relativeChange / (rp - 1.0);
  g.uncertainty = g.gci * bandScale(f1);
  return g;
}

}  // namespace

GridConvergence gridConvergence(std::vector<double> spacings, std::vector<double> values, double formalOrder) {
  if (spacings.size() != values.size())
    throw std::invalid_argument("grid convergence: as many spacings as values are needed");
  if (spacings.size() < 3)
    throw std::invalid_argument("grid convergence: at least three resolutions are needed for an order");
  if (!(formalOrder > 0.0) || !std::isfinite(formalOrder))
    throw std::invalid_argument("grid convergence: the formal order must be positive");
  std::vector<std::size_t> order(spacings.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return spacings[a] < spacings[b]; });
  for (std::size_t k = 0; k < order.size(); ++k) {
    if (!(spacings[order[k]] > 0.0) || !std::isfinite(spacings[order[k]]))
      throw std::invalid_argument("grid convergence: spacings must be positive");
    if (k > 0 && spacings[order[k]] == spacings[order[k - 1]])
      throw std::invalid_argument("grid convergence: two resolutions share a spacing");
  }
  const double h[3] = {spacings[order[0]], spacings[order[1]], spacings[order[2]]};
  const double f[3] = {values[order[0]], values[order[1]], values[order[2]]};
  GridConvergence g = threeFinest(h, f, formalOrder);
  g.leastSquares = leastSquaresUncertainty(spacings, values, formalOrder);
  const LeastSquaresUncertainty& ls = g.leastSquares;
  if (!ls.available) return g;
  // All levels must agree with the three finest that the range is asymptotic: an order within
  // the same limits, found inside the search, and residuals below the data range.
  const bool inRange = ls.order >= 0.5 && ls.order <= 2.0 * formalOrder && !ls.orderAtSearchBound && ls.goodFit;
  if (g.asymptotic && !inRange) {
    char why[200];
    std::snprintf(why, sizeof why, "the %zu levels together do not follow one power of h (least squares: order %.3g, "
                  "scatter %.3g against a data range of %.3g per level)", spacings.size(), ls.order,
                  ls.standardDeviation, ls.dataRange);
    g.note = why;
    g.asymptotic = false;
    fallbackBand(g, h[1] / h[0], f[0], f[1], f[2]);
  }
  // Where the three finest's changes alternate, Roache's fallback (a monotone sequence's bound,
  // three times the last change over r21 - 1) measures the last swing, not the error: the fit
  // over all levels is the band there, at least half the three finest's spread (Stern et al.).
  // Elsewhere the wider band: the three finest's where it holds the scatter of all levels, else
  // Eca and Hoekstra's (whose fixed-order fits understate a slower order than 0.5).
  const std::string fromAll = (g.note.empty() ? "" : "; the band from all levels: ") + ls.note;
  if (g.oscillatory) {
    const double floor = halfSpread(f[0], f[1], f[2]);
    g.basis = UncertaintyBasis::LeastSquares;
    g.bandOrder = ls.estimateOrder;
    g.bandAtHalfSpread = floor > ls.uncertainty;
    g.uncertainty = std::max(ls.uncertainty, floor);
    g.gci = g.uncertainty / bandScale(f[0]);
    g.note += fromAll + (g.bandAtHalfSpread ? " (raised to half the three finest's spread)" : "");
    return g;
  }
  if (ls.uncertainty > g.uncertainty) {
    g.basis = UncertaintyBasis::LeastSquares;
    g.bandOrder = ls.estimateOrder;  // (not oscillating: the band was not raised to half the spread)
    g.uncertainty = ls.uncertainty;
    g.gci = ls.uncertainty / bandScale(f[0]);
    g.note += fromAll;
  }
  return g;
}

const char* uncertaintyBasisName(UncertaintyBasis basis) {
  switch (basis) {
    case UncertaintyBasis::ObservedOrder: return "observed order";
    case UncertaintyBasis::FormalFallback: return "formal-order fallback";
    case UncertaintyBasis::LeastSquares: return "least squares";
    case UncertaintyBasis::None: break;
  }
  return "none";
}

std::string describeBand(const GridConvergence& g, std::size_t levels) {
  char own[96] = "";
  switch (g.basis) {
    case UncertaintyBasis::None: return "";
    case UncertaintyBasis::ObservedOrder:
      std::snprintf(own, sizeof own, "GCI band (observed order %.3g, factor of safety 1.25)", g.order);
      break;
    case UncertaintyBasis::FormalFallback:
      std::snprintf(own, sizeof own, "fallback band (order %.3g, factor of safety 3)", g.bandOrder);
      break;
    case UncertaintyBasis::LeastSquares:
      std::snprintf(own, sizeof own, "least-squares band over %zu levels (factor of safety %.3g)", levels,
                    g.leastSquares.safetyFactor);
      break;
  }
  if (!g.bandAtHalfSpread) return own;
  return std::string("half the three finest's spread, wider than the ") + own;
}

}  // namespace ejecta::verify
