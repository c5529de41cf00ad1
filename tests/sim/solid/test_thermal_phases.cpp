// Temperatures with phase changes (sim/solid/thermal.hpp): T(u) against hand-computed points
// below, on and above each plateau; the melt and vapour fractions; the energy accounted for
// through the plateaus; and the seed's straight line kept where no latent heats are given.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "sim/solid/materials.hpp"
#include "sim/solid/thermal.hpp"
#include "support/material_scene_error.hpp"

namespace ejecta {
namespace {

// Round numbers, so every point below is a line of arithmetic: c_v 1000 J/kg/K from 300 K,
// melting at 1300 K with L_m = 400 kJ/kg, a liquid at 1500 J/kg/K boiling at 2300 K with
// L_v = 10 MJ/kg, a vapour at 2000 J/kg/K.
ThermalModel roundNumbers() {
  ThermalModel t;
  t.specificHeat = 1000.0;
  t.initialTemperature = 300.0;
  t.meltTemperature = 1300.0;
  t.meltLatentHeat = 4e5;
  t.liquidSpecificHeat = 1500.0;
  t.boilTemperature = 2300.0;
  t.vapourLatentHeat = 1e7;
  t.vapourSpecificHeat = 2000.0;
  return t;
}

TEST(ThermalPhases, TemperatureHasPlateausAtTheMeltingAndBoilingPoints) {
  const ThermalModel t = roundNumbers();
  // Solid: 300 K + u / 1000; the melt starts at u = 1000 x 1000 = 1 MJ/kg.
  EXPECT_DOUBLE_EQ(t.temperature(0.0), 300.0);
  EXPECT_DOUBLE_EQ(t.temperature(5e5), 800.0);
  EXPECT_DOUBLE_EQ(t.temperature(1e6), 1300.0);
  // On the melting plateau, 1.0-1.4 MJ/kg: 1300 K, molten fraction (u - 1e6) / 4e5.
  EXPECT_DOUBLE_EQ(t.temperature(1.2e6), 1300.0);
  EXPECT_DOUBLE_EQ(t.meltFraction(1.2e6), 0.5);
  EXPECT_DOUBLE_EQ(t.vapourFraction(1.2e6), 0.0);
  // Liquid: 1300 K + (u - 1.4e6) / 1500 up to 2300 K at u = 1.4e6 + 1.5e6 = 2.9 MJ/kg.
  EXPECT_DOUBLE_EQ(t.temperature(2.15e6), 1800.0);
  EXPECT_DOUBLE_EQ(t.meltFraction(2.15e6), 1.0);
  EXPECT_DOUBLE_EQ(t.temperature(2.9e6), 2300.0);
  // Boiling, 2.9-12.9 MJ/kg: 2300 K, vapour fraction (u - 2.9e6) / 1e7.
  EXPECT_DOUBLE_EQ(t.temperature(7.9e6), 2300.0);
  EXPECT_DOUBLE_EQ(t.vapourFraction(7.9e6), 0.5);
  EXPECT_DOUBLE_EQ(t.meltFraction(7.9e6), 1.0);
  // Vapour: 2300 K + (u - 12.9e6) / 2000.
  EXPECT_DOUBLE_EQ(t.temperature(14.9e6), 3300.0);
  EXPECT_DOUBLE_EQ(t.vapourFraction(14.9e6), 1.0);
  // The seed's line would have put 14.9 MJ/kg at 15200 K.
  ThermalModel seed = t;
  seed.meltLatentHeat = seed.vapourLatentHeat = 0.0;
  EXPECT_DOUBLE_EQ(seed.temperature(14.9e6), 15200.0);
}

// Every joule is somewhere: sensible heat of each phase up to T plus the latent heat of the
// fractions that changed phase adds back to u, at every energy (and T(u) is continuous).
TEST(ThermalPhases, TheEnergyIsAccountedForThroughThePlateaus) {
  const ThermalModel t = roundNumbers();
  double previous = t.temperature(0.0);
  for (double u = 0.0; u <= 2e7; u += 1234.5) {
    const double T = t.temperature(u);
    const double solid = t.specificHeat * (std::min(T, 1300.0) - 300.0);
    const double liquid = 1500.0 * std::clamp(T - 1300.0, 0.0, 1000.0);
    const double vapour = 2000.0 * std::max(T - 2300.0, 0.0);
    const double latent = t.meltFraction(u) * 4e5 + t.vapourFraction(u) * 1e7;
    ASSERT_NEAR(solid + liquid + vapour + latent, u, 1e-6 * (u + 1.0)) << u;
    ASSERT_GE(T, previous) << u;                 // monotone
    ASSERT_LE(T - previous, 1234.5 / 1000.0 + 1e-9) << u;  // no jump
    previous = T;
  }
}

std::string sceneWithThermal(const std::string& thermal) {
  return "[scene]\nname = \"t\"\ndimension = \"1d\"\n[time]\nt_end = 1e-6\n"
         "[[materials]]\nname = \"al\"\neos = \"tillotson\"\nlibrary = \"aluminium\"\n"
         "[materials.thermal]\n" + thermal +
         "\n[[bodies]]\nname = \"b\"\nmaterial = \"al\"\nshape = \"box\"\nmin = [0.0]\n"
         "max = [0.01]\nspacing = 0.001\ndensity = 2700.0\npressure = 0.0\n";
}

TEST(ThermalPhases, TheLibrarySuppliesLatentHeatsOnRequest) {
  auto thermalOf = [](const std::string& keys) {
    const Scene s = parseScene(sceneWithThermal(keys), "t.toml");
    return MaterialTable::fromScene(s)[0].thermal;
  };
  EXPECT_FALSE(thermalOf("").phaseChanges());  // the seed's line by default
  const ThermalModel al = thermalOf("phase_changes = true");
  EXPECT_TRUE(al.phaseChanges());
  EXPECT_GT(al.meltLatentHeat, 0.0);
  EXPECT_GT(al.boilTemperature, al.meltTemperature);
  EXPECT_GT(al.vapourLatentHeat, al.meltLatentHeat);
  // A key overrides the library's value.
  EXPECT_DOUBLE_EQ(thermalOf("phase_changes = true\nlatent_heat_melting = \"0.3 MJ/kg\"").meltLatentHeat, 3e5);
  const std::string contradiction = test::materialSceneError(
      sceneWithThermal("phase_changes = false\nlatent_heat_melting = \"0.3 MJ/kg\""));
  EXPECT_NE(contradiction.find("phase_changes = false"), std::string::npos) << contradiction;
  const std::string boil = test::materialSceneError(sceneWithThermal(
      "latent_heat_melting = \"0.3 MJ/kg\"\nboiling_temperature = \"500 K\""));
  EXPECT_NE(boil.find("boiling_temperature must exceed"), std::string::npos) << boil;
}

}  // namespace
}  // namespace ejecta
