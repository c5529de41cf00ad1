#include "sim/solid/model_keys.hpp"

#include <utility>

#include "sim/solid/strength_catalog.hpp"

namespace ejecta {

namespace {

using namespace config::keys;
const Dimension kPa = Dimension::Pressure;
const Dimension kKelvin = Dimension::Temperature;
const Dimension kPerVolume{0, -3, 0, 0};
const Dimension kSpecificHeat{0, 2, -2, -1};
const Dimension kSpecificEnergy = Dimension::SpecificEnergy;

// Defaults are those sim/solid/materials.cpp applies (ThermalModel, FractureModel).
std::vector<std::string_view> modelNames(const std::vector<ModelKind>& models) {
  std::vector<std::string_view> out;
  for (const ModelKind& m : models) out.push_back(m.name);
  return out;
}

}  // namespace

const ModelFamily& thermalModelFamily() {
  static const ModelFamily family{
      "thermal",
      {},
      {text("library", "the eos library's name",
            "thermal library entry (specific heat, melting point)"),
       quantity("specific_heat", kSpecificHeat, "library; ideal gas: R/((γ − 1) M)",
                "specific heat c_v [J/(kg K)]"),
       number("mean_atomic_mass", "—", "g/mol per atom: c_v = 3R/M (Dulong-Petit)"),
       number("molar_mass", "28.9644", "ideal gas: molar mass in g/mol (default: dry air)"),
       quantity("initial_temperature", kKelvin, "\"293 K\"", "T0 at u = 0"),
       quantity("melt_temperature", kKelvin, "strength or thermal library; else never",
                "strength vanishes at and above it"),
       boolean("phase_changes", "false",
               "latent heats of melting and vaporisation from the thermal library: T(u) has "
               "plateaus at T_melt and T_boil (docs/thermal.md); false: T0 + u/c_v (the seed's)"),
       quantity("latent_heat_melting", kSpecificEnergy, "library, with phase_changes",
                "L_m [J/kg]; giving it turns phase changes on"),
       quantity("boiling_temperature", kKelvin, "library, with phase_changes",
                "T_b: the vaporisation plateau"),
       quantity("latent_heat_vaporisation", kSpecificEnergy, "library, with phase_changes",
                "L_v [J/kg]"),
       quantity("liquid_specific_heat", kSpecificHeat, "specific_heat",
                "c_v of the melt, between T_melt and T_boil"),
       quantity("vapour_specific_heat", kSpecificHeat, "liquid_specific_heat",
                "c_v of the vapour, above T_boil")}};
  return family;
}

// The strength models and their keys are the rows of sim/solid/strength_catalog.hpp.
const ModelFamily& strengthModelFamily() {
  static const ModelFamily family = [] {
    ModelFamily f{"strength", {}, {}};
    const std::vector<StrengthModelRow>& rows = strengthCatalog();
    for (const StrengthModelRow& r : rows) {
      ModelKind kind{r.name, r.doc, {"shear_modulus"}};
      for (const config::KeySpec& k : r.keys) kind.keys.push_back(k.name);
      f.models.push_back(std::move(kind));
    }
    f.keys = {
        choice("model", modelNames(f.models), "required", "the yield model (below)"),
        text("library", "—", "a published set of G, the Johnson-Cook constants and T_melt"),
        quantity("shear_modulus", kPa, "required without a library", "shear modulus G"),
    };
    // Each model's keys, in catalog order; a key two models share is listed once.
    for (const StrengthModelRow& r : rows)
      for (const config::KeySpec& k : r.keys)
        if (!config::findKey(f.keys, k.name)) f.keys.push_back(k);
    return f;
  }();
  return family;
}

const ModelFamily& fractureModelFamily() {
  static const ModelFamily family = [] {
    ModelFamily f{"fracture",
                  {{"none", "no crack growth: erosion alone, if erosion_strain is given", {}},
                   {"grady_kipp",
                    "Grady-Kipp / Benz-Asphaug Weibull flaws; needs a strength table",
                    {"weibull_k", "weibull_m"}},
                   {"principal_stress", "fails where the largest principal stress exceeds it",
                    {"tensile_strength"}}},
                  {}};
    f.keys = {
        choice("model", modelNames(f.models), "required", "the fracture model (below)"),
        quantity("weibull_k", kPerVolume, "required for grady_kipp", "Weibull constant k"),
        number("weibull_m", "required for grady_kipp", "Weibull exponent m"),
        quantity("tensile_strength", kPa, "required for principal_stress",
                 "principal-stress failure threshold"),
        number("erosion_strain", "none (never)",
               "any model: fail (D = 1) above this equivalent strain"),
        number("crack_speed_factor", "0.4", "crack growth speed c_g / c_l"),
        number("max_crack_increment", "0.3",
               "the most a crack fraction s = D^(1/3) may grow in one step, in (0, 1]: it limits "
               "the time step (0.1 converges fragment speeds at 2.7x the steps, "
               "docs/fragmentation.md)"),
        integer("seed", "1", "seed of the flaw draw, ≥ 0"),
    };
    return f;
  }();
  return family;
}

// The porosity models (sim/solid/porosity.hpp); docs/porosity.md has their sources.
const ModelFamily& porosityModelFamily() {
  static const ModelFamily family = [] {
    ModelFamily f{"porosity",
                  {{"p_alpha",
                    "P-alpha (Herrmann 1969; Jutzi, Benz & Michel 2008): the distention falls "
                    "along a crush curve in pressure",
                    {"porosity", "initial_distention", "elastic_pressure", "solid_pressure",
                     "crush_exponent", "transition_pressure", "transition_distention",
                     "transition_exponent", "solid_density", "porous_sound_speed",
                     "max_distention_change"}},
                   {"epsilon_alpha",
                    "epsilon-alpha (Wünnemann, Collins & Melosh 2006; Collins, Melosh & "
                    "Wünnemann 2011): the distention falls with the volumetric strain",
                    {"porosity", "initial_distention", "elastic_strain", "transition_distention",
                     "kappa", "sound_speed_ratio", "thermal_strain", "solid_density",
                     "max_distention_change"}}},
                  {}};
    f.keys = {
        choice("model", modelNames(f.models), "required", "the porosity model (below)"),
        number("porosity", "—", "initial porosity φ0 in [0, 1): α0 = 1/(1 − φ0); or give "
               "initial_distention"),
        number("initial_distention", "—", "initial distention α0 = ρ_solid/ρ > 1"),
        quantity("elastic_pressure", Dimension::Pressure, "required",
                 "Pe: plastic compaction begins"),
        quantity("solid_pressure", Dimension::Pressure, "required",
                 "Ps: fully compacted (α = 1)"),
        number("crush_exponent", "2", "n of the crush curve α = 1 + (αe − 1)((Ps − P)/(Ps − Pe))^n"),
        quantity("transition_pressure", Dimension::Pressure, "solid_pressure",
                 "Pt of the two-segment curve (docs/porosity.md)"),
        number("transition_distention", "αe (one segment); required (epsilon_alpha)",
               "p_alpha: αt of the two-segment curve, in [1, αe]; epsilon_alpha: αx, where the "
               "exponential gives way to the power law, in [1, αe]"),
        number("transition_exponent", "2", "n1 of the two-segment curve's first segment"),
        number("elastic_strain", "0",
               "epsilon_alpha: |εe|, the volumetric strain's magnitude where plastic compaction "
               "begins (iSALE's EPSE0, which its inputs give negative, is εe)"),
        number("kappa", "required", "epsilon_alpha: κ in (0, 1), the exponential's rate "
               "α = αe exp(κ (ε − εe))"),
        number("sound_speed_ratio", "1",
               "epsilon_alpha: χ = c0/cs0 in (0, 1], the porous to the matrix's sound speed at "
               "α0 (iSALE's CHI; 1: no elastic compaction)"),
        boolean("thermal_strain", "true",
                "epsilon_alpha: leave the matrix's thermal expansion Γ0/cs0² du out of the "
                "strain that compacts (iSALE, Spheral; false: miluphcuda)"),
        quantity("solid_density", Dimension::Density, "the eos reference density",
                 "ρ_s0: the matrix's density at P = 0"),
        quantity("porous_sound_speed", Dimension::Velocity, "the matrix's (rigid pores below Pe)",
                 "p_alpha: c_e, the porous material's sound speed at α0"),
        number("max_distention_change", "0.02",
               "the most α may change in one step: it limits the time step"),
    };
    return f;
  }();
  return family;
}

}  // namespace ejecta
