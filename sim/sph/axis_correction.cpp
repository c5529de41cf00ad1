#include "sim/sph/axis_correction.hpp"

#include <cmath>

#include "sim/sph/kernel.hpp"

namespace ejecta {

namespace {

// Kernel (h = 1) projected onto one axis: Wp(x) = integral W2D(sqrt(x^2 + z^2)) dz.
template <template <int> class K>
std::vector<double> projectedKernel(const std::vector<double>& xs) {
  constexpr int kSteps = 800;  // Simpson panels over z in [0, 2]; W is C1 or smoother
  std::vector<double> wp(xs.size());
  for (std::size_t k = 0; k < xs.size(); ++k) {
    const double x = xs[k];
    const double zMax = std::sqrt(std::max(4.0 - x * x, 0.0));
    const double dz = zMax / kSteps;
    double sum = 0.0;
    for (int s = 0; s <= kSteps; ++s) {
      const double z = s * dz;
      const double weight = (s == 0 || s == kSteps) ? 1.0 : (s % 2 ? 4.0 : 2.0);
      sum += weight * kernelValue<K, 2>(std::sqrt(x * x + z * z), 1.0);
    }
    wp[k] = 2.0 * sum * dz / 3.0;  // both halves of z
  }
  return wp;
}

}  // namespace

AxisCorrection::AxisCorrection(KernelKind kernel) : I_(kTableSize), dI_(kTableSize) {
  // Projected kernel on a fine grid of s in [-2, 2].
  constexpr int kGrid = 4000;
  const double ds = 4.0 / kGrid;
  std::vector<double> s(kGrid + 1);
  for (int k = 0; k <= kGrid; ++k) s[k] = -2.0 + k * ds;
  const std::vector<double> wp = withKernel(kernel, [&]<template <int> class K>() {
    return projectedKernel<K>(s);
  });
  // I(xi) = int |xi - s| Wp ds and I'(xi) = int sign(xi - s) Wp ds, trapezoid rule; the table
  // points xi fall on grid nodes (kGrid is a multiple of 2 * (kTableSize - 1)), so the kink of
  // |xi - s| sits on a node and the rule stays second order.
  for (int t = 0; t < kTableSize; ++t) {
    const double xi = 2.0 * t / (kTableSize - 1);
    double I = 0.0, dI = 0.0;
    for (int k = 0; k <= kGrid; ++k) {
      const double weight = (k == 0 || k == kGrid) ? 0.5 : 1.0;
      const double d = xi - s[k];
      I += weight * std::abs(d) * wp[k];
      dI += weight * (d > 0 ? 1.0 : (d < 0 ? -1.0 : 0.0)) * wp[k];
    }
    I_[t] = I * ds;
    dI_[t] = dI * ds;
  }
  // Beyond the support the relations are exact; pin the last entry so the table joins them.
  I_[kTableSize - 1] = 2.0;
  dI_[kTableSize - 1] = 1.0;
}

void AxisCorrection::smoothedRadius(double r, double h, double& rt, double& drt_dr) const {
  const double xi = std::abs(r) / h;
  // Beyond the support, and for a NaN state (which the step's health check then reports with
  // the particle, rather than this table being indexed out of range).
  if (!(xi < 2.0)) {
    rt = std::abs(r);
    drt_dr = 1.0;
    return;
  }
  // Cubic Hermite interpolation of I with its tabulated slope: consistent value and derivative.
  const double pos = xi * (kTableSize - 1) / 2.0;
  const int k = std::min(static_cast<int>(pos), kTableSize - 2);
  const double t = pos - k, step = 2.0 / (kTableSize - 1);
  const double t2 = t * t, t3 = t2 * t;
  const double h00 = 2 * t3 - 3 * t2 + 1, h10 = t3 - 2 * t2 + t;
  const double h01 = -2 * t3 + 3 * t2, h11 = t3 - t2;
  rt = h * (h00 * I_[k] + h10 * step * dI_[k] + h01 * I_[k + 1] + h11 * step * dI_[k + 1]);
  // The derivative of the same Hermite curve, so rt and d rt/dr are exactly consistent.
  const double d00 = 6 * t2 - 6 * t, d10 = 3 * t2 - 4 * t + 1;
  const double d01 = -6 * t2 + 6 * t, d11 = 3 * t2 - 2 * t;
  drt_dr = (d00 * I_[k] + d01 * I_[k + 1]) / step + d10 * dI_[k] + d11 * dI_[k + 1];
}

}  // namespace ejecta
