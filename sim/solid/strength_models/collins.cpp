#include "sim/solid/strength_models/collins.hpp"

#include <algorithm>
#include <stdexcept>

namespace ejecta {

double intactRockStrength(const CollinsParameters& c, double P) {
  if (P < 0.0) return std::max(c.cohesion + c.frictionIntact * P, 0.0);
  const double rise = c.frictionIntact * P;
  return c.cohesion + rise / (1.0 + rise / (c.strengthLimit - c.cohesion));
}

double damagedRockStrength(const CollinsParameters& c, double P) {
  const double friction = std::max(c.cohesionDamaged + c.frictionDamaged * P, 0.0);
  return std::min(friction, intactRockStrength(c, P));
}

double rockStrength(const CollinsParameters& c, double P, double D) {
  const double d = std::clamp(D, 0.0, 1.0);
  return (1.0 - d) * intactRockStrength(c, P) + d * damagedRockStrength(c, P);
}

double CollinsYield::flowStress(double, double, double, double, double pressure,
                                double damage) const {
  return rockStrength(c_, pressure, damage);
}

StrengthModelRow collinsStrengthRow() {
  using namespace config::keys;
  const Dimension kPa = Dimension::Pressure;
  return {"collins",
          "pressure-dependent rock, Collins et al. (2004): intact Lundborg curve, damaged Coulomb line",
          {cohesionKey(),
           number("friction_intact", "required for collins", "intact friction coefficient μ_i, > 0"),
           strengthLimitKey(),
           number("friction_damaged", "required for collins", "damaged friction coefficient μ_d"),
           quantity("cohesion_damaged", kPa, "0",
                    "damaged cohesion Y_d0: Y_d = Y_d0 + μ_d P (0, as in Collins et al.)")},
          {"cohesion", "friction_intact", "strength_limit", "friction_damaged"},
          [](const ModelSpec& s, const StrengthLibraryEntry*) -> std::shared_ptr<const YieldSurface> {
            CollinsParameters c;
            c.cohesion = s.valueOr("cohesion", 0.0);
            c.frictionIntact = s.valueOr("friction_intact", 0.0);
            c.strengthLimit = s.valueOr("strength_limit", 0.0);
            c.frictionDamaged = s.valueOr("friction_damaged", 0.0);
            c.cohesionDamaged = s.valueOr("cohesion_damaged", 0.0);  // Collins et al. (2004): none
            if (!(c.frictionIntact > 0.0))
              throw std::invalid_argument("strength.friction_intact must be positive");
            if (!(c.strengthLimit > c.cohesion))
              throw std::invalid_argument(
                  "strength.strength_limit must exceed strength.cohesion (the Lundborg curve rises "
                  "from the cohesion to the limit)");
            return std::make_shared<CollinsYield>(c);
          }};
}

}  // namespace ejecta
