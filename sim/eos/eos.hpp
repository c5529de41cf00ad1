#pragma once
// Equation of state interface. One object per material; calls are batched over all particles
// of that material so the virtual dispatch happens once per material, never per pair.
#include <cstddef>
#include <memory>
#include <string>

namespace ejecta {

class EquationOfState {
 public:
  virtual ~EquationOfState() = default;
  virtual std::string name() const = 0;
  // Pressure [Pa] and sound speed [m/s] from density [kg/m^3] and specific internal energy
  // [J/kg], for the particles listed in `indices` (count `n`).
  virtual void evaluate(const double* rho, const double* u, double* P, double* cs,
                        const std::size_t* indices, std::size_t n) const = 0;
  // Single-point forms, for set-up and tests.
  virtual double pressure(double rho, double u) const = 0;
  virtual double soundSpeed(double rho, double u) const = 0;
  // Specific internal energy giving pressure P at density rho (used to set bodies up from a
  // pressure). Throws std::domain_error when no such energy exists.
  virtual double specificEnergy(double rho, double P) const = 0;
  // Whether a negative specific internal energy is unphysical for this material (a gas: negative
  // pressure and temperature). Solids and their cold curves may dip below u = 0 (elastic
  // unloading, expansion), so only gases are checked.
  virtual bool requiresPositiveEnergy() const { return false; }
  // The density at which P = 0 with u = 0 [kg/m^3] (the solid's reference density), or 0 where
  // the form has none (gases, explosives): what a porous material's matrix is compacted to.
  virtual double referenceDensity() const { return 0.0; }
  // dP/drho at constant u and dP/du at constant rho (a porous matrix's response,
  // sim/solid/porosity.hpp). The default differences the pressure: central, or forward where
  // the step would cross u = 0 (the solid forms evaluate u < 0 as 0, a kink there).
  struct Slopes {
    double dRho = 0.0;
    double dU = 0.0;
  };
  virtual Slopes pressureSlopes(double rho, double u) const;
};

// Ideal (gamma-law) gas: P = (gamma - 1) rho u, c^2 = gamma P / rho.
class IdealGas final : public EquationOfState {
 public:
  explicit IdealGas(double gamma);
  std::string name() const override { return "ideal_gas"; }
  void evaluate(const double* rho, const double* u, double* P, double* cs,
                const std::size_t* indices, std::size_t n) const override;
  double pressure(double rho, double u) const override;
  double soundSpeed(double rho, double u) const override;
  double specificEnergy(double rho, double P) const override;
  bool requiresPositiveEnergy() const override { return true; }
  double gamma() const { return gamma_; }

 private:
  double gamma_;
};

}  // namespace ejecta
