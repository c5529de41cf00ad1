#pragma once
// The artificial stress pair term (Monaghan 2000, J. Comput. Phys. 159, 290; Gray, Monaghan &
// Swift 2001, CMAME 190, 6641, eqs. 4.6-4.8), which keeps particles of a solid in tension from
// clumping (the tensile instability): each particle's tensile principal stresses give
//   R = -epsilon sigma / (rho s), rotated back from the principal frame,
// and a pair adds (R_i + R_j) f^n to its stress, f = W(r)/W(dp) with dp = h/eta the spacing.
// Symmetric in i and j, so it conserves momentum; its work goes to du/dt with the viscosity's.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "sim/sph/hydro_workspace.hpp"
#include "sim/sph/kernel.hpp"
#include "sim/sph/terms/pair.hpp"
#include "sim/sph/terms/stress_divergence.hpp"
#include "sim/state/particles.hpp"
#include "sim/state/tensor.hpp"

namespace ejecta {

template <template <int> class K, int D, bool RZ>
class ArtificialStress {
 public:
  // R of the particles `which`; the rest (halos still in flight) come by refresh.
  ArtificialStress(const ParticleSet& p, const HydroWorkspace& ws, TermParticles which)
      : epsilon_(ws.artificialStress),
        exponent_(ws.sph.artificialStressExponent),
        integerExponent_(static_cast<int>(exponent_)) {
    integerPower_ = integerExponent_ == exponent_ && integerExponent_ <= 16;
    double dwRef;
    K<D>::shape(1.0 / ws.sph.eta, wRef_, dwRef);
    refresh(p, ws, which);
  }

  // Computes R of the particles `which` (halos whose values arrived).
  void refresh(const ParticleSet& p, const HydroWorkspace& ws, TermParticles which) {
    if (!enabled()) return;
    for (int a = 0; a < D; ++a)
      for (int b = a; b < D; ++b) R_[kSymIndex[a][b]].resize(p.size());
#pragma omp parallel for schedule(static)
    for (std::size_t k = 0; k < which.count(); ++k) {
      const std::size_t i = which[k];
      for (int a = 0; a < D; ++a)
        for (int b = a; b < D; ++b) R_[kSymIndex[a][b]][i] = 0.0;  // no tension: no R
      if (!(ws.shearModulus[p.material[i]] > 0.0)) continue;  // fluids: no tensile instability
      const double sigmaI = RZ ? p.areaDensity[i] : p.rho[i];
      principalTension(actingStress(p, ws, i), epsilon_ / (p.rho[i] * sigmaI), i);
    }
  }

  bool enabled() const { return epsilon_ > 0.0; }

  // The pair's weight m_j f^n dW/dr / r of (R_i + R_j).
  double pairWeight(const PairOrigin& o, const Pair& g) const {
    double w, dw;
    K<D>::shape(2.0 * g.r / (o.h + g.hj), w, dw);
    return g.mj * power(w / wRef_) * g.dWavg * g.rInv;
  }
  // Component k of R_i + R_j.
  double sum(int k, std::size_t i, std::size_t j) const { return R_[k][i] + R_[k][j]; }

 private:
  // R of particle i from its stress, eps = epsilon / (rho s).
  void principalTension(const SymTensor& sigma, double eps, std::size_t i) {
    if constexpr (D == 1) {
      R_[kXX][i] = sigma[kXX] > 0.0 ? -eps * sigma[kXX] : 0.0;
    } else if constexpr (D == 2) {
      double lo, hi, c, s;
      planeEigen(sigma[kXX], sigma[kYY], sigma[kXY], lo, hi, c, s);
      const double rHi = hi > 0.0 ? -eps * hi : 0.0, rLo = lo > 0.0 ? -eps * lo : 0.0;
      // Eigenvector of hi is (c, s), of lo (-s, c).
      R_[kXX][i] = rHi * c * c + rLo * s * s;
      R_[kYY][i] = rHi * s * s + rLo * c * c;
      R_[kXY][i] = (rHi - rLo) * c * s;
    } else {
      std::array<double, 3> values;
      Mat3 vectors;
      symmetricEigen(sigma, values, &vectors);
      if (values[2] <= 0.0) return;
      for (int k = 0; k < 6; ++k) {
        double total = 0.0;
        for (int e = 0; e < 3; ++e)
          if (values[e] > 0.0)
            total += -eps * values[e] * vectors[kSymRow[k]][e] * vectors[kSymCol[k]][e];
        R_[k][i] = total;
      }
    }
  }

  // f^n is evaluated for every pair: an integer n (the default 4) is a few multiplications,
  // where std::pow cost a fifth of a solid step.
  double power(double f) const {
    if (!integerPower_) return std::pow(f, exponent_);
    double out = 1.0, base = f;
    for (int e = integerExponent_; e > 0; e >>= 1, base *= base)
      if (e & 1) out *= base;
    return out;
  }

  std::array<std::vector<double>, 6> R_;
  double epsilon_, exponent_;
  int integerExponent_;
  bool integerPower_ = false;
  double wRef_ = 1.0;  // W at the spacing, f's reference
};

}  // namespace ejecta
