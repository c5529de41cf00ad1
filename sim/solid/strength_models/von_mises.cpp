#include "sim/solid/strength_models/von_mises.hpp"

#include "sim/solid/strength_library.hpp"

namespace ejecta {

double VonMisesYield::flowStress(double, double, double, double, double, double) const {
  return yieldStress_;
}

StrengthModelRow vonMisesStrengthRow() {
  using namespace config::keys;
  return {"von_mises",
          "perfectly plastic, yield stress Y",
          {quantity("yield_stress", Dimension::Pressure, "required for von_mises",
                    "von Mises yield stress Y")},
          {"yield_stress"},
          [](const ModelSpec& s, const StrengthLibraryEntry* entry) -> std::shared_ptr<const YieldSurface> {
            return std::make_shared<VonMisesYield>(s.valueOr("yield_stress", entry ? entry->yieldStress : 0.0));
          }};
}

}  // namespace ejecta
