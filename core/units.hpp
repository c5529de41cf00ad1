#pragma once
// Physical quantities written with units ("10 km/s", "2.7 g/cm^3", "100 kt") converted to SI.
// The one unit parser of every input file (scenes, thermal studies, Whipple shield files, the
// command line): any dimensional value may be given either as a plain number (taken as SI) or as a
// string "<number> <unit expression>"; the expected dimension is always known from the key, so
// a value with the wrong dimension is rejected instead of silently misread.
#include <stdexcept>
#include <string>
#include <string_view>

namespace ejecta {

// Exponents of the SI base units kg, m, s, K, and of the radian. SI counts the radian as
// dimensionless; here it is a dimension of its own so that "45 deg" is rejected where a plain
// number is expected (fov_degrees = "30 deg" would otherwise silently read as 0.52).
struct Dimension {
  int mass = 0, length = 0, time = 0, temperature = 0, angle = 0;

  constexpr bool operator==(const Dimension&) const = default;
  constexpr Dimension operator*(const Dimension& o) const {
    return {mass + o.mass, length + o.length, time + o.time, temperature + o.temperature,
            angle + o.angle};
  }
  constexpr Dimension operator/(const Dimension& o) const {
    return {mass - o.mass, length - o.length, time - o.time, temperature - o.temperature,
            angle - o.angle};
  }
  constexpr Dimension pow(int n) const {
    return {mass * n, length * n, time * n, temperature * n, angle * n};
  }

  static const Dimension None, Length, Mass, Time, Temperature, Angle, Velocity, Acceleration,
      Density, Pressure, Energy, SpecificEnergy, Area, Volume, Force, Power;
};

inline constexpr Dimension Dimension::None{0, 0, 0, 0};
inline constexpr Dimension Dimension::Length{0, 1, 0, 0};
inline constexpr Dimension Dimension::Mass{1, 0, 0, 0};
inline constexpr Dimension Dimension::Time{0, 0, 1, 0};
inline constexpr Dimension Dimension::Temperature{0, 0, 0, 1};
inline constexpr Dimension Dimension::Angle{0, 0, 0, 0, 1};
inline constexpr Dimension Dimension::Velocity{0, 1, -1, 0};
inline constexpr Dimension Dimension::Acceleration{0, 1, -2, 0};
inline constexpr Dimension Dimension::Density{1, -3, 0, 0};
inline constexpr Dimension Dimension::Pressure{1, -1, -2, 0};
inline constexpr Dimension Dimension::Energy{1, 2, -2, 0};
inline constexpr Dimension Dimension::SpecificEnergy{0, 2, -2, 0};
inline constexpr Dimension Dimension::Area{0, 2, 0, 0};
inline constexpr Dimension Dimension::Volume{0, 3, 0, 0};
inline constexpr Dimension Dimension::Force{1, 1, -2, 0};
inline constexpr Dimension Dimension::Power{1, 2, -3, 0};

// "a density (kg/m^3)"; dimensions without a name are written out: "a quantity in kg m^-1 s^-1".
std::string describeDimension(Dimension d);
// The SI unit of d: "kg/m^3", "m/s", "rad", "" for dimensionless.
std::string siUnit(Dimension d);
// "-0.1 m", "2.5e+09 Pa": a value with its SI unit, for messages.
std::string formatQuantity(double siValue, Dimension d);

class UnitError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// Parses "<number>[ <unit expression>]" into SI. A bare number is taken as SI already. The unit
// expression is a product of unit symbols, each with an optional SI prefix and an integer
// power, joined by '*', '/' or spaces and read left to right ("J/kg/K" = J kg^-1 K^-1).
// "t" is ambiguous (tonne of mass or ton of TNT) and is resolved by `expected`.
// Throws UnitError, e.g. "expected a density (kg/m^3), got a velocity (m/s)".
double parseQuantity(std::string_view text, Dimension expected);

}  // namespace ejecta
