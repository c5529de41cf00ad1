#pragma once
// The crater that point-source (pi-group) scaling predicts for an impact, to set beside the one a
// run measures (docs/crater.md, "Against pi-group scaling").
//
// Holsapple (1993), Annu. Rev. Earth Planet. Sci. 21, 333-373, in the form of Holsapple's notes
// to his crater-size spreadsheet (the six material classes below):
//   pi_V = rho V / m = K1 [ pi_2 + pi_3^((2 + mu)/2) ]^(-3 mu / (2 + mu)),
//   pi_2 = g a / U^2,   pi_3 = Y / (rho U^2),
// with m, a and U the impactor's mass, radius and speed, rho the target's density, g its surface
// gravity and Y its effective strength. The crater radius at the original surface is
// R = K_r V^(1/3); the depth given here is that of a paraboloid bowl of that volume and radius,
// d = 2 V / (pi R^2) (the notes give no depth rule).
#include <string>
#include <string_view>
#include <vector>

namespace ejecta::fields {

struct CraterScalingLaw {
  std::string name;           // the class, as a scene names it ("hard_rock")
  double k1 = 0.0;            // K1
  double mu = 0.0;            // the velocity exponent mu (alpha = 3 mu / (2 + mu))
  double strength = 0.0;      // the effective strength Y [Pa]
  double radiusFactor = 0.0;  // K_r in R = K_r V^(1/3)
};

// Holsapple's six classes: water, dry_sand, dry_soil, wet_soil, soft_rock, hard_rock.
const std::vector<CraterScalingLaw>& craterScalingClasses();
// The class of that name, or nullptr.
const CraterScalingLaw* craterScalingClass(std::string_view name);
// "water, dry_sand, ..." for messages and docs.
std::string craterScalingClassNames();

// What the scaling needs to know of an impact, in SI units.
struct ScalingImpact {
  double impactorMass = 0.0;    // m [kg]
  double impactorRadius = 0.0;  // a [m] (a non-spherical impactor: the sphere of its volume)
  double speed = 0.0;           // U [m/s]: the full speed (an oblique impact scaled as normal)
  double targetDensity = 0.0;   // rho [kg/m^3]
  double gravity = 0.0;         // g [m/s^2] at the target's surface
};

struct ScaledCrater {
  double pi2 = 0.0, pi3 = 0.0, piV = 0.0;
  double volume = 0.0;  // [m^3], below the original surface
  double radius = 0.0;  // [m], at the original surface
  double depth = 0.0;   // [m], of the paraboloid of that volume and radius
  bool strengthRegime = false;  // pi_3^((2 + mu)/2) > pi_2: strength, not gravity, stops it
};

// Throws std::invalid_argument when an input is not positive and finite (gravity may be 0 where
// the strength is not), naming it (the message has no prefix: the caller says where).
ScaledCrater scaleCrater(const CraterScalingLaw& law, const ScalingImpact& impact);

}  // namespace ejecta::fields
