#include "sim/exact/underwater_explosion_laws.hpp"

#include <cmath>

namespace ejecta::exact {

double SimilitudeLaw::peakPressure(double chargeMass, double distance) const {
  return peakCoefficient * std::pow(std::cbrt(chargeMass) / distance, peakExponent);
}

double SimilitudeLaw::decayTime(double chargeMass, double distance) const {
  const double w3 = std::cbrt(chargeMass);
  return decayCoefficient * w3 * std::pow(w3 / distance, decayExponent);
}

}  // namespace ejecta::exact
