#include "sim/solid/strength_models/elastic.hpp"

#include <limits>

namespace ejecta {

double ElasticYield::flowStress(double, double, double, double, double, double) const {
  return std::numeric_limits<double>::infinity();
}

StrengthModelRow elasticStrengthRow() {
  return {"elastic", "elastic shear stress, no yield", {}, {},
          [](const ModelSpec&, const StrengthLibraryEntry*) -> std::shared_ptr<const YieldSurface> {
            return std::make_shared<ElasticYield>();
          }};
}

}  // namespace ejecta
