#pragma once
// The checks every fluid-only [sph] option (gradients = "iad", volume_elements = "generalised",
// dissipation = "riemann") shares: on the periodic 2D blast of tests/support/periodic_blast.hpp,
// its centre off the lattice's symmetry, momentum and energy conserved and results independent of
// the thread count (`option`: the --set overrides that turn it on); and the scenes the reader and
// the simulation refuse it for, with the file, the key and the reason named (`line`: the [sph]
// line that turns it on, e.g. `dissipation = "riemann"`).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "sim/run/run.hpp"
#include "sim/run/simulation.hpp"
#include "sim/setup/bodies.hpp"
#include "sim/setup/scene.hpp"
#include "sim/solid/materials.hpp"
#include "support/periodic_blast.hpp"

namespace ejecta::test {

inline constexpr const char* kOptionSceneFile = "option.toml";

inline Simulation simulationOf(const Scene& scene, int threads) {
  MaterialTable materials = MaterialTable::fromScene(scene);
  ParticleSet p = buildParticles(scene, materials);
  return Simulation(scene, std::move(p), std::move(materials), threads);
}

inline Scene offCentreBlast(std::vector<std::string> option, const std::vector<std::string>& more = {}) {
  option.push_back("energy_deposits[0].center=[0.1375, 0.0625]");
  option.insert(option.end(), more.begin(), more.end());
  return parseScene(periodicBlastScene(), "option_blast.toml", option);
}

// Energy to `energyBound` of the total (the time integration's error: test_simulation.cpp's
// kernel-gradient blast measures ~1e-4 with a bound of 1e-3); momentum to round-off of sum |m v|
// (antisymmetric pair terms and periodic images).
inline void expectBlastConserves(const std::vector<std::string>& option, double energyBound = 1e-3) {
  Simulation sim = simulationOf(offCentreBlast(option), 2);
  const RunOutcome r = runSimulation(sim, RunOptions{});
  ASSERT_TRUE(r.ok) << r.error;
  std::printf("  periodic blast: energy error %.2e, %ld steps\n", r.summary.energy.relativeError,
              r.summary.steps);
  EXPECT_LT(std::abs(r.summary.energy.relativeError), energyBound);
  double scale = 0.0;
  const ParticleSet& p = sim.particles();
  for (std::size_t i = 0; i < p.numReal; ++i) scale += p.mass[i] * std::hypot(p.v[0][i], p.v[1][i]);
  for (int d = 0; d < 2; ++d)
    EXPECT_LT(std::abs(r.summary.momentum.final[d] - r.summary.momentum.initial[d]), 1e-12 * scale);
}

// Bit for bit on 1 and 2 threads (every reduction is ordered).
inline void expectThreadIndependent(const std::vector<std::string>& option) {
  auto run = [&option](int threads) {
    Simulation sim = simulationOf(offCentreBlast(option, {"time.t_end=0.006"}), threads);
    EXPECT_TRUE(runSimulation(sim, RunOptions{}).ok);
    return sim.particles();
  };
  const ParticleSet a = run(2), b = run(1);
  ASSERT_EQ(a.numReal, b.numReal);
  for (std::size_t i = 0; i < a.numReal; ++i) {
    ASSERT_EQ(a.x[0][i], b.x[0][i]) << i;
    ASSERT_EQ(a.v[1][i], b.v[1][i]) << i;
    ASSERT_EQ(a.u[i], b.u[i]) << i;
  }
}

// A gas box in `dimension` with the option's line and `sph` in [sph], `more` after [time] (e.g.
// `stepping = "individual"`).
inline std::string optionGasScene(const std::string& line, const std::string& dimension,
                                  const std::string& sph = "", const std::string& more = "") {
  return R"(
[scene]
name = "option"
dimension = ")" + dimension + R"("
[sph]
)" + line + "\n" + sph + R"(
[time]
t_end = "1 s"
)" + more + R"(
[[materials]]
name = "gas"
eos = "ideal_gas"
gamma = 1.4
[[bodies]]
name = "box"
material = "gas"
shape = "box"
min = [0.0, 0.0]
max = [1.0, 1.0]
spacing = 0.1
density = 1.0
pressure = 1.0
)";
}

// A 2D scene with the option's line and a material with strength ('granite').
inline std::string optionSolidScene(const std::string& line) {
  return R"(
[scene]
name = "option"
dimension = "2d"
[sph]
)" + line + R"(
[time]
t_end = "1 s"
[[materials]]
name = "granite"
eos = "tillotson"
library = "granite"
[materials.strength]
model = "von_mises"
yield_stress = "1 GPa"
shear_modulus = "30 GPa"
)";
}

// The reader refuses `toml` naming the file, `key` and `words`.
inline void expectReaderRefuses(const std::string& toml, const std::string& key,
                                const std::string& words) {
  try {
    parseScene(toml, kOptionSceneFile);
    ADD_FAILURE() << "accepted; expected a refusal naming " << key;
  } catch (const SceneError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(kOptionSceneFile), std::string::npos) << message;
    EXPECT_NE(message.find(key), std::string::npos) << message;
    EXPECT_NE(message.find(words), std::string::npos) << message;
  }
}

// What none of the fluid options (IAD gradients, generalised volumes, Riemann dissipation) is built
// for, refused by the reader naming `key`: continuity density, the interface form, a material with
// strength. (Each option's test adds its own: RZ, individual steps, the other options.)
inline void expectRefusedWhereNoOptionIsBuilt(const std::string& line, const std::string& key) {
  expectReaderRefuses(optionGasScene(line, "2d", "density = \"continuity\"\n"), key,
                      "summation density");
  expectReaderRefuses(optionGasScene(line, "2d", "form = \"interface\"\n"), key, "Lagrangian form");
  expectReaderRefuses(optionSolidScene(line), key, "granite");
}

// A scene built in code (a bench) passes no reader: the simulation refuses the option with
// individual steps itself, naming `key`.
inline void expectSimulationRefusesIndividualSteps(const std::string& line, const std::string& key) {
  Scene scene = parseScene(optionGasScene(line, "2d"), kOptionSceneFile);
  scene.time.stepping = Stepping::Individual;
  try {
    simulationOf(scene, 1);
    ADD_FAILURE() << "accepted individual steps";
  } catch (const SimulationError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(key), std::string::npos) << message;
    EXPECT_NE(message.find("global time steps"), std::string::npos) << message;
  }
}

}  // namespace ejecta::test
