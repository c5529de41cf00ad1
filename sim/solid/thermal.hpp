#pragma once
// Temperature of a material from its specific internal energy. The seed's model (Stage 1,
// eq. 4.5) is T = T0 + u / c_v with c_v constant (the Dulong-Petit value 3 R / M_atom for
// solids, or a measured specific heat). With phase changes (docs/thermal.md, "Phase changes")
// the energy also pays the latent heats: T(u) rises at c_v to the melting point T_m, stays
// there while the latent heat of melting L_m is absorbed (the melt fraction rising from 0 to
// 1), rises at the liquid's specific heat to the boiling point T_b, stays there through the
// latent heat of vaporisation L_v (the vapour fraction), then rises at the vapour's. Strength
// vanishes from the melting point on.
#include <algorithm>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace ejecta {

// Molar gas constant [J/(mol K)] (CODATA 2018, exact).
inline constexpr double kGasConstant = 8.314462618;

struct ThermalModel {
  double specificHeat = 0.0;         // c_v [J/(kg K)] (of the solid, with phase changes)
  double initialTemperature = 293.0; // T0: temperature at u = 0 [K]
  double meltTemperature = std::numeric_limits<double>::infinity();  // [K]; inf: never melts
  // Phase changes; all zero (the default): the seed's single straight line.
  double meltLatentHeat = 0.0;       // L_m [J/kg]
  double boilTemperature = std::numeric_limits<double>::infinity();  // T_b [K]
  double vapourLatentHeat = 0.0;     // L_v [J/kg]
  double liquidSpecificHeat = 0.0;   // [J/(kg K)]; 0: the solid's
  double vapourSpecificHeat = 0.0;   // [J/(kg K)]; 0: the liquid's

  bool phaseChanges() const { return meltLatentHeat > 0.0 || vapourLatentHeat > 0.0; }
  double temperature(double u) const {
    if (!phaseChanges()) return initialTemperature + u / specificHeat;
    const Thresholds e = thresholds();
    if (u <= e.meltStart) return initialTemperature + u / specificHeat;
    if (u <= e.meltEnd) return meltTemperature;
    if (u <= e.boilStart) return meltTemperature + (u - e.meltEnd) / liquid();
    if (u <= e.boilEnd) return boilTemperature;
    return boilTemperature + (u - e.boilEnd) / vapour();
  }
  // The mass fraction molten (liquid or vapour) and vaporised at specific energy u.
  double meltFraction(double u) const { return fraction(u, thresholds().meltStart, meltLatentHeat); }
  double vapourFraction(double u) const {
    return fraction(u, thresholds().boilStart, vapourLatentHeat);
  }
  bool molten(double T) const { return T >= meltTemperature; }

  // The specific energies at which the plateaus begin and end (u = 0 at T0).
  struct Thresholds {
    double meltStart, meltEnd, boilStart, boilEnd;
  };
  Thresholds thresholds() const {
    Thresholds e;
    e.meltStart = specificHeat * (meltTemperature - initialTemperature);
    e.meltEnd = e.meltStart + meltLatentHeat;
    e.boilStart = e.meltEnd + liquid() * (boilTemperature - meltTemperature);
    e.boilEnd = e.boilStart + vapourLatentHeat;
    return e;
  }

 private:
  double liquid() const { return liquidSpecificHeat > 0.0 ? liquidSpecificHeat : specificHeat; }
  double vapour() const { return vapourSpecificHeat > 0.0 ? vapourSpecificHeat : liquid(); }
  static double fraction(double u, double start, double latent) {
    if (u <= start) return 0.0;
    return latent > 0.0 ? std::min(1.0, (u - start) / latent) : 1.0;
  }
};

struct ThermalLibraryEntry {
  std::string name;
  double specificHeat;     // [J/(kg K)]
  double meltTemperature;  // [K]
  std::string source;
  // Phase changes, where published (0 / infinity: not in the library).
  double meltLatentHeat = 0.0;  // [J/kg]
  double boilTemperature = std::numeric_limits<double>::infinity();  // [K]
  double vapourLatentHeat = 0.0;  // [J/kg]
  std::string phaseSource = {};
  double liquidSpecificHeat = 0.0;  // [J/(kg K)]; 0: not in the library (the solid's is used)
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
