#include "sim/solid/materials.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/input_error.hpp"
#include "sim/eos/eos_catalog.hpp"
#include "sim/solid/material_spec.hpp"

namespace ejecta {

namespace {

[[noreturn]] void fail(const std::string& what) { throw std::invalid_argument(what); }

double valueOr(const ModelSpec& spec, std::string_view key, double fallback) {
  const double* v = spec.find(key);
  return v ? *v : fallback;
}

// Thermal data: the [materials.thermal] keys, else the thermal library entry named by
// thermal.library or by the eos library, else (ideal gas) R / ((gamma - 1) M).
ThermalModel makeThermal(const MaterialSpec& spec, const std::optional<double>& strengthMelt) {
  const ModelSpec& t = spec.thermal;
  const std::string libraryName = !t.library.empty() ? t.library : spec.library;
  const ThermalLibraryEntry* entry = libraryName.empty() ? nullptr : findThermalEntry(libraryName);
  if (!t.library.empty() && !entry) {
    std::string known;
    for (const ThermalLibraryEntry& e : thermalLibrary()) known += (known.empty() ? "" : ", ") + e.name;
    fail("thermal.library: no entry '" + t.library + "'; known: " + known);
  }
  ThermalModel model;
  model.initialTemperature = valueOr(t, "initial_temperature", model.initialTemperature);
  if (const double* c = t.find("specific_heat")) {
    model.specificHeat = *c;
  } else if (const double* m = t.find("mean_atomic_mass")) {
    model.specificHeat = dulongPetitSpecificHeat(*m * 1e-3);  // given in g/mol
  } else if (entry) {
    model.specificHeat = entry->specificHeat;
  } else if (spec.eos == "ideal_gas") {
    model.specificHeat = idealGasSpecificHeat(spec.gamma, valueOr(t, "molar_mass", kAirMolarMass * 1e3) * 1e-3);
  } else {
    fail("no specific heat for the temperature: give [materials.thermal] specific_heat (J/kg/K) "
         "or mean_atomic_mass (g/mol, Dulong-Petit), or a thermal library entry");
  }
  if (!(model.specificHeat > 0.0)) fail("thermal.specific_heat must be positive");
  if (const double* tm = t.find("melt_temperature")) model.meltTemperature = *tm;
  else if (strengthMelt) model.meltTemperature = *strengthMelt;
  else if (entry) model.meltTemperature = entry->meltTemperature;
  return model;
}

std::optional<StrengthModel> makeStrength(const MaterialSpec& spec, std::optional<double>& melt) {
  const ModelSpec& s = spec.strength;
  if (!s.present) return std::nullopt;
  StrengthModel model;
  const StrengthLibraryEntry* entry = nullptr;
  if (!s.library.empty()) {
    entry = findStrengthEntry(s.library);
    if (!entry) {
      std::string known;
      for (const StrengthLibraryEntry& e : strengthLibrary()) known += (known.empty() ? "" : ", ") + e.name;
      fail("strength.library: no entry '" + s.library + "'; known: " + known);
    }
    model.shearModulus = entry->shearModulus;
    model.yieldStress = entry->yieldStress;
    model.johnsonCook = entry->johnsonCook;
    melt = entry->meltTemperature;
  }
  model.yield = s.model == "elastic"     ? YieldModel::Elastic
                : s.model == "von_mises" ? YieldModel::VonMises
                : s.model == "collins"   ? YieldModel::Collins
                                         : YieldModel::JohnsonCook;
  model.shearModulus = valueOr(s, "shear_modulus", model.shearModulus);
  if (!(model.shearModulus > 0.0)) fail("strength.shear_modulus is required and must be positive");
  if (model.yield == YieldModel::VonMises) {
    model.yieldStress = valueOr(s, "yield_stress", model.yieldStress);
    if (!s.find("yield_stress") && !(entry && entry->yield == YieldModel::VonMises))
      fail("strength.yield_stress is required for model \"von_mises\"");
  }
  if (model.yield == YieldModel::JohnsonCook) {
    JohnsonCookParameters& jc = model.johnsonCook;
    const bool fromLibrary = entry && entry->yield == YieldModel::JohnsonCook;
    for (const char* key : {"A", "B", "n", "C", "m"})
      if (!fromLibrary && !s.find(key))
        fail(std::string("strength.") + key + " is required for model \"johnson_cook\" without a library");
    jc.A = valueOr(s, "A", jc.A);
    jc.B = valueOr(s, "B", jc.B);
    jc.n = valueOr(s, "n", jc.n);
    jc.C = valueOr(s, "C", jc.C);
    jc.m = valueOr(s, "m", jc.m);
    jc.referenceStrainRate = valueOr(s, "reference_strain_rate", jc.referenceStrainRate);
    jc.roomTemperature = valueOr(s, "room_temperature", jc.roomTemperature);
    if (!(jc.referenceStrainRate > 0.0)) fail("strength.reference_strain_rate must be positive");
  }
  for (const char* key : {"yield_stress", "A", "B", "n", "C", "m"})
    if (s.find(key) && (model.yield == YieldModel::Elastic || model.yield == YieldModel::Collins))
      fail(std::string("strength.") + key + " does not apply to model \"" + s.model + "\"");
  const char* collinsKeys[] = {"cohesion", "friction_intact", "strength_limit", "friction_damaged",
                               "cohesion_damaged"};
  if (model.yield == YieldModel::Collins) {
    for (const char* key : collinsKeys)
      if (!s.find(key) && std::string_view(key) != "cohesion_damaged")  // optional, default 0
        fail(std::string("strength.") + key + " is required for model \"collins\"");
    CollinsParameters& c = model.collins;
    c.cohesion = valueOr(s, "cohesion", 0.0);
    c.frictionIntact = valueOr(s, "friction_intact", 0.0);
    c.strengthLimit = valueOr(s, "strength_limit", 0.0);
    c.frictionDamaged = valueOr(s, "friction_damaged", 0.0);
    c.cohesionDamaged = valueOr(s, "cohesion_damaged", 0.0);  // Collins et al. (2004): none
    if (!(c.frictionIntact > 0.0)) fail("strength.friction_intact must be positive");
    if (!(c.strengthLimit > c.cohesion))
      fail("strength.strength_limit must exceed strength.cohesion (the Lundborg curve rises from "
           "the cohesion to the limit)");
  } else {
    for (const char* key : collinsKeys)
      if (s.find(key)) fail(std::string("strength.") + key + " applies only to model \"collins\"");
  }
  return model;
}

FractureModel makeFracture(const MaterialSpec& spec, bool hasStrength) {
  const ModelSpec& f = spec.fracture;
  FractureModel model;
  if (!f.present) return model;
  model.erosionStrain = valueOr(f, "erosion_strain", model.erosionStrain);
  model.crackSpeedFactor = valueOr(f, "crack_speed_factor", model.crackSpeedFactor);
  model.maxCrackIncrement = valueOr(f, "max_crack_increment", model.maxCrackIncrement);
  if (!(model.maxCrackIncrement > 0.0 && model.maxCrackIncrement <= 1.0))
    fail("fracture.max_crack_increment must be in (0, 1]: the most a crack fraction may grow in one step");
  model.seed = static_cast<std::uint64_t>(valueOr(f, "seed", 1.0));
  if (f.model == "none") return model;  // erosion alone, if erosion_strain is given
  if (f.model == "grady_kipp") {
    model.kind = FractureKind::GradyKipp;
    if (!f.find("weibull_k") || !f.find("weibull_m"))
      fail("fracture model \"grady_kipp\" needs weibull_k (m^-3) and weibull_m");
    model.weibull.k = *f.find("weibull_k");
    model.weibull.m = *f.find("weibull_m");
    if (!(model.weibull.k > 0.0) || !(model.weibull.m > 0.0))
      fail("fracture.weibull_k and weibull_m must be positive");
    if (!hasStrength)
      fail("fracture model \"grady_kipp\" needs a [materials.strength] table: the local strain "
           "is the tensile stress over Young's modulus, which needs the shear modulus");
  } else {
    model.kind = FractureKind::PrincipalStress;
    if (!f.find("tensile_strength"))
      fail("fracture model \"principal_stress\" needs tensile_strength");
    model.tensileStrength = *f.find("tensile_strength");
  }
  return model;
}

}  // namespace

MaterialTable MaterialTable::fromSpecs(const std::vector<MaterialSpec>& specs,
                                       const std::string& sourcePath) {
  MaterialTable table;
  for (const MaterialSpec& spec : specs) {
    try {
      Material m;
      m.name = spec.name;
      m.eos = makeEquationOfState(spec);
      std::optional<double> melt;
      m.strength = makeStrength(spec, melt);
      m.thermal = makeThermal(spec, melt);
      m.fracture = makeFracture(spec, m.strength.has_value());
      table.add(std::move(m));
    } catch (const std::invalid_argument& e) {
      throw SceneError(sourcePath + ":" + std::to_string(spec.line) + ": material '" +
                       spec.name + "': " + e.what());
    }
  }
  return table;
}

bool MaterialTable::anyStrength() const {
  for (const Material& m : materials_)
    if (m.strength) return true;
  return false;
}

bool MaterialTable::anyFracture() const {
  for (const Material& m : materials_)
    if (m.fracture.kind != FractureKind::None ||
        m.fracture.erosionStrain < std::numeric_limits<double>::infinity())
      return true;
  return false;
}

}  // namespace ejecta
