#include "sim/solid/model_keys.hpp"

namespace ejecta {

namespace {

using namespace config::keys;
const Dimension kPa = Dimension::Pressure;
const Dimension kKelvin = Dimension::Temperature;
const Dimension kPerVolume{0, -3, 0, 0};
const Dimension kPerTime{0, 0, -1, 0};
const Dimension kSpecificHeat{0, 2, -2, -1};

// Defaults are those sim/solid/materials.cpp applies (ThermalModel, JohnsonCookParameters,
// FractureModel).
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
                "strength vanishes at and above it")}};
  return family;
}

const ModelFamily& strengthModelFamily() {
  static const ModelFamily family = [] {
    ModelFamily f{"strength",
                  {{"elastic", "elastic shear stress, no yield", {"shear_modulus"}},
                   {"von_mises", "perfectly plastic, yield stress Y", {"shear_modulus", "yield_stress"}},
                   {"johnson_cook",
                    "Johnson-Cook flow stress (A + B εpⁿ)(1 + C ln(ε̇/ε̇0))(1 − T*ᵐ)",
                    {"shear_modulus", "A", "B", "n", "C", "m", "reference_strain_rate",
                     "room_temperature"}},
                   {"collins",
                    "pressure-dependent rock, Collins et al. (2004): intact Lundborg curve, "
                    "damaged Coulomb line",
                    {"shear_modulus", "cohesion", "friction_intact", "strength_limit",
                     "friction_damaged", "cohesion_damaged"}}},
                  {}};
    f.keys = {
        choice("model", modelNames(f.models), "required", "the yield model (below)"),
        text("library", "—", "a published set of G, the Johnson-Cook constants and T_melt"),
        quantity("shear_modulus", kPa, "required without a library", "shear modulus G"),
        quantity("yield_stress", kPa, "required for von_mises", "von Mises yield stress Y"),
        quantity("A", kPa, "required without a library", "Johnson-Cook yield stress A"),
        quantity("B", kPa, "required without a library", "Johnson-Cook hardening modulus B"),
        number("n", "required without a library", "Johnson-Cook hardening exponent n"),
        number("C", "required without a library", "Johnson-Cook strain-rate coefficient C"),
        number("m", "required without a library", "Johnson-Cook thermal-softening exponent m"),
        quantity("reference_strain_rate", kPerTime, "1", "Johnson-Cook ε̇0, > 0"),
        quantity("room_temperature", kKelvin, "\"293 K\"", "Johnson-Cook T_room"),
        quantity("cohesion", kPa, "required for collins", "intact cohesion Y_0"),
        number("friction_intact", "required for collins", "intact friction coefficient μ_i, > 0"),
        quantity("strength_limit", kPa, "required for collins", "strength limit Y_M, > Y_0"),
        number("friction_damaged", "required for collins", "damaged friction coefficient μ_d"),
        quantity("cohesion_damaged", kPa, "0",
                 "damaged cohesion Y_d0: Y_d = Y_d0 + μ_d P (0, as in Collins et al.)"),
    };
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

}  // namespace ejecta
