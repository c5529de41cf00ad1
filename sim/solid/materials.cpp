#include "sim/solid/materials.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/input_error.hpp"
#include "core/join.hpp"
#include "sim/eos/eos_catalog.hpp"
#include "sim/solid/material_spec.hpp"
#include "sim/solid/model_keys.hpp"
#include "sim/solid/porosity.hpp"
#include "sim/solid/strain_porosity.hpp"
#include "sim/solid/strength_catalog.hpp"

namespace ejecta {

namespace {

[[noreturn]] void fail(const std::string& what) { throw std::invalid_argument(what); }

double valueOr(const ModelSpec& spec, std::string_view key, double fallback) {
  const double* v = spec.find(key);
  return v ? *v : fallback;
}

// Latent heats: phase_changes = true takes the thermal library's (docs/thermal.md), and the
// latent-heat keys give or override them; without either, the seed's straight line T0 + u/c_v.
void applyPhaseChanges(const ModelSpec& t, const ThermalLibraryEntry* entry, ThermalModel& model) {
  const double* flag = t.find("phase_changes");
  const bool explicitKeys = t.find("latent_heat_melting") || t.find("latent_heat_vaporisation") ||
                            t.find("boiling_temperature");
  if (flag && *flag == 0.0) {
    if (explicitKeys)
      fail("thermal: phase_changes = false, but latent_heat_melting, latent_heat_vaporisation or "
           "boiling_temperature is given");
    return;
  }
  if (!flag && !explicitKeys) return;
  if (flag && entry && entry->meltLatentHeat > 0.0) {
    model.meltLatentHeat = entry->meltLatentHeat;
    model.boilTemperature = entry->boilTemperature;
    model.vapourLatentHeat = entry->vapourLatentHeat;
    model.liquidSpecificHeat = entry->liquidSpecificHeat;
  }
  model.meltLatentHeat = valueOr(t, "latent_heat_melting", model.meltLatentHeat);
  model.boilTemperature = valueOr(t, "boiling_temperature", model.boilTemperature);
  model.vapourLatentHeat = valueOr(t, "latent_heat_vaporisation", model.vapourLatentHeat);
  model.liquidSpecificHeat = valueOr(t, "liquid_specific_heat", model.liquidSpecificHeat);
  model.vapourSpecificHeat = valueOr(t, "vapour_specific_heat", 0.0);
  if (!model.phaseChanges())
    fail("thermal.phase_changes: no latent heats for this material in the thermal library: give "
         "latent_heat_melting, boiling_temperature and latent_heat_vaporisation (J/kg, K)");
  if (!std::isfinite(model.meltTemperature))
    fail("thermal: phase changes need a melting point (melt_temperature)");
  if (!(model.boilTemperature > model.meltTemperature))
    fail("thermal.boiling_temperature must exceed the melting point (" +
         std::to_string(model.meltTemperature) + " K)");
}

// Thermal data: the [materials.thermal] keys, else the thermal library entry named by
// thermal.library or by the eos library, else (ideal gas) R / ((gamma - 1) M).
ThermalModel makeThermal(const MaterialSpec& spec, const std::optional<double>& strengthMelt) {
  const ModelSpec& t = spec.thermal;
  const std::string libraryName = !t.library.empty() ? t.library : spec.library;
  const ThermalLibraryEntry* entry = libraryName.empty() ? nullptr : findThermalEntry(libraryName);
  if (!t.library.empty() && !entry) {
    fail("thermal.library: no entry '" + t.library + "'; known: " +
         joinList(thermalLibrary(), &ThermalLibraryEntry::name));
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
  applyPhaseChanges(t, entry, model);
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

// The initial distention of a porosity table: from exactly one of porosity and
// initial_distention.
double initialDistentionOf(const ModelSpec& t) {
  const double* phi = t.find("porosity");
  const double* alpha0 = t.find("initial_distention");
  if ((phi != nullptr) == (alpha0 != nullptr))
    fail("porosity: give exactly one of porosity (phi_0) and initial_distention (alpha_0)");
  if (phi && !(*phi < 1.0)) fail("porosity.porosity must be below 1");
  return phi ? 1.0 / (1.0 - *phi) : *alpha0;
}

PalphaModel makePalpha(const ModelSpec& t, const EquationOfState& eos) {
  PalphaParameters p;
  p.initialDistention = initialDistentionOf(t);
  if (!t.find("elastic_pressure") || !t.find("solid_pressure"))
    fail("porosity model \"p_alpha\" needs elastic_pressure and solid_pressure (its crush curve)");
  p.elasticPressure = *t.find("elastic_pressure");
  p.solidPressure = *t.find("solid_pressure");
  p.crushExponent = valueOr(t, "crush_exponent", p.crushExponent);
  p.transitionPressure = valueOr(t, "transition_pressure", p.transitionPressure);
  p.transitionDistention = valueOr(t, "transition_distention", p.transitionDistention);
  p.transitionExponent = valueOr(t, "transition_exponent", p.transitionExponent);
  p.solidDensity = valueOr(t, "solid_density", eos.referenceDensity());
  if (p.solidDensity > 0.0) p.solidSoundSpeed = eos.soundSpeed(p.solidDensity, 0.0);
  p.porousSoundSpeed = valueOr(t, "porous_sound_speed", p.solidSoundSpeed);
  p.maxChangePerStep = valueOr(t, "max_distention_change", p.maxChangePerStep);
  if (!(p.maxChangePerStep > 0.0)) fail("porosity.max_distention_change must be positive");
  return PalphaModel(p);
}

EpsilonAlphaModel makeEpsilonAlpha(const ModelSpec& t, const EquationOfState& eos) {
  EpsilonAlphaParameters p;
  p.initialDistention = initialDistentionOf(t);
  if (!t.find("transition_distention") || !t.find("kappa"))
    fail("porosity model \"epsilon_alpha\" needs transition_distention (alpha_x) and kappa");
  // The scene gives the elastic strain's magnitude (compression is negative).
  p.elasticStrain = -valueOr(t, "elastic_strain", 0.0);
  p.transitionDistention = *t.find("transition_distention");
  p.kappa = *t.find("kappa");
  p.soundSpeedRatio = valueOr(t, "sound_speed_ratio", p.soundSpeedRatio);
  p.thermalStrain = valueOr(t, "thermal_strain", 1.0) != 0.0;
  p.solidDensity = valueOr(t, "solid_density", 0.0);
  p.maxChangePerStep = valueOr(t, "max_distention_change", p.maxChangePerStep);
  return EpsilonAlphaModel::onMatrix(p, eos);
}

// The porosity table's model on the material's equation of state (its matrix).
std::shared_ptr<const PorosityModel> makePorosity(const MaterialSpec& spec,
                                                  const EquationOfState& eos) {
  const ModelSpec& t = spec.porosity;
  if (!t.present) return nullptr;
  // A key of the other model is a mistake worth naming (kappa under p_alpha, say).
  const ModelFamily& family = porosityModelFamily();
  for (const auto& [key, value] : t.values) {
    std::string owners;
    bool own = false;
    for (const ModelKind& m : family.models) {
      if (std::find(m.keys.begin(), m.keys.end(), key) == m.keys.end()) continue;
      own = own || m.name == t.model;
      owners += (owners.empty() ? "\"" : ", \"") + std::string(m.name) + "\"";
    }
    if (!own)
      fail("porosity." + key + " does not apply to model \"" + t.model + "\"; it applies only to " +
           owners);
  }
  if (t.model == "epsilon_alpha") return std::make_shared<EpsilonAlphaModel>(makeEpsilonAlpha(t, eos));
  return std::make_shared<PalphaModel>(makePalpha(t, eos));
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
      m.porosity = makePorosity(spec, *m.eos);
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

bool MaterialTable::anyPhaseChanges() const {
  for (const Material& m : materials_)
    if (m.thermal.phaseChanges()) return true;
  return false;
}

bool MaterialTable::anyPorosity() const {
  for (const Material& m : materials_)
    if (m.porosity) return true;
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
