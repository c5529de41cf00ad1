#include "sim/solid/thermal.hpp"

namespace ejecta {

const std::vector<ThermalLibraryEntry>& thermalLibrary() {
  // Names match the equation-of-state and strength libraries, so a material named after a
  // library entry gets its thermal data without further keys.
  static const std::vector<ThermalLibraryEntry> entries = {
      {"Al-2024", 875.0, 775.0, "c: seed Table 5.1 (875 J/kg/K); T_melt: Johnson & Cook (1983)"},
      {"Al-2024-T351", 875.0, 775.0, "as Al-2024"},
      {"Al-1100", 904.0, 916.0,
       "c: 1100-O aluminium, ASM Handbook vol. 2 (904 J/kg/K); T_melt: solidus 916 K (ASM)"},
      {"aluminium", 897.0, 933.5, "pure Al: c_p 897 J/kg/K, T_melt 933.47 K (CRC Handbook)"},
      {"copper", 385.0, 1356.0, "pure Cu: c_p 385 J/kg/K, T_melt 1357.8 K (CRC Handbook)"},
      {"OFHC-copper", 383.0, 1356.0, "Johnson & Cook (1983) Table 1"},
      {"iron", 449.0, 1811.0, "pure Fe: c_p 449 J/kg/K, T_melt 1811 K (CRC Handbook)"},
      {"Armco-iron", 452.0, 1811.0, "Johnson & Cook (1983) Table 1"},
      {"4340-steel", 477.0, 1793.0, "Johnson & Cook (1983) Table 1"},
      {"granite", 790.0, 1500.0,
       "c_p 790 J/kg/K (Robertson 1988, USGS OFR 88-441, typical granite); T_melt 1500 K, the "
       "seed's molten-rock cut (granite liquidus ~1500 K, solidus ~1200 K)"},
      {"basalt", 840.0, 1500.0,
       "c_p 840 J/kg/K (Robertson 1988, USGS OFR 88-441); T_melt 1500 K (basalt liquidus "
       "~1470-1520 K)"},
      {"ice", 2100.0, 273.15, "water ice near 260 K: c_p ~2.1 kJ/kg/K; T_melt 273.15 K"},
      {"water", 4181.0, 273.15, "liquid water at 298 K: c_p 4181 J/kg/K"},
      // Explosives and their detonation products: Dulong-Petit 3R/M over the atoms of the
      // molecule (the classical high-temperature limit, appropriate for the hot products):
      // TNT C7H5N3O6, 227.13 g/mol / 21 atoms; RDX C3H6N6O6, 222.12 g/mol / 21 atoms; CompB
      // 60/40 RDX/TNT by mass; C-4 taken as its 91% RDX.
      {"TNT", 3.0 * kGasConstant / (227.13e-3 / 21.0), 354.0,
       "Dulong-Petit over C7H5N3O6; T_melt 354 K (TNT melts at 80.4 C)"},
      {"TNT-AUTODYN", 3.0 * kGasConstant / (227.13e-3 / 21.0), 354.0, "as TNT"},
      {"CompB", 3.0 * kGasConstant / (1.0 / (0.6 * 21.0 / 222.12e-3 + 0.4 * 21.0 / 227.13e-3)),
       354.0, "Dulong-Petit over 60/40 RDX/TNT; T_melt of its TNT"},
      {"C-4", 3.0 * kGasConstant / (222.12e-3 / 21.0), 478.0,
       "Dulong-Petit over RDX (C3H6N6O6); T_melt of RDX 478 K"},
  };
  return entries;
}

const ThermalLibraryEntry* findThermalEntry(std::string_view name) {
  for (const ThermalLibraryEntry& e : thermalLibrary())
    if (e.name == name) return &e;
  return nullptr;
}

}  // namespace ejecta
