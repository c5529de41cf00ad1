// Quantities with units (core/units, the parser of scenes, thermal studies and shield files):
// conversions to SI, the tonne / ton-of-TNT ambiguity, angles, dimension errors.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "core/units.hpp"

namespace ejecta {
namespace {

struct Case {
  const char* text;
  Dimension dim;
  double si;
};

TEST(Units, ConvertsToSi) {
  const Case cases[] = {
      {"5", Dimension::Length, 5.0},
      {"  -2.5e3  ", Dimension::Pressure, -2.5e3},
      {"10 km/s", Dimension::Velocity, 1e4},
      {"2.7 g/cm^3", Dimension::Density, 2700.0},
      {"2.7 g cm^-3", Dimension::Density, 2700.0},
      {"2.7 g*cm^-3", Dimension::Density, 2700.0},
      {"1e5 J", Dimension::Energy, 1e5},
      {"0.1 s", Dimension::Time, 0.1},
      {"14 us", Dimension::Time, 14e-6},
      {"14 \xCE\xBCs", Dimension::Time, 14e-6},  // Greek mu
      {"14 \xC2\xB5s", Dimension::Time, 14e-6},  // micro sign
      {"0.0875 m", Dimension::Length, 0.0875},
      {"5 cm", Dimension::Length, 0.05},
      {"1 mm", Dimension::Length, 1e-3},
      {"1 km", Dimension::Length, 1e3},
      {"1 Pa", Dimension::Pressure, 1.0},
      {"1 GPa", Dimension::Pressure, 1e9},
      {"1 Mbar", Dimension::Pressure, 1e11},
      {"1 bar", Dimension::Pressure, 1e5},
      {"1 atm", Dimension::Pressure, 101325.0},
      {"1 N/m^2", Dimension::Pressure, 1.0},
      {"1 MJ/kg", Dimension::SpecificEnergy, 1e6},
      {"1500 K", Dimension::Temperature, 1500.0},
      {"1 g", Dimension::Mass, 1e-3},
      {"1 kg", Dimension::Mass, 1.0},
      {"1 m/s", Dimension::Velocity, 1.0},
      {"9.81 m/s^2", Dimension::Acceleration, 9.81},
      {"1 ms", Dimension::Time, 1e-3},
      {"1 ns", Dimension::Time, 1e-9},
      {"3 m3", Dimension::Volume, 3.0},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.text);
    EXPECT_NEAR(parseQuantity(c.text, c.dim), c.si, 1e-12 * std::abs(c.si));
  }
}

TEST(Units, TonIsResolvedByTheExpectedDimension) {
  // Energy: ton of TNT, 1 t = 4.184e9 J (1 kt = 4.184e12 J). Mass: tonne, 1 t = 1000 kg.
  EXPECT_DOUBLE_EQ(parseQuantity("100 kt", Dimension::Energy), 4.184e14);
  EXPECT_DOUBLE_EQ(parseQuantity("1 Mt", Dimension::Energy), 4.184e15);
  EXPECT_DOUBLE_EQ(parseQuantity("1.25 t", Dimension::Energy), 1.25 * 4.184e9);
  EXPECT_DOUBLE_EQ(parseQuantity("1.25 t", Dimension::Mass), 1250.0);
  EXPECT_DOUBLE_EQ(parseQuantity("2 kt", Dimension::Mass), 2e6);
  EXPECT_DOUBLE_EQ(parseQuantity("1 tonne", Dimension::Mass), 1000.0);
  EXPECT_DOUBLE_EQ(parseQuantity("1 t/m^3", Dimension::Density), 1000.0);
  EXPECT_THROW(parseQuantity("1 tonne", Dimension::Energy), UnitError);
}

TEST(Units, ShieldAndAngleUnits) {
  // psi: NIST SP 811 (2008) app. B.9, 1 lbf/in^2 = 4.4482216152605 N / (0.0254 m)^2.
  EXPECT_NEAR(parseQuantity("1 psi", Dimension::Pressure), 4.4482216152605 / (0.0254 * 0.0254),
              1e-9);
  EXPECT_DOUBLE_EQ(parseQuantity("37 ksi", Dimension::Pressure), 37 * 6.894757293168361e6);
  EXPECT_DOUBLE_EQ(parseQuantity("2.8 g/cc", Dimension::Density), 2800.0);
  EXPECT_DOUBLE_EQ(parseQuantity("1 cc", Dimension::Volume), 1e-6);
  EXPECT_DOUBLE_EQ(parseQuantity("45 deg", Dimension::Angle), std::numbers::pi / 4);
  EXPECT_DOUBLE_EQ(parseQuantity("0.5 rad", Dimension::Angle), 0.5);
  EXPECT_DOUBLE_EQ(parseQuantity("3 mrad", Dimension::Angle), 3e-3);
  EXPECT_DOUBLE_EQ(parseQuantity("2 rad/s", Dimension::Angle / Dimension::Time), 2.0);
  EXPECT_DOUBLE_EQ(parseQuantity("0.7", Dimension::Angle), 0.7);  // a bare number: radians
}

TEST(Units, AnglesAreNotPlainNumbers) {
  // A key that takes a plain number (fov_degrees) must not read "30 deg" as 0.52.
  EXPECT_THROW(parseQuantity("30 deg", Dimension::None), UnitError);
  EXPECT_THROW(parseQuantity("1 rad", Dimension::Length), UnitError);
  EXPECT_EQ(describeDimension(Dimension::Angle), "an angle (rad)");
  EXPECT_EQ(siUnit(Dimension::Angle / Dimension::Time), "s^-1 rad");
}

TEST(Units, CompoundUnitsReadLeftToRight) {
  const Dimension heatCapacity = Dimension::SpecificEnergy / Dimension::Temperature;
  EXPECT_DOUBLE_EQ(parseQuantity("4.2 kJ/kg/K", heatCapacity), 4200.0);
  EXPECT_DOUBLE_EQ(parseQuantity("4.2 kJ / kg / K", heatCapacity), 4200.0);
  EXPECT_DOUBLE_EQ(parseQuantity("2 W*s", Dimension::Energy), 2.0);
}

std::string errorOf(const char* text, Dimension d) {
  try {
    parseQuantity(text, d);
  } catch (const UnitError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(Units, WrongDimensionSaysWhatWasExpectedAndFound) {
  EXPECT_NE(errorOf("10 km/s", Dimension::Density)
                .find("expected a density (kg/m^3), got a velocity (m/s)"),
            std::string::npos)
      << errorOf("10 km/s", Dimension::Density);
  EXPECT_NE(errorOf("100 kt", Dimension::Length).find("expected a length (m), got a mass (kg)"),
            std::string::npos);
  EXPECT_NE(errorOf("3 m^2/s", Dimension::Length).find("got a quantity in m^2 s^-1"),
            std::string::npos);
}

TEST(Units, MalformedTextIsRejected) {
  for (const char* text : {"", "km/s", "abc", "10 furlongs", "10 m/", "10 m//s", "10 /s", "10 m^x",
                           "nan m", "inf", "10 m$", "1.0.0 m"}) {
    SCOPED_TRACE(text);
    EXPECT_THROW(parseQuantity(text, Dimension::Length), UnitError);
  }
  EXPECT_NE(errorOf("10 furlongs", Dimension::Length).find("unknown unit 'furlongs'"),
            std::string::npos);
}

TEST(Units, FormatRoundTrips) {
  const Case cases[] = {
      {"2.5 GPa", Dimension::Pressure, 2.5e9},     {"-0.1 m", Dimension::Length, -0.1},
      {"2.7 g/cm^3", Dimension::Density, 2700.0},  {"100 kt", Dimension::Energy, 4.184e14},
      {"3 MJ/kg", Dimension::SpecificEnergy, 3e6}, {"14 us", Dimension::Time, 1.4e-5},
      {"10 km/s", Dimension::Velocity, 1e4}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.text);
    const double si = parseQuantity(c.text, c.dim);
    const std::string written = formatQuantity(si, c.dim);
    EXPECT_DOUBLE_EQ(parseQuantity(written, c.dim), c.si) << written;
  }
  EXPECT_EQ(formatQuantity(-0.1, Dimension::Length), "-0.1 m");
  EXPECT_EQ(formatQuantity(2700, Dimension::Density), "2700 kg/m^3");
  EXPECT_EQ(formatQuantity(1.5, Dimension::None), "1.5");
}

TEST(Units, DescribesDimensions) {
  EXPECT_EQ(describeDimension(Dimension::Pressure), "a pressure (Pa)");
  EXPECT_EQ(describeDimension(Dimension::None), "a plain number");
  EXPECT_EQ(siUnit(Dimension::Energy / Dimension::Volume), "Pa");  // energy density = pressure
  EXPECT_EQ(siUnit(Dimension{1, 1, -1, 0}), "kg m s^-1");
}

}  // namespace
}  // namespace ejecta

namespace ejecta {
namespace {

// Degrees Celsius are a level offset by 273.15 K (ITS-90), so they are read only as a temperature
// on its own; in a compound unit (a heat capacity per degree) they are refused with the reason.
TEST(Units, CelsiusIsAnOffsetTemperatureOnItsOwn) {
  EXPECT_DOUBLE_EQ(parseQuantity("20 degC", Dimension::Temperature), 293.15);
  EXPECT_DOUBLE_EQ(parseQuantity("-273.15 \u00b0C", Dimension::Temperature), 0.0);
  EXPECT_DOUBLE_EQ(parseQuantity("1500 K", Dimension::Temperature), 1500.0);
  try {
    parseQuantity("20 degC", Dimension::Length);
    FAIL() << "a Celsius temperature read as a length";
  } catch (const UnitError& e) {
    EXPECT_NE(std::string(e.what()).find("got a temperature"), std::string::npos)
        << e.what();
  }
  try {
    parseQuantity("900 J/kg/degC", Dimension{0, 2, -2, -1}  /* J/(kg K) */);
    FAIL() << "Celsius inside a compound unit accepted";
  } catch (const UnitError& e) {
    EXPECT_NE(std::string(e.what()).find("offset scale"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ejecta
