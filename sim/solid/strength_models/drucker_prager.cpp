#include "sim/solid/strength_models/drucker_prager.hpp"

#include <algorithm>
#include <stdexcept>

namespace ejecta {

double druckerPragerStrength(const DruckerPragerParameters& c, double P) {
  return std::min(std::max(c.cohesion + c.friction * P, 0.0), c.strengthLimit);
}

double DruckerPragerYield::flowStress(double, double, double, double, double pressure,
                                      double) const {
  return druckerPragerStrength(c_, pressure);
}

StrengthModelRow druckerPragerStrengthRow() {
  using namespace config::keys;
  return {"drucker_prager",
          "frictional (granular, damaged) material: Y = min(Y_0 + μ P, Y_M), damage does not weaken it",
          {cohesionKey(),
           number("friction", "required for drucker_prager", "friction coefficient μ = dY/dP, > 0"),
           strengthLimitKey()},
          {"cohesion", "friction", "strength_limit"},
          [](const ModelSpec& s, const StrengthLibraryEntry*) -> std::shared_ptr<const YieldSurface> {
            DruckerPragerParameters c;
            c.cohesion = s.valueOr("cohesion", 0.0);
            c.friction = s.valueOr("friction", 0.0);
            c.strengthLimit = s.valueOr("strength_limit", 0.0);
            if (!(c.cohesion >= 0.0))
              throw std::invalid_argument("strength.cohesion must not be negative");
            if (!(c.friction > 0.0))
              throw std::invalid_argument("strength.friction must be positive (a frictionless "
                                          "surface is von_mises)");
            if (!(c.strengthLimit > c.cohesion))
              throw std::invalid_argument(
                  "strength.strength_limit must exceed strength.cohesion (the line rises from "
                  "the cohesion to the limit)");
            return std::make_shared<DruckerPragerYield>(c);
          }};
}

}  // namespace ejecta
