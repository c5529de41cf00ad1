// Energy sources (sim/programmed_burn, DED body deposits, sim/energy_ledger's yield share, issue
// 4): lighting times from points and lines, the burn fraction's ramp, deposits that land exactly
// their energy in the device's particles, the yield and the share of it in the target, the depth
// of burst, and clear errors for scenes that ask for what cannot be.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <unistd.h>
#include <variant>

#include "sim/setup/bodies.hpp"
#include "sim/run/energy_ledger.hpp"
#include "sim/eos/jwl.hpp"
#include "sim/solid/materials.hpp"
#include "sim/sources/programmed_burn.hpp"
#include "sim/run/run.hpp"
#include "sim/io/snapshot.hpp"

namespace fs = std::filesystem;

namespace ejecta {
namespace {

// A granite disc (RZ: a sphere) of radius 1 m with a TNT charge of radius 0.2 m at depth `depth`
// below its top, lit at the charge's centre, or a DED into a granite "device" body instead.
std::string burstScene(const std::string& source, double depth, const std::string& tEnd = "20 us") {
  const double zc = 1.0 - depth;
  std::string s = R"(
[scene]
name = "burst"
dimension = "rz"
[domain]
x = { min = 0.0, max = 2.0 }
y = { min = -2.0, max = 2.0 }
[time]
t_end = ")" + tEnd + R"("
[output]
snapshot_interval = ")" + tEnd + R"("
[[materials]]
name = "granite"
eos = "tillotson"
library = "granite"
[[materials]]
name = "device"
)";
  s += source == "jwl" ? "eos = \"jwl\"\nlibrary = \"TNT\"\n" : "eos = \"tillotson\"\nlibrary = \"granite\"\n";
  s += R"(
[[bodies]]
name = "charge"
material = "device"
shape = "sphere"
center = [0.0, )" + std::to_string(zc) + R"(]
radius = 0.2
spacing = 0.05
)";
  s += source == "jwl" ? "density = 1630.0\n" : "density = 2680.0\npressure = 0.0\n";
  s += R"(
[[bodies]]
name = "rock"
material = "granite"
shape = "sphere"
center = [0.0, 0.0]
radius = 1.0
spacing = 0.05
density = 2680.0
pressure = 0.0
)";
  if (source == "jwl")
    s += "[[detonations]]\nname = \"det\"\nmaterial = \"device\"\npoint = [0.0, " +
         std::to_string(zc) + "]\n";
  else
    s += "[[energy_deposits]]\nname = \"yield\"\nbody = \"charge\"\nenergy = \"0.1 t\"\n";
  return s;
}

TEST(ProgrammedBurn, LightingTimesFollowTheFrontFromAPoint) {
  const Scene scene = parseScene(burstScene("jwl", 0.5), "burst.toml");
  ASSERT_EQ(scene.detonations.size(), 1u);
  const MaterialTable materials = MaterialTable::fromScene(scene);
  const ParticleSet p = buildParticles(scene, materials);
  ASSERT_TRUE(p.hasBurn());
  const double D = jwlExplosive("TNT").dCJ;
  std::size_t explosive = 0;
  for (std::size_t i = 0; i < p.numReal; ++i) {
    if (p.material[i] != 1) {
      // Not an explosive: always burnt, pressure untouched.
      EXPECT_EQ(p.burnFraction[i], 1.0);
      EXPECT_TRUE(std::isinf(p.lightingTime[i]) && p.lightingTime[i] < 0);
      continue;
    }
    ++explosive;
    const double r = std::hypot(p.x[0][i], p.x[1][i] - 0.5);
    EXPECT_NEAR(p.lightingTime[i], r / D, 1e-15);
    EXPECT_EQ(p.burnFraction[i], 0.0);
    // Started at the detonation energy e0 = E0 / rho0 (no pressure or energy given).
    EXPECT_DOUBLE_EQ(p.u[i], jwlExplosive("TNT").specificDetonationEnergy());
  }
  EXPECT_GT(explosive, 10u);
}

TEST(ProgrammedBurn, BurnFractionRampsOverOneAndAHalfSpacingsAndNeverFalls) {
  ParticleSet p;
  p.append({0, 0, 0}, {0, 0, 0}, 1.0, 1630.0, 4e6, 0.002, 0);
  p.enableBurn();
  p.lightingTime[0] = 1e-6;
  p.burnFraction[0] = 0.0;
  p.P.assign(1, 1e10);
  const double D = 7000.0, eta = 2.0;  // spacing h/eta = 1 mm; the ramp takes 1.5 mm / D
  const BurnTable velocity{{D}, {0.0}, {0.0}};  // no compression burn
  applyProgrammedBurn(p, velocity, eta, 0.5e-6);  // before lighting
  EXPECT_EQ(p.P[0], 0.0);
  p.P[0] = 1e10;
  const double ramp = 1.5e-3 / D;
  applyProgrammedBurn(p, velocity, eta, 1e-6 + 0.5 * ramp);
  EXPECT_NEAR(p.burnFraction[0], 0.5, 1e-12);
  EXPECT_NEAR(p.P[0], 0.5e10, 1e-2);
  p.P[0] = 1e10;
  applyProgrammedBurn(p, velocity, eta, 1e-6 + 2 * ramp);
  EXPECT_EQ(p.burnFraction[0], 1.0);
  // A later call at an earlier time (the predictor of a rejected state) never un-burns.
  p.P[0] = 1e10;
  applyProgrammedBurn(p, velocity, eta, 1e-6);
  EXPECT_EQ(p.burnFraction[0], 1.0);
  EXPECT_EQ(p.P[0], 1e10);
}

// LS-DYNA's beta burn: explosive compressed just before the front reaches it burns by its
// compression, F2 = (1 - V) / (1 - V_CJ), and is fully burnt at the C-J density; further ahead of
// the front than one ramp width it does not (SPH's smoothing would light a burn running ahead).
TEST(ProgrammedBurn, CompressionAheadOfTheFrontBurnsByBeta) {
  ParticleSet p;
  const double rho0 = 1630.0, D = 6930.0, eta = 2.0;  // h = 2 mm: ramp width 1.5 mm
  p.append({0, 0, 0}, {0, 0, 0}, 1.0, rho0, 4e6, 0.002, 0);
  p.enableBurn();
  p.burnFraction[0] = 0.0;
  const BurnTable burn{{D}, {rho0}, {0.75}};
  p.rho[0] = rho0 / 0.9;  // V = 0.9: F2 = 0.1 / 0.25
  p.P.assign(1, 1e10);
  p.lightingTime[0] = 2e-3 / D;  // the front 2 mm away: beyond the window
  applyProgrammedBurn(p, burn, eta, 0.0);
  EXPECT_EQ(p.burnFraction[0], 0.0);
  EXPECT_EQ(p.P[0], 0.0);
  p.P[0] = 1e10;
  p.lightingTime[0] = 1e-3 / D;  // 1 mm away: inside it
  applyProgrammedBurn(p, burn, eta, 0.0);
  EXPECT_NEAR(p.burnFraction[0], 0.4, 1e-12);
  EXPECT_NEAR(p.P[0], 0.4e10, 1e-2);
  p.rho[0] = rho0;  // expanding back does not un-burn
  applyProgrammedBurn(p, burn, eta, 0.0);
  EXPECT_NEAR(p.burnFraction[0], 0.4, 1e-12);
  p.rho[0] = rho0 / 0.7;  // beyond the C-J density: fully burnt
  applyProgrammedBurn(p, burn, eta, 0.0);
  EXPECT_EQ(p.burnFraction[0], 1.0);
}

// TNT's C-J relative volume from its JWL set: V_CJ = 1 - p_CJ / (rho0 D^2), about 0.73-0.74 for
// every published TNT set (Dobratz & Crawford 1985: rho_CJ / rho0 = 1.36-1.38).
TEST(ProgrammedBurn, TableTakesTheCjStateOfTheExplosive) {
  const Scene scene = parseScene(burstScene("jwl", 0.5), "burst.toml");
  const MaterialTable materials = MaterialTable::fromScene(scene);
  const BurnTable t = burnTable(scene.detonations, materials);
  bool found = false;
  for (std::size_t m = 0; m < materials.size(); ++m) {
    if (t.velocity[m] <= 0.0) {
      EXPECT_EQ(t.rho0[m], 0.0);
      continue;
    }
    found = true;
    EXPECT_GT(t.cjRelativeVolume[m], 0.71);
    EXPECT_LT(t.cjRelativeVolume[m], 0.76);
    EXPECT_GT(t.rho0[m], 1500.0);
  }
  EXPECT_TRUE(found);
}

TEST(ProgrammedBurn, LineInitiationLightsByDistanceToTheSegment) {
  std::string s = burstScene("jwl", 0.5);
  s = s.replace(s.find("point = [0.0, 0.500000]"), std::string("point = [0.0, 0.500000]").size(),
                "point = [0.0, 0.4]\nline_to = [0.0, 0.6]\ntime = \"2 us\"");
  const Scene scene = parseScene(s, "line.toml");
  ASSERT_TRUE(scene.detonations[0].alongLine);
  const MaterialTable materials = MaterialTable::fromScene(scene);
  const ParticleSet p = buildParticles(scene, materials);
  const double D = jwlExplosive("TNT").dCJ;
  for (std::size_t i = 0; i < p.numReal; ++i) {
    if (p.material[i] != 1) continue;
    const double z = std::clamp(p.x[1][i], 0.4, 0.6);
    const double r = std::hypot(p.x[0][i], p.x[1][i] - z);
    EXPECT_NEAR(p.lightingTime[i], 2e-6 + r / D, 1e-15);
  }
}

TEST(ProgrammedBurn, SceneErrorsNameTheKey) {
  // A detonation of a material that is not a JWL explosive.
  std::string s = burstScene("ded", 0.5);
  s += "[[detonations]]\nname = \"d\"\nmaterial = \"granite\"\npoint = [0.0, 0.5]\n";
  try {
    parseScene(s, "bad.toml");
    FAIL() << "expected a SceneError";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("detonations[0].material"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("not a JWL explosive"), std::string::npos) << e.what();
  }
  // An explosive body with no state and no detonation to light it.
  std::string unlit = burstScene("jwl", 0.5);
  unlit = unlit.substr(0, unlit.find("[[detonations]]"));
  try {
    parseScene(unlit, "unlit.toml");
    FAIL() << "expected a SceneError";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("bodies[0].pressure"), std::string::npos) << e.what();
  }
  // In RZ the initiation point must be on the axis.
  std::string offAxis = burstScene("jwl", 0.5);
  offAxis.replace(offAxis.rfind("point = [0.0,"), 13, "point = [0.1,");
  EXPECT_THROW(parseScene(offAxis, "off.toml"), SceneError);
}

TEST(DirectEnergyDeposition, BodyDepositLandsTheYieldUniformlyInTheDevice) {
  const Scene scene = parseScene(burstScene("ded", 0.5), "ded.toml");
  ASSERT_EQ(scene.deposits.size(), 1u);
  EXPECT_EQ(scene.deposits[0].body, 0);
  // "0.1 t" as an energy is a tenth of a ton of TNT: 4.184e8 J (core/units.cpp).
  EXPECT_DOUBLE_EQ(scene.deposits[0].energy, 4.184e8);
  const MaterialTable materials = MaterialTable::fromScene(scene);
  const ParticleSet p = buildParticles(scene, materials);
  double deposited = 0.0, du = -1.0;
  for (std::size_t i = 0; i < p.numReal; ++i) {
    if (p.material[i] != 1) {
      EXPECT_NEAR(p.u[i], 0.0, 1e-9) << "the deposit leaked into the target";
      continue;
    }
    deposited += p.mass[i] * p.u[i];
    if (du < 0) du = p.u[i];
    EXPECT_NEAR(p.u[i], du, 1e-9 * du) << "the seed's DED: the same specific energy everywhere";
  }
  EXPECT_NEAR(deposited, scene.deposits[0].energy, 1e-12 * scene.deposits[0].energy);
}

TEST(SourceLedger, YieldGroupsAndDepthOfBurst) {
  const Scene ded = parseScene(burstScene("ded", 0.5), "ded.toml");
  const LedgerGroups g = ledgerGroups(ded);
  EXPECT_EQ(g.explosive, std::vector<int>{1});
  EXPECT_EQ(g.target, std::vector<int>{0});
  EXPECT_TRUE(g.impactor.empty());
  EXPECT_DOUBLE_EQ(sourceYield(ded, {0.0, 0.0}), 4.184e8);
  // The device's centre 0.5 m below the top of a 1 m sphere: 0.5 m deep.
  ASSERT_TRUE(depthOfBurst(ded).has_value());
  EXPECT_NEAR(*depthOfBurst(ded), 0.5, 1e-12);
  // A contact burst 0.1 m above the surface: negative depth (a height of burst).
  const Scene above = parseScene(burstScene("jwl", -0.1), "above.toml");
  EXPECT_NEAR(*depthOfBurst(above), -0.1, 1e-12);
  // The JWL yield is the explosive's initial internal energy (its chemical energy).
  EXPECT_DOUBLE_EQ(sourceYield(above, {0.0, 0.0}), 0.0);
  EXPECT_DOUBLE_EQ(sourceYield(above, {5.0, 7.0}), 7.0);
}

std::string tempDir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() /
                     ("ejecta_sources_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  return d.string();
}

double extra(const RunSummary& s, const std::string& key) {
  for (const auto& [k, v] : s.extras)
    if (k == key) return std::get<double>(v);
  ADD_FAILURE() << "no summary extra '" << key << "'";
  return std::numeric_limits<double>::quiet_NaN();
}

// A short subsurface burst run by each source: the summary's share of the yield is the target's
// energy gain over the yield, the energy.csv column follows it in time, and energy is conserved.
TEST(SourceLedger, SubsurfaceBurstReportsTheShareOfTheYieldInTheTarget) {
  for (const std::string source : {"ded", "jwl"}) {
    SCOPED_TRACE(source);
    const Scene scene = parseScene(burstScene(source, 0.5, "60 us"), source + ".toml");
    RunOptions options;
    options.outDir = tempDir(source);
    const RunOutcome out = runScene(scene, options);
    ASSERT_TRUE(out.ok) << out.error;
    const double yield = extra(out.summary, "yield_J");
    const double share = extra(out.summary, "target_share_of_yield");
    const double kept = extra(out.summary, "explosive_share_of_yield");
    EXPECT_NEAR(extra(out.summary, "yield_kt"), yield / 4.184e12, 1e-15);
    if (source == "ded") {
      EXPECT_DOUBLE_EQ(yield, 4.184e8);
    }
    // By 60 us the shock has crossed most of the 1 m sphere: a real share has coupled, and the
    // explosive keeps the rest, exactly up to the run's own energy error (the target starts with
    // none, so the run's initial energy is the yield).
    EXPECT_GT(share, 0.05);
    EXPECT_LT(share, 1.0);
    const auto& e = out.summary.energy;
    EXPECT_NEAR(share + kept, (e.initial + e.relativeError * std::abs(e.initial)) / yield, 1e-9);
    EXPECT_LT(std::abs(e.relativeError), 0.01);  // 4 particles across the charge's radius
    EXPECT_NEAR(extra(out.summary, "target_kinetic_fraction") +
                    extra(out.summary, "target_internal_fraction"), 1.0, 1e-12);
    EXPECT_NEAR(extra(out.summary, "depth_of_burst_m"), 0.5, 1e-12);
    EXPECT_NEAR(extra(out.summary, "scaled_depth_of_burst_m_per_kt3"),
                0.5 / std::cbrt(yield / 4.184e12), 1e-9);
    // energy.csv: the target_share column ends at the summary's value.
    std::ifstream csv(fs::path(options.outDir) / "energy.csv");
    std::string header, line, last;
    std::getline(csv, header);
    EXPECT_EQ(header.substr(header.rfind(',') + 1), "target_share");
    while (std::getline(csv, line)) last = line;
    EXPECT_NEAR(std::stod(last.substr(last.rfind(',') + 1)), share, 1e-9);
    fs::remove_all(options.outDir);
  }
}

TEST(ProgrammedBurn, SnapshotRestoresLightingTimesAndBurnFractions) {
  const Scene scene = parseScene(burstScene("jwl", 0.5), "burst.toml");
  const MaterialTable materials = MaterialTable::fromScene(scene);
  ParticleSet p = buildParticles(scene, materials);
  p.P.assign(p.size(), 1e9);
  applyProgrammedBurn(p, burnTable(scene.detonations, materials), scene.sph.eta, 2e-5);
  SnapshotInfo info;
  info.geometry = scene.geometry;
  info.sceneSource = burstScene("jwl", 0.5);
  const std::string path = tempDir("snap") + ".h5";
  writeSnapshot(path, p, info);
  SnapshotInfo back;
  const ParticleSet q = readSnapshot(path, back);
  ASSERT_TRUE(q.hasBurn());
  for (std::size_t i = 0; i < p.numReal; ++i) {
    EXPECT_EQ(q.lightingTime[i], p.lightingTime[i]);
    EXPECT_EQ(q.burnFraction[i], p.burnFraction[i]);
  }
  fs::remove(path);
}

}  // namespace
}  // namespace ejecta
