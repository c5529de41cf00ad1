#pragma once
// model = "von_mises": perfectly plastic, a constant yield stress Y.
#include "sim/solid/strength_catalog.hpp"

namespace ejecta {

class VonMisesYield final : public YieldSurface {
 public:
  explicit VonMisesYield(double yieldStress) : yieldStress_(yieldStress) {}
  double yieldStress() const { return yieldStress_; }
  double flowStress(double epsP, double strainRate, double temperature, double meltTemperature,
                    double pressure, double damage) const override;

 private:
  double yieldStress_;  // Y [Pa]
};

StrengthModelRow vonMisesStrengthRow();

}  // namespace ejecta
