// Strength, fracture and thermal models (issue 3): hand-computed points and limits of each
// model, the scene keys that build them, and a bit-for-bit restart of a run that uses them all.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "sim/bodies.hpp"
#include "sim/fracture.hpp"
#include "sim/run.hpp"
#include "sim/snapshot.hpp"
#include "sim/strength.hpp"
#include "sim/tensor.hpp"
#include "sim/thermal.hpp"

namespace fs = std::filesystem;

namespace ejecta {
namespace {

TEST(Tensor, JacobiEigenpairsOfASymmetricTensor) {
  // A rotated diag(3, -1, 2): eigenvalues recovered to round-off, vectors orthonormal.
  SymTensor a;
  const double c = std::cos(0.3), s = std::sin(0.3);
  // R diag(3, -1) R^T in the x-y plane, 2 on z, plus nothing else.
  a[kXX] = 3 * c * c + (-1) * s * s;
  a[kYY] = 3 * s * s + (-1) * c * c;
  a[kXY] = (3 - (-1)) * c * s;
  a[kZZ] = 2.0;
  std::array<double, 3> values;
  Mat3 vectors;
  symmetricEigen(a, values, &vectors);
  EXPECT_NEAR(values[0], -1.0, 1e-13);
  EXPECT_NEAR(values[1], 2.0, 1e-13);
  EXPECT_NEAR(values[2], 3.0, 1e-13);
  EXPECT_NEAR(std::abs(vectors[0][2]), c, 1e-12);  // the eigenvector of 3 is (c, s, 0)
  EXPECT_NEAR(std::abs(vectors[1][2]), s, 1e-12);
  double lo, hi, ct, st;
  planeEigen(a[kXX], a[kYY], a[kXY], lo, hi, ct, st);
  EXPECT_NEAR(lo, -1.0, 1e-13);
  EXPECT_NEAR(hi, 3.0, 1e-13);
  EXPECT_NEAR(ct, c, 1e-13);
  EXPECT_NEAR(st, s, 1e-13);
}

TEST(Strength, HookeRateOfUniaxialStrainAndJaumannRotation) {
  const double G = 30e9;
  // Uniaxial strain rate: dS_xx/dt = 2G (1 - 1/3) e, dS_yy/dt = dS_zz/dt = -2G/3 e.
  Mat3 L{};
  L[0][0] = 1e3;
  SymTensor zero;
  const SymTensor r = jaumannStressRate(L, zero, G);
  EXPECT_DOUBLE_EQ(r[kXX], 4.0 / 3.0 * G * 1e3);
  EXPECT_DOUBLE_EQ(r[kYY], -2.0 / 3.0 * G * 1e3);
  EXPECT_DOUBLE_EQ(r[kZZ], -2.0 / 3.0 * G * 1e3);
  // Rigid rotation (spin w about z): a stress S = diag(s, -s, 0) rotates, dS_xy/dt = -2 s w...
  // checked against the rotated tensor R(wt) S R(wt)^T differentiated at t = 0.
  Mat3 spin{};
  const double w = 5.0;
  spin[0][1] = -w;  // v = w x r = (-w y, w x): L = [[0, -w], [w, 0]]
  spin[1][0] = w;
  SymTensor S;
  S[kXX] = 1e8;
  S[kYY] = -1e8;
  const SymTensor rot = jaumannStressRate(spin, S, G);
  // d/dt (R S R^T) = W S - S W for W = L (antisymmetric): xy component = w (Sxx - Syy).
  EXPECT_NEAR(rot[kXY], w * 2e8, 1e-6);
  EXPECT_NEAR(rot[kXX], 0.0, 1e-6);
  EXPECT_NEAR(equivalentStrainRate(spin), 0.0, 1e-12);  // no deformation in a rotation
}

TEST(Strength, RadialReturnScalesOntoTheYieldSurface) {
  SymTensor S;
  S[kXX] = 2e8;
  S[kYY] = -1e8;
  S[kZZ] = -1e8;
  const double vonMises = std::sqrt(3.0 * secondInvariant(S));  // 3e8
  EXPECT_NEAR(vonMises, 3e8, 1e-3);
  const double G = 25e9;
  const double dEp = radialReturn(S, 2e8, G);
  EXPECT_NEAR(std::sqrt(3.0 * secondInvariant(S)), 2e8, 1e-3);
  EXPECT_NEAR(dEp, 1e8 / (3.0 * G), 1e-15);
  EXPECT_EQ(radialReturn(S, 5e8, G), 0.0);  // inside: untouched
  EXPECT_EQ(radialReturn(S, 0.0, G) > 0.0, true);  // molten: no deviatoric stress left
  EXPECT_EQ(S[kXX], 0.0);
}

TEST(Strength, JohnsonCookFlowStressByHand) {
  const StrengthLibraryEntry* al = findStrengthEntry("Al-2024-T351");
  ASSERT_NE(al, nullptr);
  StrengthModel m;
  m.yield = YieldModel::JohnsonCook;
  m.shearModulus = al->shearModulus;
  m.johnsonCook = al->johnsonCook;
  const double Tm = al->meltTemperature, Tr = al->johnsonCook.roomTemperature;
  // Quasi-static, room temperature, no plastic strain: A.
  EXPECT_DOUBLE_EQ(m.flowStress(0.0, 1.0, Tr, Tm), 265e6);
  // eps_p = 0.1, rate 1e3/s, halfway to melt: (265 + 426 * 0.1^0.34)(1 + 0.015 ln 1000)(1 - 0.5).
  const double expected = (265e6 + 426e6 * std::pow(0.1, 0.34)) * (1 + 0.015 * std::log(1e3)) * 0.5;
  EXPECT_NEAR(m.flowStress(0.1, 1e3, 0.5 * (Tr + Tm), Tm), expected, 1e-6 * expected);
  EXPECT_EQ(m.flowStress(0.1, 1e3, Tm, Tm), 0.0);  // melting drops strength to zero
  EXPECT_DOUBLE_EQ(m.flowStress(0.0, 1e-3, Tr, Tm), 265e6);  // slower than eps_dot_0: no softening
  m.yield = YieldModel::Elastic;
  EXPECT_TRUE(std::isinf(m.flowStress(1.0, 1.0, Tr, Tm)));
}

TEST(Fracture, CrackGrowthRateAndItsCap) {
  // One active flaw of four: grows at c_g / R_s until D = 1/4, i.e. s = 4^(-1/3).
  EXPECT_DOUBLE_EQ(crackGrowthRate(1, 4, 0.0, 5000.0, 1e-3, 0.4), 0.4 * 5000.0 / 1e-3);
  EXPECT_EQ(crackGrowthRate(1, 4, std::cbrt(0.25), 5000.0, 1e-3, 0.4), 0.0);
  EXPECT_EQ(crackGrowthRate(0, 4, 0.0, 5000.0, 1e-3, 0.4), 0.0);
  EXPECT_DOUBLE_EQ(youngsModulus(50e9, 30e9), 9.0 * 50e9 * 30e9 / (150e9 + 30e9));
}

TEST(Thermal, DulongPetitAndIdealGasSpecificHeats) {
  // Aluminium, 26.98 g/mol: 3R/M = 924.5 J/kg/K (the measured c_p is 897).
  EXPECT_NEAR(dulongPetitSpecificHeat(26.98e-3), 924.5, 0.1);
  // Air: c_v = R/((gamma - 1) M) = 717.6 J/kg/K.
  EXPECT_NEAR(idealGasSpecificHeat(1.4, kAirMolarMass), 717.6, 0.1);
  ThermalModel t{900.0, 300.0, 1000.0};
  EXPECT_DOUBLE_EQ(t.temperature(9e4), 400.0);
  EXPECT_TRUE(t.molten(1000.0));
}

const char* kSolidScene = R"(
[scene]
name = "solid_test"
dimension = "2d"
[sph]
density = "continuity"
form = "interface"
[time]
t_end = "6 us"
[output]
snapshot_interval = "1.5 us"
[[materials]]
name = "basalt"
eos = "tillotson"
library = "basalt"
[materials.strength]
model = "von_mises"
shear_modulus = "22.7 GPa"
yield_stress = "3.5 GPa"
[materials.fracture]
model = "grady_kipp"
weibull_k = "5e34 m^-3"
weibull_m = 8.5
seed = 7
[[materials]]
name = "al"
eos = "mie_gruneisen"
library = "Al-2024"
[materials.strength]
model = "johnson_cook"
library = "Al-2024-T351"
[materials.fracture]
model = "principal_stress"
tensile_strength = "1 GPa"
erosion_strain = 1.0
[[bodies]]
name = "target"
material = "basalt"
shape = "sphere"
center = [0.0, 0.0]
radius = "10 mm"
spacing = "1 mm"
density = "2700 kg/m^3"
pressure = 0.0
[[bodies]]
name = "impactor"
material = "al"
shape = "sphere"
center = ["-13 mm", 0.0]
radius = "2 mm"
spacing = "1 mm"
density = "2785 kg/m^3"
pressure = 0.0
velocity = ["3 km/s", 0.0]
)";

TEST(SolidRun, ImpactFracturesTheTargetHeatsItAndConservesEnergy) {
  Scene scene = parseScene(kSolidScene, "solid_test.toml", {"output.snapshots=false"});
  MaterialTable materials = MaterialTable::fromScene(scene);
  ASSERT_TRUE(materials.anyStrength());
  Simulation sim(scene, buildParticles(scene, materials), materials, 2);
  const RunOutcome r = runSimulation(sim, RunOptions{});
  ASSERT_TRUE(r.ok) << r.error;
  const ParticleSet& p = sim.particles();
  ASSERT_EQ(p.stressComponents(), 4);
  ASSERT_TRUE(p.hasFracture());
  double damaged = 0.0, hot = 0.0, plastic = 0.0;
  for (std::size_t i = 0; i < p.numReal; ++i) {
    if (p.material[i] == 0 && p.damage(i) > 0.5) damaged += 1.0;
    if (p.temperature[i] > 400.0) hot += 1.0;
    if (p.plasticStrain[i] > 0.0) plastic += 1.0;
  }
  // A 3 km/s impact shatters part of the basalt, heats the impact site and yields the metal.
  EXPECT_GT(damaged, 10.0);
  EXPECT_GT(hot, 3.0);
  EXPECT_GT(plastic, 3.0);
  // Strength, plasticity and fracture change the stress, not the energy bookkeeping: the
  // conjugate energy equation keeps the total to the time-integration error.
  EXPECT_LT(std::abs(r.summary.energy.relativeError), 2e-3);
}

TEST(SolidRun, RestartWithStrengthAndFractureIsBitForBit) {
  const fs::path full = fs::temp_directory_path() / "ejecta_test_solid_full";
  const fs::path cut = fs::temp_directory_path() / "ejecta_test_solid_cut";
  fs::remove_all(full);
  fs::remove_all(cut);
  for (const fs::path& dir : {full, cut}) {
    RunOptions options;
    options.outDir = dir.string();
    options.sceneSource = kSolidScene;
    options.threads = 2;
    const RunOutcome r = runScene(parseScene(kSolidScene, "solid_test.toml"), options);
    ASSERT_TRUE(r.ok) << r.error;
  }
  ASSERT_TRUE(fs::remove(cut / "snapshots" / "snap_0003.h5"));
  ASSERT_TRUE(fs::remove(cut / "snapshots" / "snap_0004.h5"));
  RunOptions options;
  options.threads = 2;
  const RunOutcome resumed = restartRun(cut.string(), options);
  ASSERT_TRUE(resumed.ok) << resumed.error;
  SnapshotInfo ia, ib;
  const ParticleSet a = readSnapshot((full / "snapshots" / "snap_0004.h5").string(), ia);
  const ParticleSet b = readSnapshot((cut / "snapshots" / "snap_0004.h5").string(), ib);
  ASSERT_EQ(a.numReal, b.numReal);
  ASSERT_EQ(a.stressComponents(), 4);
  ASSERT_TRUE(b.hasFracture());
  for (std::size_t i = 0; i < a.numReal; ++i) {
    for (int d = 0; d < 2; ++d) ASSERT_EQ(a.x[d][i], b.x[d][i]) << "particle " << i;
    for (int c = 0; c < 4; ++c) ASSERT_EQ(a.stress[c][i], b.stress[c][i]) << "particle " << i;
    ASSERT_EQ(a.crack[i], b.crack[i]);
    ASSERT_EQ(a.plasticStrain[i], b.plasticStrain[i]);
    ASSERT_EQ(a.temperature[i], b.temperature[i]);
  }
}

TEST(SolidScene, BadStrengthAndFractureKeysAreNamed) {
  auto error = [](const std::string& extra) {
    const std::string text = std::string(R"(
[scene]
name = "bad"
dimension = "1d"
[time]
t_end = 1.0
[[materials]]
name = "al"
eos = "mie_gruneisen"
library = "Al-2024"
)") + extra + R"(
[[bodies]]
name = "b"
material = "al"
shape = "box"
min = [0.0]
max = [1.0]
spacing = 0.1
density = 2785.0
pressure = 0.0
)";
    try {
      const Scene s = parseScene(text, "bad.toml");
      MaterialTable::fromScene(s);
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error("[materials.strength]\nshear_modulus = \"27 GPa\"\n").find("strength.model"),
            std::string::npos);
  EXPECT_NE(error("[materials.strength]\nmodel = \"von_mises\"\nshear_modulus = \"27 GPa\"\n")
                .find("yield_stress is required"),
            std::string::npos);
  EXPECT_NE(error("[materials.strength]\nmodel = \"johnson_cook\"\nlibrary = \"unobtainium\"\n")
                .find("known: Al-2024-T351"),
            std::string::npos);
  EXPECT_NE(error("[materials.fracture]\nmodel = \"grady_kipp\"\nweibull_k = \"1e30 m^-3\"\n"
                  "weibull_m = 9\n")
                .find("needs a [materials.strength]"),
            std::string::npos);
  EXPECT_NE(error("[materials.strength]\nmodel = \"elastic\"\nshear_modulus = \"2 GPa/s\"\n")
                .find("materials[0].strength.shear_modulus"),
            std::string::npos);
}

}  // namespace
}  // namespace ejecta
