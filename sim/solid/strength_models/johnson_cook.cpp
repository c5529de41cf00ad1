#include "sim/solid/strength_models/johnson_cook.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sim/solid/strength_library.hpp"

namespace ejecta {

double JohnsonCookYield::flowStress(double epsP, double strainRate, double temperature,
                                    double meltTemperature, double, double) const {
  const JohnsonCookParameters& jc = p_;
  const double hardening = jc.A + jc.B * std::pow(std::max(epsP, 0.0), jc.n);
  // Rates below the reference rate do not soften (the usual floor of ln eps_dot* at 0).
  const double rateRatio = std::max(strainRate / jc.referenceStrainRate, 1.0);
  const double rate = 1.0 + jc.C * std::log(rateRatio);
  double thermal = 1.0;
  if (temperature > jc.roomTemperature) {
    const double homologous =
        (temperature - jc.roomTemperature) / (meltTemperature - jc.roomTemperature);
    thermal = std::max(1.0 - std::pow(homologous, jc.m), 0.0);
  }
  return hardening * rate * thermal;
}

StrengthModelRow johnsonCookStrengthRow() {
  using namespace config::keys;
  const Dimension kPa = Dimension::Pressure;
  return {"johnson_cook",
          "Johnson-Cook flow stress (A + B εpⁿ)(1 + C ln(ε̇/ε̇0))(1 − T*ᵐ)",
          {quantity("A", kPa, "required without a library", "Johnson-Cook yield stress A"),
           quantity("B", kPa, "required without a library", "Johnson-Cook hardening modulus B"),
           number("n", "required without a library", "Johnson-Cook hardening exponent n"),
           number("C", "required without a library", "Johnson-Cook strain-rate coefficient C"),
           number("m", "required without a library", "Johnson-Cook thermal-softening exponent m"),
           quantity("reference_strain_rate", Dimension{0, 0, -1, 0}, "1", "Johnson-Cook ε̇0, > 0"),
           quantity("room_temperature", Dimension::Temperature, "\"293 K\"", "Johnson-Cook T_room")},
          {"A", "B", "n", "C", "m"},
          [](const ModelSpec& s, const StrengthLibraryEntry* entry) -> std::shared_ptr<const YieldSurface> {
            JohnsonCookParameters jc = entry ? entry->johnsonCook : JohnsonCookParameters{};
            jc.A = s.valueOr("A", jc.A);
            jc.B = s.valueOr("B", jc.B);
            jc.n = s.valueOr("n", jc.n);
            jc.C = s.valueOr("C", jc.C);
            jc.m = s.valueOr("m", jc.m);
            jc.referenceStrainRate = s.valueOr("reference_strain_rate", jc.referenceStrainRate);
            jc.roomTemperature = s.valueOr("room_temperature", jc.roomTemperature);
            if (!(jc.referenceStrainRate > 0.0))
              throw std::invalid_argument("strength.reference_strain_rate must be positive");
            return std::make_shared<JohnsonCookYield>(jc);
          }};
}

}  // namespace ejecta
