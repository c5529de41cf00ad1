// Whipple-shield ballistic-limit equations in NASA JSC's units (cm, g/cm^3, km/s, ksi).
// docs/whipple.md.
#include "radiation/whipple.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "radiation/format_number.hpp"

namespace ejecta::radiation {

namespace {

// Coefficients of Christiansen (1993), eqs. for the Whipple shield (NASA TP-2003-210788 prints
// the same): ballistic 0.6 and exponent 18/19 with the (sigma/40)^0.5 wall term; hypervelocity
// 3.918 with (sigma/70)^(1/3); sizing c_w = 0.16, c_b = 0.25 / 0.20 (S/d below / from 30).
constexpr double kBallisticCoefficient = 0.6;
constexpr double kBallisticExponent = 18.0 / 19.0;
constexpr double kBallisticYieldReference = 40.0;   // [ksi]
constexpr double kHypervelocityCoefficient = 3.918;
constexpr double kHypervelocityYieldReference = 70.0;  // [ksi]
constexpr double kWallSizingCoefficient = 0.16;
constexpr double kBumperSizingCoefficientClose = 0.25;  // S/d < 30
constexpr double kBumperSizingCoefficientFar = 0.20;    // S/d >= 30
constexpr double kBumperSizingStandoffRatio = 30.0;

void requirePositive(double x, const char* name) {
  if (!std::isfinite(x) || !(x > 0.0))
    throw std::invalid_argument(std::string(name) + " must be finite and > 0, got " + formatNumber("%g", x));
}

void requireAngle(double theta) {
  if (!std::isfinite(theta) || theta < 0.0 || theta >= std::numbers::pi / 2)
    throw std::invalid_argument("impact angle must be in [0, 90) deg from the bumper normal, got " +
                                formatNumber("%g", theta * 180.0 / std::numbers::pi) + " deg");
}

double effectiveAngle(double theta, const WhippleOptions& options) {
  requireAngle(theta);
  if (!std::isfinite(options.maxObliquity) || !(options.maxObliquity > 0.0) ||
      options.maxObliquity > std::numbers::pi / 2)
    throw std::invalid_argument("maxObliquity must be in (0, 90] deg, got " +
                                formatNumber("%g", options.maxObliquity * 180.0 / std::numbers::pi) + " deg");
  return std::min(theta, options.maxObliquity);
}

// The shield and projectile in the equations' units.
struct BleUnits {
  double tb, tw, S, sigma;  // cm, cm, cm, ksi
  double rhoB, rhoP;        // g/cm^3
  double cosTheta;
};

BleUnits toBleUnits(const WhippleShield& s, double projectileDensity, double theta) {
  return {s.bumperThickness / kMetrePerCentimetre, s.wallThickness / kMetrePerCentimetre,
          s.standoff / kMetrePerCentimetre, s.wallYieldStress / kPascalPerKsi,
          s.bumperDensity / kKgPerM3PerGPerCm3, projectileDensity / kKgPerM3PerGPerCm3, std::cos(theta)};
}

// Ballistic regime at speed v [km/s]: d_c [cm].
double ballisticDiameter(const BleUnits& u, double v) {
  const double resistance = u.tw * std::sqrt(u.sigma / kBallisticYieldReference) + u.tb;
  return std::pow(resistance / (kBallisticCoefficient * std::pow(u.cosTheta, 5.0 / 3.0) * std::sqrt(u.rhoP) *
                                std::pow(v, 2.0 / 3.0)),
                  kBallisticExponent);
}

// The hypervelocity factor without t_w^(2/3): d_c = factor * t_w^(2/3) [cm].
double hypervelocityFactor(const BleUnits& u, double v) {
  return kHypervelocityCoefficient * std::pow(u.rhoP, -1.0 / 3.0) * std::pow(u.rhoB, -1.0 / 9.0) *
         std::pow(v * u.cosTheta, -2.0 / 3.0) * std::cbrt(u.S) * std::cbrt(u.sigma / kHypervelocityYieldReference);
}

double hypervelocityDiameter(const BleUnits& u, double v) {
  return hypervelocityFactor(u, v) * std::pow(u.tw, 2.0 / 3.0);
}

// d_c [cm] at v [km/s] with the regime speeds vLow, vHigh [km/s]: shatter is the straight line
// in V from the ballistic value at vLow to the hypervelocity value at vHigh.
double diameterAt(const BleUnits& u, double v, double vLow, double vHigh, WhippleRegime regime) {
  switch (regime) {
    case WhippleRegime::Ballistic: return ballisticDiameter(u, v);
    case WhippleRegime::Hypervelocity: return hypervelocityDiameter(u, v);
    case WhippleRegime::Shatter: break;
  }
  const double w = (v - vLow) / (vHigh - vLow);
  return (1.0 - w) * ballisticDiameter(u, vLow) + w * hypervelocityDiameter(u, vHigh);
}

WhippleRegime regimeOf(double speed, const RegimeBoundaries& b) {
  if (speed <= b.ballisticLimit) return WhippleRegime::Ballistic;
  if (speed >= b.hypervelocityLimit) return WhippleRegime::Hypervelocity;
  return WhippleRegime::Shatter;
}

double bumperCoefficient(double standoff, double diameter) {
  return standoff / diameter < kBumperSizingStandoffRatio ? kBumperSizingCoefficientClose
                                                          : kBumperSizingCoefficientFar;
}

}  // namespace

std::string_view regimeName(WhippleRegime regime) {
  switch (regime) {
    case WhippleRegime::Ballistic: return "ballistic";
    case WhippleRegime::Shatter: return "shatter";
    case WhippleRegime::Hypervelocity: return "hypervelocity";
  }
  return "unknown";
}

double WhippleShield::arealMass() const {
  return bumperDensity * bumperThickness + wallDensity * wallThickness;
}

void validateShield(const WhippleShield& s) {
  requirePositive(s.bumperThickness, "bumper thickness");
  requirePositive(s.bumperDensity, "bumper density");
  requirePositive(s.wallThickness, "rear wall thickness");
  requirePositive(s.wallYieldStress, "rear wall yield stress");
  requirePositive(s.standoff, "standoff");
  if (!std::isfinite(s.wallDensity) || s.wallDensity < 0.0)
    throw std::invalid_argument("rear wall density must be finite and >= 0, got " + formatNumber("%g", s.wallDensity));
}

RegimeBoundaries regimeBoundaries(double impactAngle, const WhippleOptions& options) {
  const double c = std::cos(effectiveAngle(impactAngle, options));
  return {kBallisticNormalSpeedLimit / c, kHypervelocityNormalSpeedLimit / c};
}

BallisticLimit criticalDiameter(const WhippleShield& shield, double projectileDensity, double speed,
                                double impactAngle, const WhippleOptions& options) {
  validateShield(shield);
  requirePositive(projectileDensity, "projectile density");
  requirePositive(speed, "impact speed");
  const double theta = effectiveAngle(impactAngle, options);
  const RegimeBoundaries b = regimeBoundaries(theta, options);
  const BleUnits u = toBleUnits(shield, projectileDensity, theta);
  const double k = kMetrePerSecondPerKmPerSecond;
  BallisticLimit r;
  r.regime = regimeOf(speed, b);
  r.diameter = diameterAt(u, speed / k, b.ballisticLimit / k, b.hypervelocityLimit / k, r.regime) *
               kMetrePerCentimetre;
  r.normalSpeed = speed * u.cosTheta;
  r.effectiveAngle = theta;
  return r;
}

bool bumperAdequate(const WhippleShield& shield, double projectileDensity, double diameter) {
  validateShield(shield);
  requirePositive(projectileDensity, "projectile density");
  requirePositive(diameter, "projectile diameter");
  return shield.bumperThickness >=
         bumperCoefficient(shield.standoff, diameter) * diameter * projectileDensity / shield.bumperDensity;
}

double requiredWallThickness(const WhippleShield& shield, double projectileDensity, double diameter,
                             double speed, double impactAngle, const WhippleOptions& options) {
  WhippleShield s = shield;
  s.wallThickness = 1.0;  // placeholder so the shield validates; the unknown
  validateShield(s);
  requirePositive(projectileDensity, "projectile density");
  requirePositive(diameter, "projectile diameter");
  requirePositive(speed, "impact speed");
  const double theta = effectiveAngle(impactAngle, options);
  const RegimeBoundaries b = regimeBoundaries(theta, options);
  const WhippleRegime regime = regimeOf(speed, b);
  const double k = kMetrePerSecondPerKmPerSecond;
  const double v = speed / k, vLow = b.ballisticLimit / k, vHigh = b.hypervelocityLimit / k;
  const double d = diameter / kMetrePerCentimetre;
  BleUnits u = toBleUnits(s, projectileDensity, theta);

  if (regime == WhippleRegime::Ballistic) {
    // (t_w (sigma/40)^0.5 + t_b) = d^(19/18) 0.6 cos^(5/3) rho_p^0.5 V^(2/3)
    const double resistance = std::pow(d, 1.0 / kBallisticExponent) * kBallisticCoefficient *
                              std::pow(u.cosTheta, 5.0 / 3.0) * std::sqrt(u.rhoP) * std::pow(v, 2.0 / 3.0);
    const double tw = (resistance - u.tb) / std::sqrt(u.sigma / kBallisticYieldReference);
    return std::max(tw, 0.0) * kMetrePerCentimetre;
  }
  if (regime == WhippleRegime::Hypervelocity)
    return std::pow(d / hypervelocityFactor(u, v), 1.5) * kMetrePerCentimetre;

  // Shatter: d_c is increasing in t_w (both end points are), so bracket and bisect.
  auto excess = [&](double tw) {
    u.tw = tw;
    return diameterAt(u, v, vLow, vHigh, regime) - d;
  };
  if (excess(0.0) >= 0.0) return 0.0;
  double lo = 0.0, hi = std::max(u.tb, d);
  while (excess(hi) < 0.0) {
    lo = hi;
    hi *= 2.0;
    if (!std::isfinite(hi)) throw std::runtime_error("requiredWallThickness: no bracket found");
  }
  for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (excess(mid) < 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi) * kMetrePerCentimetre;
}

WhippleSizing christiansenSizing(double projectileDensity, double diameter, double speed, double impactAngle,
                                 double bumperDensity, double wallYieldStress, double standoff,
                                 const WhippleOptions& options) {
  requirePositive(projectileDensity, "projectile density");
  requirePositive(diameter, "projectile diameter");
  requirePositive(speed, "impact speed");
  requirePositive(bumperDensity, "bumper density");
  requirePositive(wallYieldStress, "rear wall yield stress");
  requirePositive(standoff, "standoff");
  const double theta = effectiveAngle(impactAngle, options);
  const double d = diameter / kMetrePerCentimetre, S = standoff / kMetrePerCentimetre;
  const double rhoP = projectileDensity / kKgPerM3PerGPerCm3, rhoB = bumperDensity / kKgPerM3PerGPerCm3;
  const double vn = speed * std::cos(theta) / kMetrePerSecondPerKmPerSecond;
  const double sigma = wallYieldStress / kPascalPerKsi;
  const double mass = std::numbers::pi / 6.0 * d * d * d * rhoP;  // [g]
  WhippleSizing r;
  r.bumperCoefficient = bumperCoefficient(standoff, diameter);
  r.bumperThickness = r.bumperCoefficient * d * rhoP / rhoB * kMetrePerCentimetre;
  r.wallThickness = kWallSizingCoefficient * std::sqrt(d) * std::pow(rhoP * rhoB, 1.0 / 6.0) * std::cbrt(mass) *
                    vn / std::sqrt(S) * std::sqrt(kHypervelocityYieldReference / sigma) * kMetrePerCentimetre;
  r.inRange = speed * std::cos(theta) >= kHypervelocityNormalSpeedLimit * (1.0 - 1e-12);
  return r;
}

std::vector<BallisticLimitPoint> ballisticLimitCurve(const WhippleShield& shield, double projectileDensity,
                                                     double impactAngle, double speedMin, double speedMax,
                                                     int samples, const WhippleOptions& options) {
  requirePositive(speedMin, "lowest curve speed");
  requirePositive(speedMax, "highest curve speed");
  if (!(speedMax > speedMin))
    throw std::invalid_argument("highest curve speed (" + formatNumber("%g", speedMax) +
                                " m/s) must exceed the lowest (" + formatNumber("%g", speedMin) + " m/s)");
  if (samples < 2) throw std::invalid_argument("a curve needs at least 2 samples, got " + std::to_string(samples));
  std::vector<double> speeds;
  speeds.reserve(static_cast<std::size_t>(samples) + 2);
  for (int i = 0; i < samples; ++i) speeds.push_back(speedMin + (speedMax - speedMin) * i / (samples - 1));
  const RegimeBoundaries b = regimeBoundaries(impactAngle, options);
  const double spacing = (speedMax - speedMin) / (samples - 1);
  for (double corner : {b.ballisticLimit, b.hypervelocityLimit}) {
    if (!(corner > speedMin && corner < speedMax)) continue;
    const auto near = std::find_if(speeds.begin(), speeds.end(),
                                   [&](double v) { return std::abs(v - corner) < 1e-9 * spacing; });
    if (near != speeds.end())
      *near = corner;  // a sample within rounding of the corner is the corner
    else
      speeds.push_back(corner);
  }
  std::sort(speeds.begin(), speeds.end());
  std::vector<BallisticLimitPoint> curve;
  curve.reserve(speeds.size());
  for (double v : speeds) curve.push_back({v, criticalDiameter(shield, projectileDensity, v, impactAngle, options)});
  return curve;
}

}  // namespace ejecta::radiation
