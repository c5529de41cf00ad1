#pragma once
// Shared plumbing of equations of state whose Derived::state(rho, u) returns {P, c2} (the
// Mie-Grüneisen, polynomial and JWL forms): batched evaluation and the single-point pressure and
// sound speed, with c floored at Derived::soundSpeedFloor() where c2 is small, negative or NaN.
#include <cmath>
#include <cstddef>

#include "sim/eos/eos.hpp"

namespace ejecta {

// sqrt(c2), or `floor` when c2 < floor^2 (NaN c2 also fails the comparison and gets the floor).
inline double flooredSoundSpeed(double c2, double floor) {
  return (c2 > floor * floor) ? std::sqrt(c2) : floor;
}

template <typename Derived>
class StateEquationOfState : public EquationOfState {
 public:
  void evaluate(const double* rho, const double* u, double* P, double* cs,
                const std::size_t* indices, std::size_t n) const override {
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t i = indices[k];
      const auto s = self().state(rho[i], u[i]);
      P[i] = s.P;
      cs[i] = flooredSoundSpeed(s.c2, self().soundSpeedFloor());
    }
  }
  double pressure(double rho, double u) const override { return self().state(rho, u).P; }
  double soundSpeed(double rho, double u) const override {
    return flooredSoundSpeed(self().state(rho, u).c2, self().soundSpeedFloor());
  }
  // Analytic c^2 = dP/drho|_u + (P/rho^2) dP/du|_rho before the positivity floor (for tests).
  double soundSpeedSquared(double rho, double u) const { return self().state(rho, u).c2; }

 private:
  const Derived& self() const { return static_cast<const Derived&>(*this); }
};

}  // namespace ejecta
