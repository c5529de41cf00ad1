#include <cmath>
#include <stdexcept>

#include "sim/eos/eos.hpp"

namespace ejecta {

IdealGas::IdealGas(double gamma) : gamma_(gamma) {
  if (!(gamma > 1.0)) throw std::invalid_argument("ideal gas: gamma must exceed 1");
}

void IdealGas::evaluate(const double* rho, const double* u, double* P, double* cs,
                        const std::size_t* indices, std::size_t n) const {
  const double gm1 = gamma_ - 1.0;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = indices[k];
    const double p = gm1 * rho[i] * u[i];
    P[i] = p;
    // u < 0 is caught by the run's health check; keep c real meanwhile.
    cs[i] = std::sqrt(std::max(gamma_ * gm1 * u[i], 0.0));
  }
}

double IdealGas::pressure(double rho, double u) const { return (gamma_ - 1.0) * rho * u; }

double IdealGas::soundSpeed(double, double u) const {
  return std::sqrt(std::max(gamma_ * (gamma_ - 1.0) * u, 0.0));
}

double IdealGas::specificEnergy(double rho, double P) const {
  if (!(rho > 0.0)) throw std::domain_error("ideal gas: density must be positive");
  if (P < 0.0) throw std::domain_error("ideal gas: pressure cannot be negative");
  return P / ((gamma_ - 1.0) * rho);
}

}  // namespace ejecta
