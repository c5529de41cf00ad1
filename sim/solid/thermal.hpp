#pragma once
// Temperature of a material from its specific internal energy: T = T0 + u / c_v, with c_v
// constant (the Dulong-Petit value 3 R / M_atom for solids, as the seed's Stage 1 eq. 4.5, or a
// measured specific heat), and the melting temperature at which strength vanishes.
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace ejecta {

// Molar gas constant [J/(mol K)] (CODATA 2018, exact).
inline constexpr double kGasConstant = 8.314462618;

struct ThermalModel {
  double specificHeat = 0.0;         // c_v [J/(kg K)]
  double initialTemperature = 293.0; // T0: temperature at u = 0 [K]
  double meltTemperature = std::numeric_limits<double>::infinity();  // [K]; inf: never melts

  double temperature(double u) const { return initialTemperature + u / specificHeat; }
  bool molten(double T) const { return T >= meltTemperature; }
};

struct ThermalLibraryEntry {
  std::string name;
  double specificHeat;     // [J/(kg K)]
  double meltTemperature;  // [K]
  std::string source;
};

// Published specific heats and melting points (sources in each entry and docs/strength.md).
const std::vector<ThermalLibraryEntry>& thermalLibrary();
// The entry of that name, or nullptr.
const ThermalLibraryEntry* findThermalEntry(std::string_view name);

// Dulong-Petit specific heat 3 R / M of a solid whose mean atomic mass is M [kg/mol].
inline double dulongPetitSpecificHeat(double meanAtomicMass) {
  return 3.0 * kGasConstant / meanAtomicMass;
}

// An ideal gas of molar mass M and adiabatic index gamma: c_v = R / ((gamma - 1) M).
inline double idealGasSpecificHeat(double gamma, double molarMass) {
  return kGasConstant / ((gamma - 1.0) * molarMass);
}

// Molar mass of dry air [kg/mol] (U.S. Standard Atmosphere 1976): the default gas.
inline constexpr double kAirMolarMass = 0.0289644;

}  // namespace ejecta
