#include "sim/eos/eos_catalog.hpp"

#include <functional>
#include <set>
#include <stdexcept>
#include <vector>

#include "core/input_error.hpp"
#include "sim/eos/jwl.hpp"
#include "sim/eos/mie_gruneisen.hpp"
#include "sim/eos/tillotson.hpp"
#include "sim/solid/material_spec.hpp"

namespace ejecta {

namespace {

// A parameter key bound to a member of a parameter struct.
template <typename Params>
struct Field {
  std::string_view key;
  Dimension dimension;
  double Params::*member;
};

const std::vector<Field<TillotsonParameters>> kTillotsonFields{
    {"rho0", Dimension::Density, &TillotsonParameters::rho0},
    {"A", Dimension::Pressure, &TillotsonParameters::A},
    {"B", Dimension::Pressure, &TillotsonParameters::B},
    {"E0", Dimension::SpecificEnergy, &TillotsonParameters::E0},
    {"Eiv", Dimension::SpecificEnergy, &TillotsonParameters::Eiv},
    {"Ecv", Dimension::SpecificEnergy, &TillotsonParameters::Ecv},
    {"a", Dimension::None, &TillotsonParameters::a},
    {"b", Dimension::None, &TillotsonParameters::b},
    {"alpha", Dimension::None, &TillotsonParameters::alpha},
    {"beta", Dimension::None, &TillotsonParameters::beta},
};

const std::vector<Field<ShockMaterial>> kShockFields{
    {"rho0", Dimension::Density, &ShockMaterial::rho0},
    {"c0", Dimension::Velocity, &ShockMaterial::c0},
    {"s1", Dimension::None, &ShockMaterial::s1},
    {"s2", Dimension::None, &ShockMaterial::s2},
    {"s3", Dimension::None, &ShockMaterial::s3},
    {"gamma0", Dimension::None, &ShockMaterial::gamma0},
    {"a", Dimension::None, &ShockMaterial::a},
};

const std::vector<Field<JwlParams>> kJwlFields{
    {"rho0", Dimension::Density, &JwlParams::rho0},
    {"A", Dimension::Pressure, &JwlParams::A},
    {"B", Dimension::Pressure, &JwlParams::B},
    {"R1", Dimension::None, &JwlParams::R1},
    {"R2", Dimension::None, &JwlParams::R2},
    {"omega", Dimension::None, &JwlParams::omega},
    {"E0", Dimension::Pressure, &JwlParams::E0},  // detonation energy per unit volume [J/m^3]
    {"D_cj", Dimension::Velocity, &JwlParams::dCJ},
    {"P_cj", Dimension::Pressure, &JwlParams::pCJ},
};

template <typename Params>
std::vector<EosParameter> parameterList(const std::vector<Field<Params>>& fields) {
  std::vector<EosParameter> out;
  for (const auto& f : fields) out.push_back({f.key, f.dimension});
  return out;
}

// Library entry (or zeros), then the spec's overrides; every field must end up set.
template <typename Params>
Params assemble(const MaterialSpec& spec, const std::vector<Field<Params>>& fields,
                const std::function<Params(std::string_view)>& library) {
  Params p{};
  std::set<std::string_view> set;
  if (!spec.library.empty()) {
    try {
      p = library(spec.library);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("library: ") + e.what());
    }
    for (const auto& f : fields) set.insert(f.key);
  }
  for (const auto& [key, value] : spec.parameters) {
    bool found = false;
    for (const auto& f : fields)
      if (f.key == key) {
        p.*(f.member) = value;
        set.insert(f.key);
        found = true;
      }
    if (!found) throw std::invalid_argument("parameters." + key + ": not a parameter of " + spec.eos);
  }
  for (const auto& f : fields)
    if (!set.count(f.key))
      throw std::invalid_argument("parameters." + std::string(f.key) +
                                  ": required (no library entry named for this material)");
  if (spec.library.empty()) p.name = spec.name;
  return p;
}

}  // namespace

const std::vector<EosKind>& eosKinds() {
  static const std::vector<EosKind> kinds = {
      {"ideal_gas", {{"gamma", Dimension::None}}, {}},
      {"tillotson",
       [] {
         // Not an EOS constant but its tension cut-off (TillotsonOptions::minimumPressure).
         std::vector<EosParameter> list = parameterList(kTillotsonFields);
         list.push_back({"minimum_pressure", Dimension::Pressure});
         return list;
       }(),
       tillotsonLibraryNames()},
      {"mie_gruneisen", parameterList(kShockFields), shockMaterialNames()},
      {"jwl", parameterList(kJwlFields), jwlExplosiveNames()},
  };
  return kinds;
}

const EosKind* findEosKind(std::string_view name) {
  for (const EosKind& k : eosKinds())
    if (k.name == name) return &k;
  return nullptr;
}

std::shared_ptr<const EquationOfState> makeEquationOfState(const MaterialSpec& spec) {
  if (spec.eos == "ideal_gas") return std::make_shared<IdealGas>(spec.gamma);
  if (spec.eos == "tillotson") {
    // minimum_pressure is an option of the EOS, not one of its library constants.
    TillotsonOptions options;
    MaterialSpec constants = spec;
    std::erase_if(constants.parameters, [&](const auto& kv) {
      if (kv.first != "minimum_pressure") return false;
      options.minimumPressure = kv.second;
      return true;
    });
    return std::make_shared<Tillotson>(
        assemble<TillotsonParameters>(constants, kTillotsonFields,
                                      [](std::string_view n) { return tillotsonLibrary(n); }),
        options);
  }
  if (spec.eos == "mie_gruneisen")
    return std::make_shared<MieGruneisen>(assemble<ShockMaterial>(
        spec, kShockFields, [](std::string_view n) { return shockMaterial(n); }));
  if (spec.eos == "jwl")
    return std::make_shared<Jwl>(
        assemble<JwlParams>(spec, kJwlFields, [](std::string_view n) { return jwlExplosive(n); }));
  throw std::invalid_argument("unknown eos '" + spec.eos + "'");
}

}  // namespace ejecta
