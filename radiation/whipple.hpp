#pragma once
// Whipple-shield ballistic-limit equations (BLE): the largest projectile a bumper + rear-wall
// shield stops, as a function of impact speed and angle, in NASA JSC's three regimes
// (Christiansen 1993, Int. J. Impact Eng. 14, 145-156; NASA TP-2003-210788, 2003), the source's
// sizing equations, and the inverse design form (the rear wall that stops a given threat).
// docs/whipple.md gives the equations, the seed's errata (its eqs. 5.1-5.3) and the examples.
//
// The API is SI (m, kg/m^3, m/s, Pa, rad); the equations are evaluated in their own units (cm,
// g/cm^3, km/s, ksi) with the conversions below. Inputs are validated: std::invalid_argument
// names the parameter and the reason.
#include <numbers>
#include <string_view>
#include <vector>

namespace ejecta::radiation {

// Units of the empirical equations. 1 ksi = 1000 lbf/in^2 with the international pound-force
// 4.4482216152605 N and inch 0.0254 m (both exact: NIST SP 811, 2008, app. B.8 and B.9):
// 4448.2216152605 / 0.0254^2 = 6.894757293168361e6 Pa.
inline constexpr double kPascalPerKsi = 6.894757293168361e6;
inline constexpr double kMetrePerCentimetre = 1e-2;
inline constexpr double kKgPerM3PerGPerCm3 = 1e3;   // 1 g/cm^3 = 1000 kg/m^3
inline constexpr double kMetrePerSecondPerKmPerSecond = 1e3;

// Regime boundaries in normal speed V cos(theta) [m/s] (Christiansen 1993): ballistic (the
// projectile stays intact) up to 3 km/s, hypervelocity (projectile melts or vaporises in the
// bumper) from 7 km/s, and shatter (fragmentation; a straight line in V between the two) between.
inline constexpr double kBallisticNormalSpeedLimit = 3e3;
inline constexpr double kHypervelocityNormalSpeedLimit = 7e3;

enum class WhippleRegime { Ballistic, Shatter, Hypervelocity };
std::string_view regimeName(WhippleRegime regime);  // "ballistic", "shatter", "hypervelocity"

struct WhippleShield {
  double bumperThickness = 0.0;   // t_b [m]
  double bumperDensity = 0.0;     // rho_b [kg/m^3]
  double wallThickness = 0.0;     // t_w, the rear wall [m]
  double wallDensity = 0.0;       // [kg/m^3]; areal mass only (the BLE do not use it); 0: unknown
  double wallYieldStress = 0.0;   // sigma, the rear wall's yield stress [Pa]
  double standoff = 0.0;          // S, bumper to rear wall [m]

  // rho_b t_b + rho_w t_w [kg/m^2] (needs wallDensity).
  double arealMass() const;
};

struct WhippleOptions {
  // Obliquities above this are evaluated at it. The cos(theta) terms make d_c grow without bound
  // towards grazing incidence, which tests do not support; NASA JSC's practice, as implemented
  // by Ryan (co-author of the JSC BLE program, NASA/TM-2009-214789) in pyBLOSSUM, is 65 deg.
  // Set to pi/2 to use the equations as printed.
  double maxObliquity = 65.0 * std::numbers::pi / 180.0;  // [rad]
};

struct BallisticLimit {
  double diameter = 0.0;          // d_c, the critical projectile diameter [m]
  WhippleRegime regime = WhippleRegime::Ballistic;
  double normalSpeed = 0.0;       // V cos(theta_eff) [m/s]
  double effectiveAngle = 0.0;    // theta after the obliquity cap [rad]
};

// Validates the shield (every field finite and > 0, wallDensity >= 0); throws
// std::invalid_argument naming the field.
void validateShield(const WhippleShield& shield);

// The speeds [m/s] at which the regime changes for this impact angle: V = 3 km/s / cos(theta)
// and 7 km/s / cos(theta) (theta after the cap).
struct RegimeBoundaries {
  double ballisticLimit = 0.0;      // ballistic for V <= this
  double hypervelocityLimit = 0.0;  // hypervelocity for V >= this
};
RegimeBoundaries regimeBoundaries(double impactAngle, const WhippleOptions& options = {});

// d_c for a spherical projectile of the given density [kg/m^3] at `speed` [m/s] and impact angle
// [rad] from the bumper's normal, in [0, pi/2). Speed must be > 0.
BallisticLimit criticalDiameter(const WhippleShield& shield, double projectileDensity, double speed,
                                double impactAngle, const WhippleOptions& options = {});

// Whether the bumper is thick enough for the BLE's assumption that it breaks up the projectile:
// t_b >= c_b d rho_p / rho_b (Christiansen 1993; c_b of christiansenSizing).
bool bumperAdequate(const WhippleShield& shield, double projectileDensity, double diameter);

// The thinnest rear wall [m] for which d_c equals `diameter` at this speed and angle, the other
// shield fields as given (wallThickness is ignored): the BLE solved for t_w in whichever regime
// the speed falls (closed form in the ballistic and hypervelocity regimes, bisection in shatter,
// where d_c is increasing in t_w). 0 when the bumper alone already gives d_c >= diameter.
double requiredWallThickness(const WhippleShield& shield, double projectileDensity, double diameter,
                             double speed, double impactAngle, const WhippleOptions& options = {});

// The source's design equations for a projectile of diameter d (Christiansen 1993, for normal
// speeds >= 7 km/s), in its units [cm, g/cm^3, g, km/s, ksi]:
//   t_b = c_b d rho_p / rho_b,  c_b = 0.25 for S/d < 30, 0.20 for S/d >= 30;
//   t_w = c_w d^0.5 (rho_p rho_b)^(1/6) m_p^(1/3) V_n S^-0.5 (70/sigma)^0.5,  c_w = 0.16,
// with m_p = pi/6 d^3 rho_p. The t_w form is the hypervelocity BLE solved for t_w, with the
// constants rounded (0.16 (pi/6)^(1/3) = 0.12897 against 3.918^-1.5 = 0.12894).
struct WhippleSizing {
  double bumperThickness = 0.0;      // [m]
  double wallThickness = 0.0;        // [m]
  double bumperCoefficient = 0.0;    // c_b
  bool inRange = false;              // V cos(theta_eff) >= 7 km/s, where the equations apply
};
WhippleSizing christiansenSizing(double projectileDensity, double diameter, double speed, double impactAngle,
                                 double bumperDensity, double wallYieldStress, double standoff,
                                 const WhippleOptions& options = {});

// The ballistic-limit curve: `samples` speeds evenly spaced in [speedMin, speedMax] [m/s], plus
// the regime boundaries that fall strictly inside (so a plot has its corners), sorted.
struct BallisticLimitPoint {
  double speed = 0.0;  // [m/s]
  BallisticLimit limit;
};
std::vector<BallisticLimitPoint> ballisticLimitCurve(const WhippleShield& shield, double projectileDensity,
                                                     double impactAngle, double speedMin, double speedMax,
                                                     int samples, const WhippleOptions& options = {});

}  // namespace ejecta::radiation
