#include "sim/solid/strength_library.hpp"

namespace ejecta {

const std::vector<StrengthLibraryEntry>& strengthLibrary() {
  auto jc = [](double A, double B, double n, double C, double m) {
    JohnsonCookParameters p;
    p.A = A; p.B = B; p.n = n; p.C = C; p.m = m;
    p.referenceStrainRate = 1.0;
    p.roomTemperature = 294.0;
    return p;
  };
  static const std::vector<StrengthLibraryEntry> entries = {
      // Johnson & Cook (1983), 7th Int. Symp. on Ballistics, Table 1 (reference strain rate
      // 1/s); the seed's Table 5.2 prints the same 2024-T351 set.
      {"Al-2024-T351", 27.6e9, "johnson_cook", 0.0,
       jc(265e6, 426e6, 0.34, 0.015, 1.0), 775.0,
       "Johnson & Cook (1983) Table 1, 2024-T351 aluminium; = seed Table 5.2"},
      {"OFHC-copper", 46.0e9, "johnson_cook", 0.0,
       jc(90e6, 292e6, 0.31, 0.025, 1.09), 1356.0,
       "Johnson & Cook (1983) Table 1, OFHC copper"},
      {"Armco-iron", 81.8e9, "johnson_cook", 0.0,
       jc(175e6, 380e6, 0.32, 0.060, 0.55), 1811.0,
       "Johnson & Cook (1983) Table 1, Armco iron"},
      {"4340-steel", 77.5e9, "johnson_cook", 0.0,
       jc(792e6, 510e6, 0.26, 0.014, 1.03), 1793.0,
       "Johnson & Cook (1983) Table 1, 4340 steel (Rc 30)"},
  };
  return entries;
}

const StrengthLibraryEntry* findStrengthEntry(std::string_view name) {
  for (const StrengthLibraryEntry& e : strengthLibrary())
    if (e.name == name) return &e;
  return nullptr;
}

}  // namespace ejecta
