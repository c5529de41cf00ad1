#include "sim/fracture.hpp"

#include <cmath>

namespace ejecta {

double crackGrowthRate(std::uint32_t activeFlaws, std::uint32_t totalFlaws, double crack,
                       double longitudinalSpeed, double particleRadius, double crackSpeedFactor) {
  if (activeFlaws == 0 || totalFlaws == 0) return 0.0;
  // Damage cannot exceed the fraction of flaws activated (each crack relieves its own volume).
  const double cap = std::cbrt(static_cast<double>(activeFlaws) / totalFlaws);
  if (crack >= cap) return 0.0;
  // Linear in the number of active flaws, as miluphcuda implements Benz & Asphaug (1995); the
  // growth speed only sets how fast the cap above is reached (docs/materials.md).
  return static_cast<double>(activeFlaws) * crackSpeedFactor * longitudinalSpeed / particleRadius;
}

}  // namespace ejecta
