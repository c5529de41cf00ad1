#include "sim/solid/materials.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/input_error.hpp"
#include "sim/eos/eos_catalog.hpp"
#include "sim/solid/material_spec.hpp"
#include "sim/solid/strength_catalog.hpp"

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
  if (!spec.strength.present) return std::nullopt;
  return buildStrength(spec.strength, strengthCatalog(), melt);
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
