#pragma once
// Smoothing kernels with compact support 2h, normalised in 1, 2 and 3 dimensions.
//   W(r, h) = sigma_D / h^D * w(q),  q = r / h
// Each kernel is a small struct with the dimensionless shape w(q) and its derivative, so the pair
// loops can be instantiated per kernel with no branch or virtual call per pair.
//
// Cubic spline M4 (Monaghan & Lattanzio 1985). The seed's eq. (1.2) prints the outer branch as
// 1 - (1/4)(2 - q^3); the correct branch is (1/4)(2 - q)^3 (see docs/errata.md).
// Wendland C2 and C4 (Wendland 1995; Dehnen & Aly 2012, Table 1), written with support 2h. In 1D
// the Wendland functions of the 1D family are used (psi_{3,1}, psi_{4,2}).
#include <numbers>

#include "sim/sph/sph_options.hpp"

namespace ejecta {

inline constexpr double kKernelSupport = 2.0;  // in units of h, for every kernel here

template <int D>
struct CubicSplineKernel {
  static constexpr double sigma = D == 1 ? 2.0 / 3.0
                                  : D == 2 ? 10.0 / (7.0 * std::numbers::pi)
                                           : 1.0 / std::numbers::pi;
  // w(q) and dw/dq; zero for q >= 2.
  static inline void shape(double q, double& w, double& dw) {
    if (q < 1.0) {
      w = 1.0 - 1.5 * q * q + 0.75 * q * q * q;
      dw = -3.0 * q + 2.25 * q * q;
    } else if (q < 2.0) {
      const double a = 2.0 - q;
      w = 0.25 * a * a * a;
      dw = -0.75 * a * a;
    } else {
      w = 0.0;
      dw = 0.0;
    }
  }
};

template <int D>
struct WendlandC2Kernel {
  static constexpr double sigma = D == 1 ? 5.0 / 8.0
                                  : D == 2 ? 7.0 / (4.0 * std::numbers::pi)
                                           : 21.0 / (16.0 * std::numbers::pi);
  static inline void shape(double q, double& w, double& dw) {
    if (q >= 2.0) { w = 0.0; dw = 0.0; return; }
    const double a = 1.0 - 0.5 * q;
    if constexpr (D == 1) {
      const double a2 = a * a;
      w = a2 * a * (1.0 + 1.5 * q);
      dw = -3.0 * q * a2;
    } else {
      const double a3 = a * a * a;
      w = a3 * a * (1.0 + 2.0 * q);
      dw = -5.0 * q * a3;
    }
  }
};

template <int D>
struct WendlandC4Kernel {
  static constexpr double sigma = D == 1 ? 3.0 / 4.0
                                  : D == 2 ? 9.0 / (4.0 * std::numbers::pi)
                                           : 495.0 / (256.0 * std::numbers::pi);
  static inline void shape(double q, double& w, double& dw) {
    if (q >= 2.0) { w = 0.0; dw = 0.0; return; }
    const double a = 1.0 - 0.5 * q;
    if constexpr (D == 1) {
      const double a4 = a * a * a * a;
      w = a4 * a * (1.0 + 2.5 * q + 2.0 * q * q);
      dw = -3.5 * q * (1.0 + 2.0 * q) * a4;
    } else {
      const double a5 = a * a * a * a * a;
      w = a5 * a * (1.0 + 3.0 * q + (35.0 / 12.0) * q * q);
      dw = -(14.0 / 3.0) * q * (1.0 + 2.5 * q) * a5;
    }
  }
};

// Dimensional helpers shared by every kernel.
template <int D>
inline double hPowerD(double h) {
  if constexpr (D == 1) return h;
  else if constexpr (D == 2) return h * h;
  else return h * h * h;
}

// W(r, h) for kernel K in D dimensions.
template <template <int> class K, int D>
inline double kernelValue(double r, double h) {
  double w, dw;
  K<D>::shape(r / h, w, dw);
  return K<D>::sigma / hPowerD<D>(h) * w;
}

// dW/dr for kernel K in D dimensions.
template <template <int> class K, int D>
inline double kernelDerivative(double r, double h) {
  double w, dw;
  K<D>::shape(r / h, w, dw);
  return K<D>::sigma / (hPowerD<D>(h) * h) * dw;
}

// dW/dh: -(sigma / h^(D+1)) (D w + q dw/dq).
template <template <int> class K, int D>
inline double kernelDerivativeH(double r, double h) {
  const double q = r / h;
  double w, dw;
  K<D>::shape(q, w, dw);
  return -K<D>::sigma / (hPowerD<D>(h) * h) * (D * w + q * dw);
}

// Runtime dispatch to a function templated on the kernel: f.template operator()<K>().
template <typename F>
decltype(auto) withKernel(KernelKind kind, F&& f) {
  switch (kind) {
    case KernelKind::WendlandC2: return f.template operator()<WendlandC2Kernel>();
    case KernelKind::WendlandC4: return f.template operator()<WendlandC4Kernel>();
    case KernelKind::CubicSpline: break;
  }
  return f.template operator()<CubicSplineKernel>();
}

// Name as used in scene files: "cubic_spline", "wendland_c2", "wendland_c4".
const char* kernelName(KernelKind kind);

}  // namespace ejecta
