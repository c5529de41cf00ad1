#pragma once
// Published strength data ([materials.strength] library = "..."): a shear modulus, a melting
// point and the parameters of one strength model (so far Johnson-Cook alone).
#include <string>
#include <string_view>
#include <vector>

#include "sim/solid/strength_models/johnson_cook.hpp"

namespace ejecta {

struct StrengthLibraryEntry {
  std::string name;
  double shearModulus;
  std::string_view model;             // the catalog row whose parameters it gives
  double yieldStress;                 // von_mises
  JohnsonCookParameters johnsonCook;  // johnson_cook
  double meltTemperature;             // the model's T_melt [K]
  std::string source;
};

const std::vector<StrengthLibraryEntry>& strengthLibrary();
const StrengthLibraryEntry* findStrengthEntry(std::string_view name);

}  // namespace ejecta
