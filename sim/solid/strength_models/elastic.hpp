#pragma once
// model = "elastic": no plasticity (rubber, verification of wave speeds): the flow stress is
// infinite below the melting point.
#include "sim/solid/strength_catalog.hpp"

namespace ejecta {

class ElasticYield final : public YieldSurface {
 public:
  double flowStress(double epsP, double strainRate, double temperature, double meltTemperature,
                    double pressure, double damage) const override;
};

StrengthModelRow elasticStrengthRow();

}  // namespace ejecta
