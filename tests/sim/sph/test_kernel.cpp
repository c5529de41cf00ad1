// Kernel unit tests: normalisation in 1, 2 and 3 dimensions, derivative consistency, compact
// support, and the RZ axis correction's limits.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sim/sph/axis_correction.hpp"
#include "sim/sph/kernel.hpp"

namespace ejecta {
namespace {

// Integral of W over R^D by the radial measure (2, 2 pi r, 4 pi r^2), Simpson's rule.
template <template <int> class K, int D>
double integral(double h) {
  const int n = 4000;
  const double R = kKernelSupport * h, dr = R / n;
  double sum = 0.0;
  for (int k = 0; k <= n; ++k) {
    const double r = k * dr;
    const double measure = D == 1 ? 2.0 : D == 2 ? 2.0 * std::numbers::pi * r
                                                 : 4.0 * std::numbers::pi * r * r;
    const double w = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
    sum += w * measure * kernelValue<K, D>(r, h);
  }
  return sum * dr / 3.0;
}

template <template <int> class K>
void expectNormalised() {
  // Simpson with 4000 panels on a piecewise polynomial: error ~1e-10; 1e-8 leaves margin.
  for (double h : {0.1, 1.0, 3.7}) {
    EXPECT_NEAR((integral<K, 1>(h)), 1.0, 1e-8);
    EXPECT_NEAR((integral<K, 2>(h)), 1.0, 1e-8);
    EXPECT_NEAR((integral<K, 3>(h)), 1.0, 1e-8);
  }
}

TEST(Kernel, CubicSplineIsNormalised) { expectNormalised<CubicSplineKernel>(); }
TEST(Kernel, WendlandC2IsNormalised) { expectNormalised<WendlandC2Kernel>(); }
TEST(Kernel, WendlandC4IsNormalised) { expectNormalised<WendlandC4Kernel>(); }

template <template <int> class K, int D>
void expectDerivativesMatchFiniteDifferences() {
  const double h = 0.7, eps = 1e-6;
  for (double q = 0.05; q < 2.0; q += 0.0731) {
    const double r = q * h;
    const double fdR = (kernelValue<K, D>(r + eps, h) - kernelValue<K, D>(r - eps, h)) / (2 * eps);
    const double fdH = (kernelValue<K, D>(r, h + eps) - kernelValue<K, D>(r, h - eps)) / (2 * eps);
    // Central differences of a C1+ function at step 1e-6: error ~1e-10 relative to W(0)/h.
    const double scale = kernelValue<K, D>(0.0, h) / h;
    EXPECT_NEAR((kernelDerivative<K, D>(r, h)), fdR, 1e-7 * scale) << "q=" << q;
    EXPECT_NEAR((kernelDerivativeH<K, D>(r, h)), fdH, 1e-7 * scale) << "q=" << q;
  }
}

TEST(Kernel, DerivativesMatchFiniteDifferences) {
  expectDerivativesMatchFiniteDifferences<CubicSplineKernel, 1>();
  expectDerivativesMatchFiniteDifferences<CubicSplineKernel, 2>();
  expectDerivativesMatchFiniteDifferences<CubicSplineKernel, 3>();
  expectDerivativesMatchFiniteDifferences<WendlandC2Kernel, 1>();
  expectDerivativesMatchFiniteDifferences<WendlandC2Kernel, 3>();
  expectDerivativesMatchFiniteDifferences<WendlandC4Kernel, 1>();
  expectDerivativesMatchFiniteDifferences<WendlandC4Kernel, 2>();
}

TEST(Kernel, CubicSplineOuterBranchIsCorrected) {
  // The seed's eq. (1.2) prints 1 - (2 - q^3)/4 for 1 < q < 2, which is discontinuous at q = 2
  // (it gives 7/4 there). The M4 spline is (2 - q)^3 / 4: continuous at q = 1 and zero at q = 2.
  double w, dw;
  CubicSplineKernel<3>::shape(1.5, w, dw);
  EXPECT_DOUBLE_EQ(w, 0.25 * 0.125);
  double wIn, wOut, dIn, dOut;
  CubicSplineKernel<3>::shape(1.0 - 1e-12, wIn, dIn);
  CubicSplineKernel<3>::shape(1.0 + 1e-12, wOut, dOut);
  EXPECT_NEAR(wIn, wOut, 1e-10);
  EXPECT_NEAR(dIn, dOut, 1e-10);
  CubicSplineKernel<3>::shape(2.0 - 1e-9, w, dw);
  EXPECT_NEAR(w, 0.0, 1e-20);
}

TEST(Kernel, CompactSupport) {
  EXPECT_EQ((kernelValue<CubicSplineKernel, 3>(2.0, 1.0)), 0.0);
  EXPECT_EQ((kernelValue<WendlandC2Kernel, 2>(2.5, 1.0)), 0.0);
  EXPECT_EQ((kernelDerivative<WendlandC4Kernel, 1>(2.0, 1.0)), 0.0);
}

TEST(AxisCorrection, ReducesToRadiusAwayFromAxisAndIsSmoothNearIt) {
  for (KernelKind kind : {KernelKind::CubicSpline, KernelKind::WendlandC2, KernelKind::WendlandC4}) {
    AxisCorrection axis(kind);
    double rt, drt;
    axis.smoothedRadius(2.5, 1.0, rt, drt);  // beyond the support: exact
    EXPECT_DOUBLE_EQ(rt, 2.5);
    EXPECT_DOUBLE_EQ(drt, 1.0);
    // Just inside the support the smoothed |r| differs from r only by the kernel's tail.
    axis.smoothedRadius(1.99, 1.0, rt, drt);
    EXPECT_NEAR(rt, 1.99, 1e-4);
    // On the axis: rt(0) = h * int |s| Wp(s) ds > 0 and the slope is 0 by symmetry.
    axis.smoothedRadius(0.0, 2.0, rt, drt);
    EXPECT_GT(rt, 0.2 * 2.0);
    EXPECT_LT(rt, 1.0 * 2.0);
    EXPECT_NEAR(drt, 0.0, 1e-6);
    // rt >= r everywhere (|r| smoothed by a positive kernel is convex) and increasing.
    double prev = 0.0;
    for (double r = 0.0; r < 2.2; r += 0.01) {
      axis.smoothedRadius(r, 1.0, rt, drt);
      EXPECT_GE(rt, r - 1e-9);
      EXPECT_GE(rt, prev);
      prev = rt;
    }
  }
}

}  // namespace
}  // namespace ejecta
