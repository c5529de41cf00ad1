#pragma once
// The crater that point-source (pi-group) scaling predicts for an impact, to set beside the one a
// run measures (docs/crater.md, "Against pi-group scaling"). Two forms, each with its classes:
//
// The volume form, Holsapple (1993), Annu. Rev. Earth Planet. Sci. 21, 333-373, as Holsapple's
// notes to his crater-size spreadsheet give it (six classes, water to hard rock):
//   pi_V = rho V / m = K1 [ pi_2 + pi_3^((2 + mu)/2) ]^(-3 mu / (2 + mu)),
//   pi_2 = g a / U^2,   pi_3 = Y / (rho U^2),
// with m, a and U the impactor's mass, radius and speed, rho the target's density, g its surface
// gravity and Y its effective strength; the radius at the original surface R = K_r V^(1/3).
//
// The radius form, Housen & Holsapple (2011), Icarus 211, 856-875, fitted to laboratory craters
// in porous targets (their Table 3's sand, glass spheres, sand/fly ash and perlite/sand, 35-60%
// porous: the hh2011_ classes), with delta the impactor's density:
//   gravity:  R (rho/m)^(1/3) = H1 (rho/delta)^((2 + mu - 6 nu) / (3 (2 + mu))) pi_2^(-mu/(2 + mu))
//   strength: R (rho/m)^(1/3) = H2 (rho/delta)^((1 - 3 nu) / 3) pi_3^(-mu/2)
// each class fitted in one of the two (were a class fitted in both, the smaller radius: the regime
// that stops the crater first); its volume is taken from R by the same K_r rule, V = (R / K_r)^3.
//
// The depth given in both is that of a paraboloid bowl of that volume and radius,
// d = 2 V / (pi R^2) (neither source gives a depth rule).
#include <string>
#include <string_view>
#include <vector>

namespace ejecta::fields {

struct CraterScalingLaw {
  std::string name;           // the class, as a scene names it ("hard_rock")
  double k1 = 0.0;            // K1 (the volume form)
  double mu = 0.0;            // the velocity exponent mu (alpha = 3 mu / (2 + mu))
  double strength = 0.0;      // the effective strength Y [Pa]
  double radiusFactor = 0.0;  // K_r in R = K_r V^(1/3)
  // The radius form: H1 and H2 (0 where the source fits no such regime) and the density-ratio
  // exponent nu.
  double h1 = 0.0;
  double h2 = 0.0;
  double nu = 1.0 / 3.0;

  bool radiusForm() const { return h1 > 0.0 || h2 > 0.0; }
};

// Holsapple's six classes (water, dry_sand, dry_soil, wet_soil, soft_rock, hard_rock), then
// Housen & Holsapple's (2011) four porous targets (hh2011_sand, hh2011_glass_spheres,
// hh2011_sand_fly_ash, hh2011_perlite_sand).
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
  double strength = 0.0;  // the Y in pi_3 [Pa]: the class's, or the scene's [crater] strength
  double volume = 0.0;  // [m^3], below the original surface
  double radius = 0.0;  // [m], at the original surface
  double depth = 0.0;   // [m], of the paraboloid of that volume and radius
  bool strengthRegime = false;  // pi_3^((2 + mu)/2) > pi_2: strength, not gravity, stops it
};

// Throws std::invalid_argument when an input is not positive and finite (gravity may be 0 where
// the strength is not), naming it (the message has no prefix: the caller says where).
ScaledCrater scaleCrater(const CraterScalingLaw& law, const ScalingImpact& impact);

}  // namespace ejecta::fields
