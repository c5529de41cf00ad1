#pragma once
// A 2D blast in a walled box [-0.3, 0.3]^2 against its quarter [0, 0.3]^2 with walls on the
// symmetry axes, shared by the tests of terms that carry a per-particle tensor onto mirror ghosts
// (the reconstructed viscosity's velocity gradient, the integral approach's matrix): with the
// reflection's signs right the quarter's particles match the full box's to round-off.
// `sphTables` is TOML inserted after [domain], e.g. "[sph]\ngradients = \"iad\"\n".
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "sim/run/run.hpp"
#include "sim/run/simulation.hpp"
#include "sim/setup/bodies.hpp"
#include "sim/setup/scene.hpp"
#include "sim/solid/materials.hpp"

namespace ejecta::test {

inline std::string wallBlastScene(double low, double energy, const std::string& sphTables) {
  const std::string lo = std::to_string(low);
  return R"(
[scene]
name = "wall_blast"
dimension = "2d"
[domain]
x = { min = )" + lo + R"(, max = 0.3, boundary = "wall" }
y = { min = )" + lo + R"(, max = 0.3, boundary = "wall" }
)" + sphTables + R"(
[time]
t_end = 0.01
[output]
snapshots = false
[[materials]]
name = "gas"
eos = "ideal_gas"
gamma = 1.4
[[bodies]]
name = "box"
material = "gas"
shape = "box"
min = [)" + lo + ", " + lo + R"(]
max = [0.3, 0.3]
spacing = 0.0125
density = 1.0
pressure = 1e-4
[[energy_deposits]]
name = "blast"
energy = )" + std::to_string(energy) + R"(
center = [0.0, 0.0]
radius = 0.04
)";
}

struct QuarterMismatch {
  double position = 0.0;  // largest distance from a quarter particle to the nearest full one [m]
  double pressure = 0.0;  // largest pressure difference there, over the full box's peak
};

// Runs the full box (energy 0.02) and the quarter (0.005) on one thread and compares them.
inline QuarterMismatch quarterAgainstFullBox(const std::string& sphTables) {
  auto run = [&](double low, double energy) {
    const Scene scene = parseScene(wallBlastScene(low, energy, sphTables), "wall_blast.toml");
    MaterialTable materials = MaterialTable::fromScene(scene);
    ParticleSet p = buildParticles(scene, materials);
    Simulation sim(scene, std::move(p), std::move(materials), 1);
    RunOptions options;
    options.threads = 1;
    const RunOutcome r = runSimulation(sim, options);
    EXPECT_TRUE(r.ok) << r.error;
    return sim.particles();
  };
  const ParticleSet full = run(-0.3, 0.02), quarter = run(0.0, 0.005);
  QuarterMismatch m;
  double peak = 0.0;
  for (std::size_t i = 0; i < full.numReal; ++i) peak = std::max(peak, full.P[i]);
  for (std::size_t q = 0; q < quarter.numReal; ++q) {
    std::size_t best = 0;
    double bestD2 = std::numeric_limits<double>::max();
    for (std::size_t i = 0; i < full.numReal; ++i) {
      const double dx = full.x[0][i] - quarter.x[0][q], dy = full.x[1][i] - quarter.x[1][q];
      if (dx * dx + dy * dy < bestD2) {
        bestD2 = dx * dx + dy * dy;
        best = i;
      }
    }
    m.position = std::max(m.position, std::sqrt(bestD2));
    m.pressure = std::max(m.pressure, std::abs(full.P[best] - quarter.P[q]) / peak);
  }
  return m;
}

}  // namespace ejecta::test
