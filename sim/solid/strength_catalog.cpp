#include "sim/solid/strength_catalog.hpp"

#include <stdexcept>
#include <string>

#include "sim/solid/strength_library.hpp"
#include "sim/solid/strength_models/collins.hpp"
#include "sim/solid/strength_models/drucker_prager.hpp"
#include "sim/solid/strength_models/elastic.hpp"
#include "sim/solid/strength_models/johnson_cook.hpp"
#include "sim/solid/strength_models/von_mises.hpp"

namespace ejecta {

namespace {

[[noreturn]] void fail(const std::string& what) { throw std::invalid_argument(what); }

std::string quotedNames(const std::vector<const StrengthModelRow*>& rows) {
  std::string out;
  for (const StrengthModelRow* r : rows) {
    if (!out.empty()) out += ", ";
    out += '"';
    out += r->name;
    out += '"';
  }
  return out;
}

bool libraryHasModel(std::string_view model) {
  for (const StrengthLibraryEntry& e : strengthLibrary())
    if (e.model == model) return true;
  return false;
}

}  // namespace

config::KeySpec cohesionKey() {
  return config::keys::quantity("cohesion", Dimension::Pressure, "required for collins, drucker_prager",
                                "cohesion Y_0, the strength at zero pressure (collins: intact)");
}

config::KeySpec strengthLimitKey() {
  return config::keys::quantity("strength_limit", Dimension::Pressure,
                                "required for collins, drucker_prager",
                                "strength limit Y_M at high pressure, > Y_0");
}

const std::vector<StrengthModelRow>& strengthCatalog() {
  static const std::vector<StrengthModelRow> rows = {
      elasticStrengthRow(),
      vonMisesStrengthRow(),
      johnsonCookStrengthRow(),
      collinsStrengthRow(),
      druckerPragerStrengthRow(),
  };
  return rows;
}

const StrengthModelRow* findStrengthModel(const std::vector<StrengthModelRow>& rows, std::string_view name) {
  for (const StrengthModelRow& r : rows)
    if (r.name == name) return &r;
  return nullptr;
}

StrengthModel buildStrength(const ModelSpec& s, const std::vector<StrengthModelRow>& rows,
                            std::optional<double>& melt) {
  double shearModulus = 0.0;
  const StrengthLibraryEntry* entry = nullptr;
  if (!s.library.empty()) {
    entry = findStrengthEntry(s.library);
    if (!entry) {
      std::string known;
      for (const StrengthLibraryEntry& e : strengthLibrary()) {
        if (!known.empty()) known += ", ";
        known += e.name;
      }
      fail("strength.library: no entry '" + s.library + "'; known: " + known);
    }
    shearModulus = entry->shearModulus;
    melt = entry->meltTemperature;
  }
  const StrengthModelRow* row = findStrengthModel(rows, s.model);
  if (!row) {
    std::vector<const StrengthModelRow*> all;
    for (const StrengthModelRow& r : rows) all.push_back(&r);
    fail("strength.model \"" + s.model + "\" is not a strength model; the models are " + quotedNames(all));
  }
  shearModulus = s.valueOr("shear_modulus", shearModulus);
  if (!(shearModulus > 0.0)) fail("strength.shear_modulus is required and must be positive");
  // A key of another model: named with the models it belongs to.
  for (const auto& [key, value] : s.values) {
    if (key == "shear_modulus" || config::findKey(row->keys, key)) continue;
    std::vector<const StrengthModelRow*> owners;
    for (const StrengthModelRow& r : rows)
      if (config::findKey(r.keys, key)) owners.push_back(&r);
    if (owners.empty()) fail("strength." + key + " is not a key of any strength model");
    fail("strength." + key + " does not apply to model \"" + s.model + "\"; strength." + key +
         (owners.size() == 1 ? " applies only to model " : " applies only to models ") +
         quotedNames(owners));
  }
  const bool fromLibrary = entry && entry->model == row->name;
  for (std::string_view key : row->required)
    if (!fromLibrary && !s.find(key))
      fail(std::string("strength.").append(key) + " is required for model \"" +
           std::string(row->name) + "\"" + (libraryHasModel(row->name) ? " without a library" : ""));
  return StrengthModel(shearModulus, row->make(s, fromLibrary ? entry : nullptr));
}

}  // namespace ejecta
