#include "sim/solid/fracture.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ejecta {

double crackCap(std::uint32_t activeFlaws, std::uint32_t totalFlaws) {
  if (totalFlaws == 0) return 1.0;
  return std::cbrt(static_cast<double>(activeFlaws) / totalFlaws);
}

double crackGrowthRate(std::uint32_t activeFlaws, std::uint32_t totalFlaws, double crack,
                       double longitudinalSpeed, double particleRadius, double crackSpeedFactor) {
  if (activeFlaws == 0 || totalFlaws == 0) return 0.0;
  if (crack >= crackCap(activeFlaws, totalFlaws)) return 0.0;
  // Linear in the number of active flaws, as miluphcuda implements Benz & Asphaug (1995); the
  // growth speed only sets how fast the cap above is reached (docs/materials.md).
  return static_cast<double>(activeFlaws) * crackSpeedFactor * longitudinalSpeed / particleRadius;
}

double advanceCrack(double crack, double rate, double dt, double cap) {
  return std::min({crack + dt * rate, std::max(crack, cap), 1.0});
}

double crackStepLimit(double rate, double maxIncrement) {
  return rate > 0.0 ? maxIncrement / rate : std::numeric_limits<double>::infinity();
}

double intactLongitudinalSpeed(double bulk, double shear, double density) {
  return std::sqrt((bulk + 4.0 * shear / 3.0) / density);
}

}  // namespace ejecta
