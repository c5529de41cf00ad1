// Whole-run behaviour: energy and momentum conservation, determinism, bit-for-bit restart, and
// a clear diagnosis of bad numerical states.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "sim/setup/bodies.hpp"
#include "sim/setup/embedded_scenes.hpp"
#include "sim/run/run.hpp"
#include "sim/io/snapshot.hpp"
#include "support/periodic_blast.hpp"

namespace fs = std::filesystem;

namespace ejecta {
namespace {

// A small periodic 2D blast (tests/support/periodic_blast.hpp).
const std::string kBlastScene = test::periodicBlastScene();

Simulation makeSimulation(const std::vector<std::string>& overrides = {}, int threads = 2) {
  Scene scene = parseScene(kBlastScene, "test_blast.toml", overrides);
  MaterialTable materials = MaterialTable::fromScene(scene);
  ParticleSet p = buildParticles(scene, materials);
  return Simulation(scene, std::move(p), std::move(materials), threads);
}

fs::path freshDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("ejecta_test_" + name);
  fs::remove_all(dir);
  return dir;
}

TEST(Simulation, ConservesEnergyAndMomentumInAPeriodicBlast) {
  Simulation sim = makeSimulation();
  RunOptions options;
  const RunOutcome r = runSimulation(sim, options);
  ASSERT_TRUE(r.ok) << r.error;
  // Leapfrog with a Courant number of 0.3: the energy error of a strong blast at this resolution
  // is ~1e-4 (time-step truncation, not a drift); 1e-3 is an order-of-magnitude margin.
  EXPECT_LT(std::abs(r.summary.energy.relativeError), 1e-3);
  // Pairwise antisymmetric forces and periodic images: momentum is conserved to round-off,
  // measured against the sum of |m v| (the scale of momentum in the run).
  double scale = 0.0;
  const ParticleSet& p = sim.particles();
  for (std::size_t i = 0; i < p.numReal; ++i) scale += p.mass[i] * std::hypot(p.v[0][i], p.v[1][i]);
  for (int d = 0; d < 2; ++d)
    EXPECT_LT(std::abs(r.summary.momentum.final[d] - r.summary.momentum.initial[d]), 1e-12 * scale);
  EXPECT_GT(r.summary.steps, 10);
}

TEST(Simulation, IsDeterministicAndIndependentOfThreadCount) {
  auto finalState = [](int threads) {
    Simulation sim = makeSimulation({"time.t_end=0.008"}, threads);
    RunOptions options;
    EXPECT_TRUE(runSimulation(sim, options).ok);
    return sim.particles();
  };
  const ParticleSet a = finalState(2), b = finalState(2), c = finalState(1);
  ASSERT_EQ(a.numReal, b.numReal);
  for (std::size_t i = 0; i < a.numReal; ++i) {
    ASSERT_EQ(a.x[0][i], b.x[0][i]);
    ASSERT_EQ(a.u[i], b.u[i]);
    ASSERT_EQ(a.x[0][i], c.x[0][i]);
    ASSERT_EQ(a.v[1][i], c.v[1][i]);
    ASSERT_EQ(a.rho[i], c.rho[i]);
  }
}

TEST(Simulation, RestartMatchesAnUninterruptedRunBitForBit) {
  const fs::path full = freshDir("restart_full"), cut = freshDir("restart_cut");
  // Interrupt the second run at its snapshot 2 (t = 0.01 of 0.02): remove the later ones, resume.
  test::runAndResumeFromSnapshot2(kBlastScene, full, cut);
  ASSERT_FALSE(::testing::Test::HasFatalFailure());
  test::expectLastSnapshotsMatch(full, cut);
  EXPECT_TRUE(fs::exists(cut / "summary.json"));
  EXPECT_TRUE(fs::exists(cut / "snapshots.xdmf"));
  // The energy ledger has a header and one line per step (step 0 included), also after the
  // restart (the steps past the resumed snapshot are not listed twice).
  auto countLines = [](const fs::path& path) {
    std::ifstream log(path);
    long lines = 0;
    for (std::string line; std::getline(log, line);) ++lines;
    return lines;
  };
  SnapshotInfo last;
  readSnapshot((full / "snapshots" / "snap_0004.h5").string(), last);
  EXPECT_EQ(countLines(full / "energy.csv"), last.step + 2);
  EXPECT_EQ(countLines(cut / "energy.csv"), last.step + 2);
}

TEST(Simulation, NonFiniteStateStopsWithADiagnosis) {
  Simulation sim = makeSimulation();
  sim.initialise();
  sim.particles().u[17] = std::nan("");
  const auto id = sim.particles().id[17];
  try {
    sim.step(1.0);
    FAIL() << "a NaN energy went undetected";
  } catch (const SimulationError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("step"), std::string::npos) << msg;
    EXPECT_NE(msg.find("particle id"), std::string::npos) << msg;
    EXPECT_TRUE(msg.find("id " + std::to_string(id)) != std::string::npos ||
                msg.find("non-finite") != std::string::npos) << msg;
  }
}

TEST(Simulation, TimeStepUnderflowStopsTheRunAndLeavesALastSnapshot) {
  const fs::path dir = freshDir("dt_underflow");
  RunOptions options;
  options.outDir = dir.string();
  options.sceneSource = kBlastScene;
  const RunOutcome r =
      runScene(parseScene(kBlastScene, "test_blast.toml", {"time.dt_min=1.0"}), options);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.error.find("time step"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("dt_min"), std::string::npos) << r.error;
  EXPECT_TRUE(fs::exists(dir / "snapshots" / "snap_0000.h5"));
  EXPECT_TRUE(fs::exists(dir / "summary.json"));
}

// The diagnosis names the particle with the tightest own limit and the criterion that set it:
// in the blast, the Courant step of a particle with the deposit's energy (u far above the
// ambient gas's), with global and with individual steps.
TEST(Simulation, TimeStepUnderflowNamesTheLimitingCriterionAndParticle) {
  for (const char* stepping : {"global", "individual"}) {
    const Scene scene = parseScene(kBlastScene, "test_blast.toml",
                                   {"time.dt_min=1.0", std::string("time.stepping=") + stepping});
    Simulation sim(scene, buildParticles(scene, MaterialTable::fromScene(scene)),
                   MaterialTable::fromScene(scene), 1);
    const RunOutcome r = runSimulation(sim, RunOptions{});
    ASSERT_FALSE(r.ok) << stepping;
    std::printf("  %s: %s\n", stepping, r.error.c_str());
    EXPECT_NE(r.error.find("tightest limit: the Courant step"), std::string::npos)
        << stepping << ": " << r.error;
    const ParticleSet& p = sim.particles();
    double uLowest = p.u[0], uHighest = p.u[0];
    for (std::size_t i = 0; i < p.numReal; ++i) {
      uLowest = std::min(uLowest, p.u[i]);
      uHighest = std::max(uHighest, p.u[i]);
    }
    // describeParticle prints u: it must be a hot one (the deposit raises u by orders).
    const auto at = r.error.find(" u=");
    ASSERT_NE(at, std::string::npos) << r.error;
    const double u = std::stod(r.error.substr(at + 3));
    EXPECT_GT(u, 0.5 * uHighest) << stepping << ": " << r.error << " (lowest u " << uLowest << ")";
  }
}

}  // namespace
}  // namespace ejecta

namespace ejecta {
namespace {

// Two gases of different gamma in pressure equilibrium: each particle's pressure comes from its
// own material's EOS, and the contact stays (nearly) at rest.
TEST(Simulation, MultiMaterialContactInPressureEquilibrium) {
  const char* scene = R"(
[scene]
name = "two_gases"
dimension = "1d"
[domain]
x = { min = -0.5, max = 0.5, boundary = "wall" }
[time]
t_end = 0.1
[[materials]]
name = "air"
gamma = 1.4
[[materials]]
name = "helium"
gamma = 1.6666666666666667
[[bodies]]
name = "left"
material = "air"
shape = "box"
min = [-0.5]
max = [0.0]
spacing = 0.0025
density = 1.0
pressure = 1.0
[[bodies]]
name = "right"
material = "helium"
shape = "box"
min = [0.0]
max = [0.5]
spacing = 0.01
density = 0.25
pressure = 1.0
)";
  Scene s = parseScene(scene, "two_gases.toml");
  MaterialTable materials = MaterialTable::fromScene(s);
  Simulation sim(s, buildParticles(s, materials), materials, 2);
  RunOptions options;
  const RunOutcome r = runSimulation(sim, options);
  ASSERT_TRUE(r.ok) << r.error;
  const ParticleSet& p = sim.particles();
  const double gammas[2] = {1.4, 5.0 / 3.0};
  double vMax = 0.0;
  for (std::size_t i = 0; i < p.numReal; ++i) {
    // Pressure of the final state from the particle's own EOS, to round-off.
    EXPECT_NEAR(p.P[i], (gammas[p.material[i]] - 1.0) * p.rho[i] * p.u[i], 1e-12 * p.P[i]);
    vMax = std::max(vMax, std::abs(p.v[0][i]));
  }
  // Summation density smooths the 4:1 density jump over ~2h, which gives the well-known
  // "pressure blip" at a contact (Price 2008, J. Comput. Phys. 227, 10040): small transient
  // velocities, a few percent of the sound speed (1.18 m/s in the air); 0.1 m/s bounds them.
  EXPECT_LT(vMax, 0.1);
  EXPECT_LT(std::abs(r.summary.energy.relativeError), 1e-4);
}

}  // namespace
}  // namespace ejecta

namespace ejecta {
namespace {

// A periodic seam between regions of different h (Sod's 1:8 spacing): the ghost layer must
// cover the supports of the particles on the far side of the box, or pairs go missing and
// momentum leaks.
TEST(Simulation, PeriodicSeamBetweenDifferentSpacingsConservesMomentum) {
  Scene scene = parseScene(std::string(findEmbeddedScene("verification/sod_1d")), "sod_1d.toml",
                           {"domain.x={min=-0.5,max=0.5,boundary=\"periodic\"}", "time.t_end=0.02"});
  MaterialTable materials = MaterialTable::fromScene(scene);
  Simulation sim(scene, buildParticles(scene, materials), materials, 2);
  RunOptions options;
  const RunOutcome r = runSimulation(sim, options);
  ASSERT_TRUE(r.ok) << r.error;
  double scale = 0.0;
  const ParticleSet& p = sim.particles();
  for (std::size_t i = 0; i < p.numReal; ++i) scale += p.mass[i] * std::abs(p.v[0][i]);
  // Antisymmetric pair forces over complete pair lists: round-off only.
  EXPECT_LT(std::abs(r.summary.momentum.final[0]), 1e-12 * scale);
}

}  // namespace
}  // namespace ejecta
