// Particles thrown clear of their body (issue 23, "what stops finer runs"). A particle whose h
// follows a density that no longer describes its surroundings (summation density once it is
// alone; continuity density rarefied below its neighbours') widens its kernel until it spans the
// body it left, and the neighbour check stops the run (two of five 0.25 m follower runs stopped
// so, docs/asteroid_studies.md). sph.h_max_factor holds each particle's h at a cap, and a
// particle whose kernel reaches nothing sets no time step.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "sim/run/run.hpp"
#include "sim/run/simulation.hpp"
#include "sim/run/timestep_criteria.hpp"
#include "sim/setup/bodies.hpp"
#include "sim/setup/scene.hpp"
#include "sim/solid/materials.hpp"
#include "sim/verify/verification.hpp"

namespace ejecta {
namespace {

struct Ran {
  ParticleSet final;
  RunOutcome outcome;
  double dtNext = 0.0;
};

Ran run(const std::string& toml) {
  const Scene scene = parseScene(toml, "rarefied.toml");
  MaterialTable materials = MaterialTable::fromScene(scene);
  ParticleSet initial = buildParticles(scene, materials);
  Simulation sim(scene, initial, std::move(materials), 2);
  Ran r;
  r.outcome = runSimulation(sim, RunOptions{});
  r.final = sim.particles();
  r.dtNext = sim.dtNext();
  std::printf("  %zu particles, %ld steps, dE/E = %.3g%s%s\n", r.final.numReal,
              r.outcome.summary.steps, r.outcome.summary.energy.relativeError,
              r.outcome.ok ? "" : ", stopped: ", r.outcome.error.c_str());
  return r;
}

// A block of granite rubble (no tension) 40 x 40 spacings (1 cm) at rest and zero pressure (it
// stays so: continuity density has no free-surface deficit), 2D planar, and `extra` bodies.
std::string blockScene(const std::string& sph, const std::string& extra,
                       const std::string& block = "min = [0.0, 0.0]\nmax = [\"0.4 m\", \"0.4 m\"]\n",
                       const std::string& dimension = "2d", const std::string& time = "") {
  return R"(
[scene]
name = "rarefied"
dimension = ")" + dimension + R"("
[sph]
form = "interface"
)" + sph + R"(
[time]
)" + (time.find("t_end") == std::string::npos ? "t_end = \"150 us\"\n" : "") + time + R"(
[[materials]]
name = "granite"
eos = "tillotson"
library = "granite"
parameters = { minimum_pressure = 0.0 }  # rubble: no tension holds the bodies together
[[bodies]]
name = "block"
material = "granite"
shape = "box"
)" + block + R"(spacing = "1 cm"
density = "2680 kg/m^3"
pressure = 0.0
)" + extra;
}

// One particle one spacing off the block's face, leaving it at 3 km/s (45 cm, 45 spacings, by
// the end), under summation density: once its kernel has left the block nothing balances its
// own term in the kernel sum, so its h (tied to the sum) doubles every pass until the kernel
// reaches back into the block, and from then on h grows with its distance from it.
const char* kLeaving = R"(
[[bodies]]
name = "fragment"
material = "granite"
shape = "box"
min = ["0.40 m", "0.19 m"]
max = ["0.41 m", "0.20 m"]
spacing = "1 cm"
density = "2680 kg/m^3"
pressure = 0.0
velocity = ["3 km/s", 0.0]
)";

std::size_t fragmentIndex(const ParticleSet& p) {
  std::size_t k = p.numReal;
  for (std::size_t i = 0; i < p.numReal; ++i)
    if (p.x[0][i] > 0.6) k = i;  // the one particle well beyond the block's face
  return k;
}

// The fragment's id: it follows the block's 40 x 40 particles.
constexpr std::int64_t kFragmentId = 1600;

std::size_t particleWithId(const ParticleSet& p, std::int64_t id) {
  for (std::size_t i = 0; i < p.numReal; ++i)
    if (p.id[i] == id) return i;
  return p.numReal;
}

TEST(StabilityRarefied, AtTheCapALeavingParticleKeepsItsKernel) {
  const std::string summation = "density = \"summation\"\n";
  const Ran free = run(blockScene(summation, kLeaving));
  const Ran capped = run(blockScene(summation + "h_max_factor = 4\n", kLeaving));
  ASSERT_TRUE(free.outcome.ok) << free.outcome.error;
  ASSERT_TRUE(capped.outcome.ok) << capped.outcome.error;
  const std::size_t kf = fragmentIndex(free.final), kc = fragmentIndex(capped.final);
  ASSERT_LT(kf, free.final.numReal);
  ASSERT_LT(kc, capped.final.numReal);
  std::printf("  fragment h: %.4g m free, %.4g m capped\n", free.final.h[kf], capped.final.h[kc]);
  // Without the cap its kernel spans the block it left (h of tens of spacings).
  EXPECT_GT(free.final.h[kf], 10 * 1.2 * 0.01);
  // With it, held at 4 x its first h (eta 1.2 x 1 cm), to rounding, and alone: it flies on at
  // its speed (3 km/s x 150 us = 45 cm from 0.405 m, less what it lost parting).
  const double cap = 4.0 * 1.2 * 0.01;
  EXPECT_NEAR(capped.final.h[kc], cap, 1e-12 * cap);
  EXPECT_GT(capped.final.x[0][kc], 0.80);
  // Held at the cap its density is its kernel sum, its own term alone: m W(0) = rho0 dx^2
  // sigma / cap^2, sigma = 10 / (7 pi) for the 2D cubic spline (Monaghan 1992).
  const double own = 2680.0 * 0.01 * 0.01 * 10.0 / (7.0 * std::numbers::pi) / (cap * cap);
  EXPECT_NEAR(capped.final.rho[kc], own, 1e-9 * own);
}

// The same leaving particle in RZ (a ring leaving the block's outer face, r from 0.40 m, in a
// block r < 0.4 m on the axis) and with individual time steps: the cap holds in every geometry
// and stepping, and the ring flies on.
TEST(StabilityRarefied, AtTheCapALeavingRingKeepsItsKernelInRZAndWithIndividualSteps) {
  const std::string summation = "density = \"summation\"\nh_max_factor = 4\n";
  const std::string onTheAxis = "min = [0.0, 0.0]\nmax = [\"0.4 m\", \"0.4 m\"]\n";
  const double cap = 4.0 * 1.2 * 0.01;
  for (const std::string time : {"", "stepping = \"individual\"\n"}) {
    const Ran rz = run(blockScene(summation, kLeaving, onTheAxis, "rz", time));
    ASSERT_TRUE(rz.outcome.ok) << rz.outcome.error;
    const std::size_t k = fragmentIndex(rz.final);
    ASSERT_LT(k, rz.final.numReal);
    std::printf("  RZ%s: ring h %.4g m at r = %.3g m\n", time.empty() ? "" : ", individual steps",
                rz.final.h[k], rz.final.x[0][k]);
    EXPECT_NEAR(rz.final.h[k], cap, 1e-12 * cap);
    EXPECT_GT(rz.final.x[0][k], 0.80);
  }
}

// Under continuity density a particle leaving the block rarefies while it parts (its neighbours
// recede: to 2080 kg/m^3 uncapped, measured) and so reaches its cap, here its first h, where its
// density is floored at the density of that h, the block's own; flying into a second block it is
// compressed again and must leave the cap: its density is its own, floored only while its h
// would pass the cap (a review found it stuck at the floor and the cap, fixed in 636e61f). Also
// with individual time steps.
const char* kIntoASecondBlock = R"(
[[bodies]]
name = "second_block"
material = "granite"
shape = "box"
min = ["0.60 m", "0.10 m"]
max = ["0.80 m", "0.30 m"]
spacing = "1 cm"
density = "2680 kg/m^3"
pressure = 0.0
)";

TEST(StabilityRarefied, ACappedParticleCompressedAgainLeavesItsCap) {
  const std::string continuity = "density = \"continuity\"\nh_max_factor = 1\n";
  const double cap = 1.0 * 1.2 * 0.01;
  // The fragment leaves at 3 km/s from x = 0.405 m: in flight at 50 us (x = 0.555 m), pressed
  // into the second block's face (at 0.60 m) at 68 us, its most compressed (measured: 3408
  // kg/m^3, h 0.887 of the cap; 2692 at 60 us, 2928 at 72 us, back at the cap by 80 us as it
  // rebounds).
  for (const std::string stepping : {"", "stepping = \"individual\"\n"}) {
    const std::string extra = std::string(kLeaving) + kIntoASecondBlock;
    const Ran flying = run(blockScene(continuity, extra, "min = [0.0, 0.0]\nmax = [\"0.4 m\", \"0.4 m\"]\n",
                                      "2d", stepping + "t_end = \"50 us\"\n"));
    const Ran arrived = run(blockScene(continuity, extra, "min = [0.0, 0.0]\nmax = [\"0.4 m\", \"0.4 m\"]\n",
                                       "2d", stepping + "t_end = \"68 us\"\n"));
    ASSERT_TRUE(flying.outcome.ok) << flying.outcome.error;
    ASSERT_TRUE(arrived.outcome.ok) << arrived.outcome.error;
    const std::size_t kf = particleWithId(flying.final, kFragmentId);
    const std::size_t ka = particleWithId(arrived.final, kFragmentId);
    ASSERT_LT(kf, flying.final.numReal);
    ASSERT_LT(ka, arrived.final.numReal);
    std::printf("  %s: in flight x %.3g m, h/cap %.4f, rho %.4g; arrived x %.3g m, h/cap %.4f, rho %.4g\n",
                stepping.empty() ? "global" : "individual", flying.final.x[0][kf],
                flying.final.h[kf] / cap, flying.final.rho[kf], arrived.final.x[0][ka],
                arrived.final.h[ka] / cap, arrived.final.rho[ka]);
    // In flight: at the cap (to the 1e-3 the continuity cap is rounded to) and the floor.
    EXPECT_NEAR(flying.final.h[kf], cap, 1e-3 * cap);
    EXPECT_NEAR(flying.final.rho[kf], 2680.0, 1e-3 * 2680.0);
    // Compressed: below the cap, denser than the floor (stuck at exactly both before 636e61f).
    // Loose bounds (measured 0.887 and 1.27 at 68 us in both steppings) so that a few us either
    // way in the moment of greatest compression (0.957 and 1.09 at 72 us) still passes.
    EXPECT_LT(arrived.final.h[ka], 0.99 * cap);
    EXPECT_GT(arrived.final.rho[ka], 1.02 * 2680.0);
  }
}

// A particle of vapour at 4e9 J/kg (a 100 kt device's particles reach 3.7e10 J/kg) far from the
// block: its kernel, even at the cap, never reaches the block. Its own sound crossing would set a
// step a tenth of the block's; it exchanges nothing, so the run takes the block's steps.
const char* kHotAlone = R"(
[[bodies]]
name = "vapour"
material = "granite"
shape = "box"
min = ["0.70 m", "0.19 m"]
max = ["0.71 m", "0.20 m"]
spacing = "1 cm"
density = "2680 kg/m^3"
internal_energy = "4e9 J/kg"
velocity = ["1 km/s", 0.0]
)";

TEST(StabilityRarefied, AParticleThatReachesNothingSetsNoStep) {
  const std::string sph = "density = \"continuity\"\nh_max_factor = 4\n";
  const Ran block = run(blockScene(sph, ""));
  const Ran both = run(blockScene(sph, kHotAlone));
  ASSERT_TRUE(block.outcome.ok) << block.outcome.error;
  ASSERT_TRUE(both.outcome.ok) << both.outcome.error;
  std::size_t k = both.final.numReal;
  for (std::size_t i = 0; i < both.final.numReal; ++i)
    if (both.final.x[0][i] > 0.6) k = i;  // the vapour: the one particle beyond the block
  ASSERT_LT(k, both.final.numReal);
  // Its own step would be far shorter than the run's (measured: ~0.07 of it), so had it voted,
  // the run would have taken many more steps.
  const double own = courantTimestep(SphOptions{}, both.final.h[k], both.final.cs[k], both.final.divv[k]);
  EXPECT_LT(own, 0.2 * both.dtNext);
  EXPECT_EQ(both.outcome.summary.steps, block.outcome.summary.steps);
  // Alone, it moves ballistically and keeps its state: x = x0 + v t, u and rho as they started.
  EXPECT_NEAR(both.final.x[0][k], 0.705 + 1e3 * 150e-6, 1e-9);
  EXPECT_DOUBLE_EQ(both.final.u[k], 4e9);
  EXPECT_DOUBLE_EQ(both.final.rho[k], 2680.0);
}

}  // namespace
}  // namespace ejecta

namespace ejecta::verify {
namespace {

// The known failure of tests/sim/sph/test_sph_options.cpp (ContinuityDensityAtAStrongContact...):
// continuity density with the seed's dh/dt at the 8:1 contact of the circular Sod tube rarefies
// a particle by the contact until its kernel holds more than 30x the neighbours it should. With
// h held at twice its first h (and the density floored where h is the cap) the run finishes and
// stays near the exact solution. Measured L1(rho) 0.026 (the default summation run: 0.0105; the
// contact's rarefied particles cost accuracy, but the run finishes); 0.045 bounds it.
TEST(StabilityRarefied, TheStrongContactUnderContinuityDensityRunsWithACap) {
  Options options;
  options.resolutions = 1;
  options.overrides = {"sph.density=continuity", "sph.smoothing_length=seed",
                       "sph.h_max_factor=2"};
  const Report r = runProblem("sod_2d", options);
  std::printf("  sod_2d, continuity density, h capped: N = %zu, L1(rho) = %.4g, dE/E = %.3g\n",
              r.runs.back().particles, r.runs.back().metric("L1_density"), r.runs.back().energyError);
  EXPECT_LT(r.runs.back().metric("L1_density"), 0.045);
  // Measured dE/E -9e-6: 1e-4 as the Sod tests allow.
  EXPECT_LT(std::abs(r.runs.back().energyError), 1e-4);
}

}  // namespace
}  // namespace ejecta::verify
