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
  std::string_view doc;
};

const std::vector<Field<TillotsonParameters>> kTillotsonFields{
    {"rho0", Dimension::Density, &TillotsonParameters::rho0, "reference density ρ0"},
    {"A", Dimension::Pressure, &TillotsonParameters::A, "linear compression coefficient A"},
    {"B", Dimension::Pressure, &TillotsonParameters::B, "quadratic compression coefficient B"},
    {"E0", Dimension::SpecificEnergy, &TillotsonParameters::E0, "reference specific energy E0"},
    {"Eiv", Dimension::SpecificEnergy, &TillotsonParameters::Eiv, "specific energy of incipient vaporisation"},
    {"Ecv", Dimension::SpecificEnergy, &TillotsonParameters::Ecv, "specific energy of complete vaporisation"},
    {"a", Dimension::None, &TillotsonParameters::a, "Tillotson a"},
    {"b", Dimension::None, &TillotsonParameters::b, "Tillotson b"},
    {"alpha", Dimension::None, &TillotsonParameters::alpha, "decay constant α of the expanded branch (density)"},
    {"beta", Dimension::None, &TillotsonParameters::beta, "decay constant β of the expanded branch (pressure)"},
};

const std::vector<Field<ShockMaterial>> kShockFields{
    {"rho0", Dimension::Density, &ShockMaterial::rho0, "reference density ρ0"},
    {"c0", Dimension::Velocity, &ShockMaterial::c0, "bulk sound speed, intercept of the Us-up fit"},
    {"s1", Dimension::None, &ShockMaterial::s1, "linear slope of the Us-up fit"},
    {"s2", Dimension::None, &ShockMaterial::s2, "quadratic coefficient (of up²/Us)"},
    {"s3", Dimension::None, &ShockMaterial::s3, "cubic coefficient (of up³/Us²)"},
    {"gamma0", Dimension::None, &ShockMaterial::gamma0, "Grüneisen coefficient Γ0 at ρ0"},
    {"a", Dimension::None, &ShockMaterial::a, "first-order volume correction to Γ0"},
};

const std::vector<Field<JwlParams>> kJwlFields{
    {"rho0", Dimension::Density, &JwlParams::rho0, "unreacted explosive density ρ0"},
    {"A", Dimension::Pressure, &JwlParams::A, "JWL A"},
    {"B", Dimension::Pressure, &JwlParams::B, "JWL B"},
    {"R1", Dimension::None, &JwlParams::R1, "JWL R1"},
    {"R2", Dimension::None, &JwlParams::R2, "JWL R2"},
    {"omega", Dimension::None, &JwlParams::omega, "Grüneisen coefficient ω of the products"},
    {"E0", Dimension::Pressure, &JwlParams::E0, "detonation energy per unit initial volume [J/m^3]; e0 = E0/ρ0"},
    {"D_cj", Dimension::Velocity, &JwlParams::dCJ, "Chapman-Jouguet detonation velocity"},
    {"P_cj", Dimension::Pressure, &JwlParams::pCJ, "Chapman-Jouguet pressure"},
};

template <typename Params>
std::vector<EosParameter> parameterList(const std::vector<Field<Params>>& fields) {
  std::vector<EosParameter> out;
  for (const auto& f : fields) out.push_back({f.key, f.dimension, f.doc});
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
      {"ideal_gas", {}, {}, "ideal gas, P = (γ − 1) ρ u",
       "its adiabatic index is the material's own `gamma` key"},
      {"tillotson",
       [] {
         // Not an EOS constant but its tension cut-off (TillotsonOptions::minimumPressure).
         std::vector<EosParameter> list = parameterList(kTillotsonFields);
         list.push_back({"minimum_pressure", Dimension::Pressure,
                         "pressures below it are clamped to it (default: no floor, the cold "
                         "branch keeps its tension)"});
         return list;
       }(),
       tillotsonLibraryNames(),
       "Tillotson (1962), solids and their vapour: `docs/eos_tillotson.md`"},
      {"mie_gruneisen", parameterList(kShockFields), shockMaterialNames(),
       "Mie-Grüneisen on a Us-up shock fit: `docs/eos_shock_jwl.md`"},
      {"jwl", parameterList(kJwlFields), jwlExplosiveNames(),
       "JWL detonation products: `docs/eos_shock_jwl.md`"},
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
