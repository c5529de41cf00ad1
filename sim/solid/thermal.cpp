#include "sim/solid/thermal.hpp"

namespace ejecta {

const std::vector<ThermalLibraryEntry>& thermalLibrary() {
  // Names match the equation-of-state and strength libraries, so a material named after a
  // library entry gets its thermal data without further keys.
  static const std::vector<ThermalLibraryEntry> entries = {
      // Al-2024 melts over 775-911 K: one plateau at its solidus (T_melt of Johnson & Cook), with
      // the alloy's L_m and pure aluminium's boiling (its 4.4% Cu moves both by little).
      {"Al-2024", 875.0, 775.0, "c: seed Table 5.1 (875 J/kg/K); T_melt: Johnson & Cook (1983)",
       3.9e5, 2790.8, 1.09e7,
       "L_m 390 kJ/kg (2024 alloy, MakeItFrom, secondary); T_b and L_v of pure aluminium"},
      {"Al-2024-T351", 875.0, 775.0, "as Al-2024", 3.9e5, 2790.8, 1.09e7, "as Al-2024"},
      {"Al-1100", 904.0, 916.0,
       "c: 1100-O aluminium, ASM Handbook vol. 2 (904 J/kg/K); T_melt: solidus 916 K (ASM)"},
      // Phase changes: docs/thermal.md, "Phase changes", has each value's source and status.
      {"aluminium", 897.0, 933.5, "pure Al: c_p 897 J/kg/K, T_melt 933.47 K (CRC Handbook)",
       3.97e5, 2790.8, 1.09e7,
       "L_m 10.71 kJ/mol (HSDB); T_b 2790.8 K (NIST-JANAF, Chase 1998); L_v 294 kJ/mol (CRC, "
       "unchecked here) = Tillotson Ecv - Eiv (Melosh 1989)"},
      {"copper", 385.0, 1356.0, "pure Cu: c_p 385 J/kg/K, T_melt 1357.8 K (CRC Handbook)"},
      {"OFHC-copper", 383.0, 1356.0, "Johnson & Cook (1983) Table 1"},
      {"iron", 449.0, 1811.0, "pure Fe: c_p 449 J/kg/K, T_melt 1811 K (CRC Handbook)", 2.47e5,
       3133.3, 6.26e6,
       "L_m 13.81 kJ/mol (NIST-JANAF; Desai 1986); T_b 3133.3 K (NIST-JANAF, Chase 1998); L_v "
       "= T_b x the JANAF entropy of vaporisation; liquid c_p 824 J/kg/K (NIST-JANAF)",
       824.0},
      {"Armco-iron", 452.0, 1811.0, "Johnson & Cook (1983) Table 1"},
      {"4340-steel", 477.0, 1793.0, "Johnson & Cook (1983) Table 1"},
      {"granite", 790.0, 1500.0,
       "c_p 790 J/kg/K (Robertson 1988, USGS OFR 88-441, typical granite); T_melt 1500 K, the "
       "seed's molten-rock cut (granite liquidus ~1500 K, solidus ~1200 K)",
       3.0e5, 3000.0, 1.45e7,
       "L_m 300 kJ/kg (felsic rock, Bittner & Schmeling 1995); T_b ~3000 K (silicate liquid-"
       "vapour at 0.1 MPa); L_v = Tillotson Ecv - Eiv (seed Table 3.2)"},
      {"basalt", 840.0, 1500.0,
       "c_p 840 J/kg/K (Robertson 1988, USGS OFR 88-441); T_melt 1500 K (basalt liquidus "
       "~1470-1520 K)",
       3.8e5, 3000.0, 1.35e7,
       "L_m 380 kJ/kg (basalt, Bittner & Schmeling 1995); T_b ~3000 K (silicate liquid-vapour "
       "at 0.1 MPa); L_v = Tillotson Ecv - Eiv (Benz & Asphaug 1999)"},
      {"ice", 2100.0, 273.15, "water ice near 260 K: c_p ~2.1 kJ/kg/K; T_melt 273.15 K", 3.334e5,
       373.12, 2.087e6,
       "IAPWS (R10-06, IAPWS-95) at 1 atm: L_m 333.4 kJ/kg, T_b 373.12 K, L_v as internal "
       "energy 2087 kJ/kg (the enthalpy's is 2256.5); liquid c_p 4219 J/kg/K at 273 K",
       4219.0},
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
