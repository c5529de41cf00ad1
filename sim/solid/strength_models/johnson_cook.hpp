#pragma once
// model = "johnson_cook": Johnson & Cook (1983), (A + B eps_p^n)(1 + C ln eps_dot*)(1 - T*^m).
#include "sim/solid/strength_catalog.hpp"

namespace ejecta {

struct JohnsonCookParameters {
  double A = 0.0;                     // yield stress [Pa]
  double B = 0.0;                     // hardening modulus [Pa]
  double n = 1.0;                     // hardening exponent
  double C = 0.0;                     // strain-rate constant
  double m = 1.0;                     // thermal-softening exponent
  double referenceStrainRate = 1.0;   // eps_dot_0 [1/s]
  double roomTemperature = 293.0;     // T_room of the homologous temperature [K]
};

class JohnsonCookYield final : public YieldSurface {
 public:
  explicit JohnsonCookYield(const JohnsonCookParameters& p) : p_(p) {}
  const JohnsonCookParameters& parameters() const { return p_; }
  double flowStress(double epsP, double strainRate, double temperature, double meltTemperature,
                    double pressure, double damage) const override;

 private:
  JohnsonCookParameters p_;
};

StrengthModelRow johnsonCookStrengthRow();

}  // namespace ejecta
