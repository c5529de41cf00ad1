#include "fields/crater_scaling.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

#include "core/join.hpp"

namespace ejecta::fields {

const std::vector<CraterScalingLaw>& craterScalingClasses() {
  // K1, mu and Y from Holsapple's notes to his crater-size spreadsheet ("Notes on Crater Scaling
  // Results", after Holsapple 1993 and Schmidt & Housen 1987, Int. J. Impact Eng. 5, 543-560),
  // his table of the volume parameters; Y given there in MPa. K_r = 1.33: the notes' rule "for
  // the crater radius in the soils and rocks"; it is used for water too (the notes' text on
  // the other classes was not readable).
  static const std::vector<CraterScalingLaw> classes = {
      {"water", 0.98, 0.55, 0.0, 1.33},
      {"dry_sand", 0.132, 0.41, 0.0, 1.33},
      {"dry_soil", 0.132, 0.41, 0.065e6, 1.33},
      {"wet_soil", 0.095, 0.55, 0.44e6, 1.33},
      {"soft_rock", 0.095, 0.55, 3.0e6, 1.33},
      {"hard_rock", 0.095, 0.55, 6.9e6, 1.33},
  };
  return classes;
}

const CraterScalingLaw* craterScalingClass(std::string_view name) {
  for (const CraterScalingLaw& law : craterScalingClasses())
    if (law.name == name) return &law;
  return nullptr;
}

std::string craterScalingClassNames() {
  return joinList(craterScalingClasses(), &CraterScalingLaw::name);
}

namespace {

void requirePositive(double value, const char* what, bool zeroAllowed = false) {
  if (std::isfinite(value) && value >= 0.0 && (zeroAllowed || value > 0.0)) return;
  char text[64];
  std::snprintf(text, sizeof text, "%g", value);
  throw std::invalid_argument(std::string("the ") + what + " is " + text +
                              (zeroAllowed ? " (must be finite and >= 0)" : " (must be finite and > 0)"));
}

}  // namespace

ScaledCrater scaleCrater(const CraterScalingLaw& law, const ScalingImpact& impact) {
  requirePositive(impact.impactorMass, "impactor's mass");
  requirePositive(impact.impactorRadius, "impactor's radius");
  requirePositive(impact.speed, "impact speed");
  requirePositive(impact.targetDensity, "target's density");
  requirePositive(impact.gravity, "surface gravity", true);
  if (impact.gravity == 0.0 && law.strength == 0.0)
    throw std::invalid_argument("class '" + law.name +
                                "' has no strength, so only gravity stops its crater; the "
                                "surface gravity is 0");
  ScaledCrater c;
  const double u2 = impact.speed * impact.speed;
  c.pi2 = impact.gravity * impact.impactorRadius / u2;
  c.pi3 = law.strength / (impact.targetDensity * u2);
  const double strengthTerm = std::pow(c.pi3, (2.0 + law.mu) / 2.0);
  c.strengthRegime = strengthTerm > c.pi2;
  c.piV = law.k1 * std::pow(c.pi2 + strengthTerm, -3.0 * law.mu / (2.0 + law.mu));
  c.volume = c.piV * impact.impactorMass / impact.targetDensity;
  c.radius = law.radiusFactor * std::cbrt(c.volume);
  c.depth = 2.0 * c.volume / (std::numbers::pi * c.radius * c.radius);
  return c;
}

}  // namespace ejecta::fields
