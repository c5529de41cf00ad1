#pragma once
// Shield and structure materials for the wall heat model: the seed's Table 4.1 (aluminium,
// tungsten, tantalum, tantalum carbide, graphite, titanium, hafnia) with density, heat capacity,
// emissivity and absorptivity added, each value from a cited source (docs/thermal_wall.md lists
// them, and where the seed's table differs). Properties are constants near room temperature; the
// model has no temperature dependence and no latent heat (it reports when a layer reaches its
// melting point instead).
#include <string>
#include <string_view>
#include <vector>

namespace ejecta::radiation {

struct WallMaterial {
  std::string name;
  double conductivity = 0.0;         // k through the wall's thickness [W/(m K)]
  // k along the face [W/(m K)], for 2D runs; differs from `conductivity` for layered materials
  // (pyrolytic graphite: 1950 along its planes, 5.7 across). 0: the same as `conductivity`.
  double inPlaneConductivity = 0.0;
  double density = 0.0;              // rho [kg/m^3]
  double specificHeat = 0.0;         // c_p [J/(kg K)]
  double meltingPoint = 0.0;         // [K]; for a material that sublimes, its sublimation point
  double boilingPoint = 0.0;         // [K]
  // Total hemispherical emissivity of the hot surface, [0, 1]: what it re-radiates.
  double emissivity = 0.0;
  // Absorptivity for the incident radiation, [0, 1]. The emitters (molten and vaporised rock,
  // 1500-9000 K) radiate mostly at 0.3-2 um, so this is a solar or 0.65 um value, not the
  // surface's own infrared emissivity.
  double absorptivity = 0.0;
  std::string source;                // where each number comes from (short)

  double alongFaceConductivity() const {
    return inPlaneConductivity > 0.0 ? inPlaneConductivity : conductivity;
  }
  double diffusivity() const { return conductivity / (density * specificHeat); }  // [m^2/s]
};

// The built-in table, in the seed's order.
const std::vector<WallMaterial>& wallMaterials();

// Looks a material up by name, ignoring case, '-' or ' ' for '_' and these aliases: aluminum,
// al, w, ta, tac, c, ti, hfo2, hafnium_oxide. Throws std::invalid_argument naming the unknown
// name and listing the known ones.
const WallMaterial& wallMaterial(std::string_view name);

// Aluminium with the seed's optical choices (emissivity 0.02, absorptivity 0.08, seed sec. 4.5,
// its ref. [26]) instead of the table's (0.06, 0.09): for reproducing the seed.
WallMaterial seedAluminium();

// Throws std::invalid_argument naming the material and the offending property when a value is
// not finite, not positive (k, rho, c_p, melting and boiling points), or an emissivity or
// absorptivity is outside [0, 1].
void validateWallMaterial(const WallMaterial& material);

}  // namespace ejecta::radiation
