#include "sim/verify/least_squares_uncertainty.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <stdexcept>

namespace ejecta::verify {

namespace {

// The order's search range: below 0.01 x^p is a constant to the data's precision, above 10 it is
// zero at every level but the coarsest; a best p at either bound means the data have no order.
constexpr double kLowestOrder = 0.01;
constexpr double kHighestOrder = 10.0;

struct Levels {
  std::vector<double> x;  // spacing / finest spacing, finest first (x = 1)
  std::vector<double> phi;
  std::vector<double> w;  // weights, summing to n for the unweighted fit and to 1 for the weighted
};

struct Fit {
  bool ok = false;
  double phi0 = 0.0;       // the fitted limit
  double finestFit = 0.0;  // the fit at the finest spacing
  double ssr = 0.0;        // sum w (phi - fit)^2
  double sigma = 0.0;      // the residuals' standard deviation (the header's step 1)
};

// phi = phi0 + sum_k a_k x^e_k by weighted least squares (normal equations on columns scaled to
// a unit maximum, so x^10 and a constant stay comparable; at most three columns). `parameters`:
// how many the fit determined, for sigma's degrees of freedom (the power fit's p is one more).
Fit fitTerms(const Levels& l, const std::vector<double>& exponents, std::size_t parameters) {
  const std::size_t m = exponents.size() + 1, n = l.x.size();
  std::vector<std::array<double, 3>> columns(n);
  std::array<double, 3> scale{1.0, 1.0, 1.0};
  for (std::size_t k = 1; k < m; ++k)
    for (std::size_t i = 0; i < n; ++i) scale[k] = std::max(scale[k], std::pow(l.x[i], exponents[k - 1]));
  for (std::size_t i = 0; i < n; ++i) {
    columns[i][0] = 1.0;
    for (std::size_t k = 1; k < m; ++k) columns[i][k] = std::pow(l.x[i], exponents[k - 1]) / scale[k];
  }
  double a[3][4] = {};
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t r = 0; r < m; ++r) {
      for (std::size_t c = 0; c < m; ++c) a[r][c] += l.w[i] * columns[i][r] * columns[i][c];
      a[r][m] += l.w[i] * columns[i][r] * l.phi[i];
    }
  // Gaussian elimination with partial pivoting; a pivot lost to round-off against the matrix's
  // scale (columns equal to the data's precision) is no fit.
  double largest = 0.0;
  for (std::size_t r = 0; r < m; ++r)
    for (std::size_t c = 0; c < m; ++c) largest = std::max(largest, std::abs(a[r][c]));
  for (std::size_t c = 0; c < m; ++c) {
    std::size_t pivot = c;
    for (std::size_t r = c + 1; r < m; ++r)
      if (std::abs(a[r][c]) > std::abs(a[pivot][c])) pivot = r;
    if (!(std::abs(a[pivot][c]) > 1e-13 * largest)) return {};
    if (pivot != c)
      for (std::size_t k = 0; k <= m; ++k) std::swap(a[c][k], a[pivot][k]);
    for (std::size_t r = c + 1; r < m; ++r) {
      const double f = a[r][c] / a[c][c];
      for (std::size_t k = c; k <= m; ++k) a[r][k] -= f * a[c][k];
    }
  }
  std::array<double, 3> coef{};
  for (std::size_t c = m; c-- > 0;) {
    double s = a[c][m];
    for (std::size_t k = c + 1; k < m; ++k) s -= a[c][k] * coef[k];
    coef[c] = s / a[c][c];
  }
  Fit fit;
  fit.phi0 = coef[0];
  double wsum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    double value = coef[0];
    for (std::size_t k = 1; k < m; ++k) value += coef[k] * columns[i][k];
    if (i == 0) fit.finestFit = value;
    fit.ssr += l.w[i] * (l.phi[i] - value) * (l.phi[i] - value);
    wsum += l.w[i];
  }
  fit.sigma = std::sqrt(static_cast<double>(n) / wsum * fit.ssr / static_cast<double>(n - parameters));
  fit.ok = std::isfinite(fit.phi0) && std::isfinite(fit.sigma);
  return fit;
}

struct PowerFit {
  Fit fit;
  double order = 0.0;
  bool atBound = false;
};

// phi = phi0 + a x^p with p minimising the residuals: a scan on a logarithmic grid, then a
// golden-section search between the best point's neighbours (the residual is smooth in p).
PowerFit fitPower(const Levels& l) {
  constexpr int kScan = 400;
  const double step = std::log(kHighestOrder / kLowestOrder) / kScan;
  auto orderAt = [&](int k) { return kLowestOrder * std::exp(step * k); };
  auto ssrAt = [&](double p) {
    const Fit f = fitTerms(l, {p}, 3);
    return f.ok ? f.ssr : HUGE_VAL;
  };
  int best = 0;
  double bestSsr = HUGE_VAL;
  for (int k = 0; k <= kScan; ++k) {
    const double s = ssrAt(orderAt(k));
    if (s < bestSsr) {
      bestSsr = s;
      best = k;
    }
  }
  double lo = orderAt(std::max(best - 1, 0)), hi = orderAt(std::min(best + 1, kScan));
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = hi - g * (hi - lo), d = lo + g * (hi - lo), sc = ssrAt(c), sd = ssrAt(d);
  for (int it = 0; it < 100 && hi - lo > 1e-12 * hi; ++it) {
    if (sc <= sd) {  // the minimum lies in [lo, d]
      hi = d;
      d = c;
      sd = sc;
      c = hi - g * (hi - lo);
      sc = ssrAt(c);
    } else {  // in [c, hi]
      lo = c;
      c = d;
      sc = sd;
      d = lo + g * (hi - lo);
      sd = ssrAt(d);
    }
  }
  PowerFit out;
  out.order = 0.5 * (lo + hi);
  if (bestSsr <= ssrAt(out.order)) out.order = orderAt(best);
  out.fit = fitTerms(l, {out.order}, 3);
  out.atBound = best == 0 || best == kScan;
  return out;
}

// One form the error estimate may come from.
struct Candidate {
  Fit fit;
  double order;  // its leading order
  const char* form;
};

}  // namespace

LeastSquaresUncertainty leastSquaresUncertainty(const std::vector<double>& spacings, const std::vector<double>& values,
                                                double formalOrder) {
  if (spacings.size() != values.size())
    throw std::invalid_argument("least-squares uncertainty: as many spacings as values are needed");
  if (!(formalOrder > 0.0) || !std::isfinite(formalOrder))
    throw std::invalid_argument("least-squares uncertainty: the formal order must be positive");
  const std::size_t n = spacings.size();
  for (double h : spacings)
    if (!(h > 0.0) || !std::isfinite(h))
      throw std::invalid_argument("least-squares uncertainty: spacings must be positive");
  std::vector<std::size_t> bySpacing(n);
  std::iota(bySpacing.begin(), bySpacing.end(), 0u);
  std::sort(bySpacing.begin(), bySpacing.end(),
            [&](std::size_t a, std::size_t b) { return spacings[a] < spacings[b]; });
  for (std::size_t k = 1; k < n; ++k)
    if (spacings[bySpacing[k]] == spacings[bySpacing[k - 1]])
      throw std::invalid_argument("least-squares uncertainty: two resolutions share a spacing");
  LeastSquaresUncertainty u;
  if (n < 4) {
    u.note = "fewer than four levels: no least-squares fit (three parameters need a fourth level to show scatter)";
    return u;
  }
  Levels unweighted;
  for (std::size_t i : bySpacing) {
    if (!std::isfinite(values[i])) {
      u.note = "a value is not finite: no least-squares fit";
      return u;
    }
    unweighted.x.push_back(spacings[i] / spacings[bySpacing[0]]);
    unweighted.phi.push_back(values[i]);
  }
  const auto [lowest, highest] = std::minmax_element(unweighted.phi.begin(), unweighted.phi.end());
  u.dataRange = (*highest - *lowest) / static_cast<double>(n - 1);
  if (u.dataRange == 0.0) {
    u.note = "all levels are equal: no least-squares fit";
    return u;
  }
  unweighted.w.assign(n, 1.0);
  Levels weighted = unweighted;
  double inverseSum = 0.0;
  for (double x : weighted.x) inverseSum += 1.0 / x;
  for (std::size_t i = 0; i < n; ++i) weighted.w[i] = (1.0 / weighted.x[i]) / inverseSum;

  const PowerFit plain = fitPower(unweighted), byWeight = fitPower(weighted);
  if (!plain.fit.ok && !byWeight.fit.ok) {
    u.note = "no least-squares fit could be made";
    return u;
  }
  u.weighted = byWeight.fit.ok && (!plain.fit.ok || byWeight.fit.sigma < plain.fit.sigma);
  const PowerFit& power = u.weighted ? byWeight : plain;
  const Levels& levels = u.weighted ? weighted : unweighted;
  u.order = power.order;
  u.orderAtSearchBound = power.atBound;

  // The error estimate's fit (the header's step 2): the power fit where its order is reasonable,
  // else the fixed-order candidate with the smallest sigma.
  std::vector<Candidate> candidates;
  const char* why = "";
  if (u.order < 0.5) {
    why = " below 0.5";
    candidates = {{fitTerms(levels, {1.0}, 2), 1.0, "phi0 + a h"},
                  {fitTerms(levels, {2.0}, 2), 2.0, "phi0 + a h^2"},
                  {fitTerms(levels, {1.0, 2.0}, 3), 1.0, "phi0 + a h + b h^2"}};
  } else if (u.order > formalOrder) {
    why = " above the formal order";
    candidates = {{fitTerms(levels, {formalOrder}, 2), formalOrder, "phi0 + a h^p_formal"},
                  {fitTerms(levels, {1.0, 2.0}, 3), 1.0, "phi0 + a h + b h^2"}};
  } else {
    candidates = {{power.fit, u.order, "phi0 + a h^p"}};
  }
  const Candidate* best = nullptr;
  for (const Candidate& c : candidates)
    if (c.fit.ok && (best == nullptr || c.fit.sigma < best->fit.sigma)) best = &c;
  if (best == nullptr) {
    u.note = "no least-squares fit could be made";
    return u;
  }
  char note[200];
  std::snprintf(note, sizeof note, "least-squares order %.3g%s: the error estimate from %s", u.order, why, best->form);
  u.note = note;
  const Fit& chosen = best->fit;
  u.estimateOrder = best->order;
  u.extrapolated = chosen.phi0;
  u.errorEstimate = std::abs(chosen.finestFit - chosen.phi0);
  u.standardDeviation = chosen.sigma;
  u.goodFit = u.standardDeviation < u.dataRange;
  u.safetyFactor = (u.order >= 0.5 && u.order < 1.05 * formalOrder && u.goodFit) ? 1.25 : 3.0;
  const double offFit = std::abs(unweighted.phi[0] - chosen.finestFit);
  const double sum = u.errorEstimate + u.standardDeviation + offFit;
  u.uncertainty = u.goodFit ? u.safetyFactor * u.errorEstimate + u.standardDeviation + offFit
                            : 3.0 * (u.standardDeviation / u.dataRange) * sum;
  u.available = true;
  return u;
}

}  // namespace ejecta::verify
