#include "sim/verify/blast_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace ejecta::verify {

double blastDistance(const ParticleSet& p, std::size_t i, const std::array<double, 3>& c, int dim) {
  double r2 = 0.0;
  for (int d = 0; d < dim; ++d) {
    const double dx = p.x[d][i] - c[d];
    r2 += dx * dx;
  }
  return std::sqrt(r2);
}

BlastShock blastShock(const ParticleSet& p, const std::array<double, 3>& centre, int dim,
                      double binWidth, double rMax) {
  const int bins = static_cast<int>(rMax / binWidth) + 1;
  std::vector<double> binRho(bins, 0.0), binP(bins, 0.0), binMass(bins, 0.0);
  for (std::size_t i = 0; i < p.numReal; ++i) {
    const int b = static_cast<int>(blastDistance(p, i, centre, dim) / binWidth);
    if (b < bins) {
      binRho[b] += p.mass[i] * p.rho[i];
      binP[b] += p.mass[i] * p.P[i];
      binMass[b] += p.mass[i];
    }
  }
  int peak = 0;
  for (int b = 0; b < bins; ++b) {
    if (binMass[b] > 0) {
      binRho[b] /= binMass[b];
      binP[b] /= binMass[b];
    }
    if (binRho[b] > binRho[peak]) peak = b;
  }
  const double radius = (peak + 0.5) * binWidth;
  double peakPressure = 0.0;
  for (int b = 0; b < bins; ++b) {
    const double binCentre = (b + 0.5) * binWidth;
    if (binCentre >= 0.5 * radius && binCentre <= 1.5 * radius)
      peakPressure = std::max(peakPressure, binP[b]);
  }
  return {radius, binRho[peak], peakPressure};
}

double centrePressureRatio(const ParticleSet& p, const std::array<double, 3>& centre, int dim,
                           const exact::SedovSolution& sedov, double time, std::size_t count) {
  std::vector<std::pair<double, std::size_t>> byDistance(p.numReal);
  for (std::size_t i = 0; i < p.numReal; ++i) byDistance[i] = {blastDistance(p, i, centre, dim), i};
  count = std::min(count, byDistance.size());
  if (count == 0) return 0.0;
  const auto last = byDistance.begin() + static_cast<std::ptrdiff_t>(count);
  std::nth_element(byDistance.begin(), last - 1, byDistance.end());  // ties: by index, reproducible
  std::vector<double> ratios;
  for (auto it = byDistance.begin(); it != last; ++it)
    ratios.push_back(p.P[it->second] / sedov.at(it->first, time).p);
  const auto middle = ratios.begin() + static_cast<std::ptrdiff_t>(ratios.size() / 2);
  std::nth_element(ratios.begin(), middle, ratios.end());
  return *middle;
}

}  // namespace ejecta::verify
