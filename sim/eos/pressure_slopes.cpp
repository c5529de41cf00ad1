// The default partial derivatives of an equation of state, by differences of its pressure.
#include <cmath>

#include "sim/eos/eos.hpp"

namespace ejecta {

EquationOfState::Slopes EquationOfState::pressureSlopes(double rho, double u) const {
  // Steps of 1e-6 relative (1 J/kg at least): truncation ~1e-12 of a smooth form, round-off
  // ~1e-10 of P over the step's change.
  const double hr = 1e-6 * rho, hu = 1e-6 * std::abs(u) + 1.0;
  Slopes s;
  s.dRho = (pressure(rho + hr, u) - pressure(rho - hr, u)) / (2.0 * hr);
  s.dU = (u >= 0.0 && u < hu) ? (pressure(rho, u + hu) - pressure(rho, u)) / hu
                              : (pressure(rho, u + hu) - pressure(rho, u - hu)) / (2.0 * hu);
  return s;
}

}  // namespace ejecta
