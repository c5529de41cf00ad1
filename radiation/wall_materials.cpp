#include "radiation/wall_materials.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "core/join.hpp"

namespace ejecta::radiation {

namespace {

// Sources (full references in docs/thermal_wall.md):
//   [I]  Incropera, DeWitt, Bergman & Lavine, Fundamentals of Heat and Mass Transfer, 6th ed.
//        (Wiley 2007), Table A.1 (metals, 300 K), A.2 (non-metals, 300 K), A.12 (solar
//        absorptivity).
//   [C]  CRC Handbook of Chemistry and Physics, 97th ed. (Haynes 2016): melting and boiling
//        points of the elements and of inorganic compounds; spectral emissivity at 0.65 um.
//   [L]  Liley, "Emissivity of solids", Heat Exchanger Design Handbook sec. 5.5.7, Table 1.
//   [M]  Mikron Instrument Co., "Table of emissivity of various surfaces" (compiled from [C],
//        DMIC Report 177 and the Honeywell Thermal Radiation Properties Survey).
//   [J]  NIST-JANAF Thermochemical Tables, 4th ed. (Chase 1998): molar heat capacity at 298 K.
//   [P]  Pierson, Handbook of Refractory Carbides and Nitrides (Noyes 1996), ch. 5.
//   [S]  Martienssen & Warlimont (eds.), Springer Handbook of Condensed Matter and Materials
//        Data (2005): hafnia.
//   [W]  Wang, Zinkevich & Aldinger, J. Am. Ceram. Soc. 89, 3751 (2006): HfO2 assessment.
std::vector<WallMaterial> builtInMaterials() {
  std::vector<WallMaterial> m;
  // Pure aluminium. k, rho, c_p [I] A.1 at 300 K. T_m 660.32 C (the ITS-90 fixed point),
  // T_b 2519 C [C] (the seed prints 2797 K). Emissivity: polished, hemispherical total at 600 K
  // [L]. Absorptivity: polished, solar [I] A.12.
  m.push_back({"aluminium", 237.0, 0.0, 2702.0, 903.0, 933.47, 2792.0, 0.06, 0.09,
               "k rho cp: Incropera A.1 (300 K); Tm Tb: CRC; eps: Liley HEDH 5.5.7 (polished, "
               "600 K); alpha: Incropera A.12 (polished, solar)"});
  // Tungsten. [I] A.1 (k 174; the seed's 173 is the rounded CRC value). T_m 3422 C, T_b 5555 C
  // [C]. Emissivity: unoxidised, total, 1000 C [M]. Absorptivity: spectral emissivity of the
  // unoxidised metal at 0.65 um [C] (Kirchhoff: equal to the absorptivity at that wavelength).
  m.push_back({"tungsten", 174.0, 0.0, 19300.0, 132.0, 3695.0, 5828.0, 0.15, 0.43,
               "k rho cp: Incropera A.1 (300 K); Tm Tb: CRC; eps: Mikron/CRC (unoxidised, "
               "1000 C); alpha: CRC spectral emissivity at 0.65 um"});
  // Tantalum. [I] A.1; T_m 3017 C, T_b 5458 C [C]; emissivity unoxidised at 1500 C [M] (the
  // table's lowest temperature for Ta); absorptivity at 0.65 um [C].
  m.push_back({"tantalum", 57.5, 0.0, 16600.0, 140.0, 3290.0, 5731.0, 0.21, 0.49,
               "k rho cp: Incropera A.1 (300 K); Tm Tb: CRC; eps: Mikron/CRC (unoxidised, "
               "1500 C); alpha: CRC spectral emissivity at 0.65 um"});
  // Tantalum carbide. k 22.1 at 20 C [P]; rho 14.3 g/cm^3, T_m 3880 C, T_b 4780 C [C] (a
  // later laser-heating measurement gives 3768 C: Cedillos-Barraza et al., Sci. Rep. 6, 37962,
  // 2016); c_p = 36.71 J/(mol K) [J] / 0.19296 kg/mol. No emissivity or absorptivity table was
  // found for TaC: tantalum's values are assumed (a metallic-conducting carbide).
  m.push_back({"tantalum_carbide", 22.1, 0.0, 14300.0, 190.2, 4153.15, 5053.15, 0.21, 0.49,
               "k: Pierson 1996; rho Tm Tb: CRC; cp: NIST-JANAF; eps alpha: ASSUMED equal to "
               "tantalum's (no source found)"});
  // Pyrolytic graphite. [I] A.2 at 300 K: k 5.70 across the basal planes (the seed's value;
  // a coating is deposited with its planes along the surface), 1950 along them. Graphite does
  // not melt at low pressure: it sublimes at 3825 C [C] (triple point 4489 C at 10.3 MPa), so
  // both points are the sublimation point (the seed prints 4000 and 4500 K). Emissivity:
  // carbon, normal total at 1000 K [L]; absorptivity: carbon at 0.65 um, 0.80-0.93 [C].
  m.push_back({"graphite", 5.70, 1950.0, 2210.0, 709.0, 4098.15, 4098.15, 0.82, 0.85,
               "k (across / along planes) rho cp: Incropera A.2 pyrolytic (300 K); Tm = Tb: "
               "CRC sublimation point; eps: Liley HEDH 5.5.7; alpha: CRC 0.65 um (0.80-0.93)"});
  // Titanium. [I] A.1; T_m 1668 C, T_b 3287 C [C]. Emissivity: polished, 0.08-0.19 over
  // 150-320 C [M], the upper value; absorptivity at 0.65 um [C].
  m.push_back({"titanium", 21.9, 0.0, 4500.0, 522.0, 1941.0, 3560.0, 0.19, 0.63,
               "k rho cp: Incropera A.1 (300 K); Tm Tb: CRC; eps: Mikron/CRC (polished, "
               "320 C); alpha: CRC spectral emissivity at 0.65 um"});
  // Hafnia (HfO2). k 1.1 for dense hafnia [S]: the seed's 23.0 is hafnium metal's
  // conductivity. rho 9.68 g/cm^3, T_m 2758 C, T_b 5400 C [C] (assessed T_m 2800 C [W]);
  // c_p = 60.3 J/(mol K) [J] / 0.21049 kg/mol. Emissivity 0.8: plasma-sprayed HfO2-based
  // coatings measure 0.84-0.90 (Coatings 13, 1386, 2023, doped); absorptivity 0.3 ASSUMED
  // (a white oxide, band gap 5.5 eV; no measurement found).
  m.push_back({"hafnia", 1.1, 0.0, 9680.0, 286.5, 3031.0, 5673.0, 0.80, 0.30,
               "k: Springer Handbook of Condensed Matter 2005; rho Tm Tb: CRC; cp: NIST-JANAF; "
               "eps: HfO2 coatings (Coatings 2023); alpha: ASSUMED (no source found)"});
  return m;
}

std::string canonicalName(std::string_view name) {
  std::string s;
  s.reserve(name.size());
  for (const char c : name) {
    if (c == '-' || c == ' ') s.push_back('_');
    else s.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
  }
  static const std::pair<const char*, const char*> kAliases[] = {
      {"aluminum", "aluminium"}, {"al", "aluminium"},        {"w", "tungsten"},
      {"ta", "tantalum"},        {"tac", "tantalum_carbide"}, {"c", "graphite"},
      {"ti", "titanium"},        {"hfo2", "hafnia"},          {"hafnium_oxide", "hafnia"}};
  for (const auto& [alias, canonical] : kAliases)
    if (s == alias) return canonical;
  return s;
}

void requirePositive(const WallMaterial& m, const char* what, double value) {
  if (!(std::isfinite(value) && value > 0.0))
    throw std::invalid_argument("wall material '" + m.name + "': " + what +
                                " must be positive and finite, got " + std::to_string(value));
}

void requireFraction(const WallMaterial& m, const char* what, double value) {
  if (!(value >= 0.0 && value <= 1.0))
    throw std::invalid_argument("wall material '" + m.name + "': " + what +
                                " must lie in [0, 1], got " + std::to_string(value));
}

}  // namespace

const std::vector<WallMaterial>& wallMaterials() {
  static const std::vector<WallMaterial> table = builtInMaterials();
  return table;
}

const WallMaterial& wallMaterial(std::string_view name) {
  const std::string key = canonicalName(name);
  const auto& table = wallMaterials();
  const auto it = std::find_if(table.begin(), table.end(),
                               [&](const WallMaterial& m) { return m.name == key; });
  if (it != table.end()) return *it;
  throw std::invalid_argument("unknown wall material '" + std::string(name) + "' (known: " +
                              joinList(table, &WallMaterial::name) + ")");
}

WallMaterial seedAluminium() {
  WallMaterial m = wallMaterial("aluminium");
  m.name = "aluminium_seed";
  m.emissivity = 0.02;    // seed sec. 4.5, its ref. [26]
  m.absorptivity = 0.08;
  m.source += "; eps 0.02, alpha 0.08: the seed's choice (sec. 4.5)";
  return m;
}

void validateWallMaterial(const WallMaterial& m) {
  requirePositive(m, "conductivity", m.conductivity);
  if (!(std::isfinite(m.inPlaneConductivity) && m.inPlaneConductivity >= 0.0))
    throw std::invalid_argument("wall material '" + m.name +
                                "': inPlaneConductivity must be >= 0 and finite (0: isotropic)");
  requirePositive(m, "density", m.density);
  requirePositive(m, "specificHeat", m.specificHeat);
  requirePositive(m, "meltingPoint", m.meltingPoint);
  requirePositive(m, "boilingPoint", m.boilingPoint);
  requireFraction(m, "emissivity", m.emissivity);
  requireFraction(m, "absorptivity", m.absorptivity);
}

}  // namespace ejecta::radiation
