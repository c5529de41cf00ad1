#pragma once
// A 2D scene run to its end with its initial and final particles, and how far the run broke the
// mirror symmetry of its lattice: tests/sim/run/test_stability.cpp (where the seed's code lost
// symmetry) and the same burst on individual time steps (test_verify_individual_steps.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <string>
#include <utility>

#include "sim/run/run.hpp"
#include "sim/run/simulation.hpp"
#include "sim/setup/bodies.hpp"
#include "sim/setup/scene.hpp"
#include "sim/solid/materials.hpp"

namespace ejecta::test {

// A scene's particles at its start and its end, and the run's outcome (2 threads).
struct Ran {
  ParticleSet initial;
  ParticleSet final;
  RunOutcome outcome;
};

inline Ran runMirrorScene(const std::string& toml) {
  const Scene scene = parseScene(toml, "stability.toml");
  MaterialTable materials = MaterialTable::fromScene(scene);
  Ran r;
  r.initial = buildParticles(scene, materials);
  Simulation sim(scene, r.initial, std::move(materials), 2);
  r.outcome = runSimulation(sim, RunOptions{});
  r.final = sim.particles();
  std::printf("  %s: %zu particles, %ld steps, dE/E = %.3g\n", scene.name.c_str(),
              r.final.numReal, r.outcome.summary.steps, r.outcome.summary.energy.relativeError);
  return r;
}

// The largest distance between a particle's final position and the mirror image (through the
// plane x[axis] = 0) of its initial partner's final position, over all pairs; ids are matched by
// their mirrored initial positions on the symmetric lattice.
inline double mirrorAsymmetry(const Ran& r, int axis) {
  const ParticleSet& p0 = r.initial;
  std::map<std::pair<long long, long long>, std::int64_t> byPosition;
  auto key = [](double x, double y) {
    return std::make_pair(std::llround(x * 1e6), std::llround(y * 1e6));
  };
  for (std::size_t i = 0; i < p0.numReal; ++i) byPosition[key(p0.x[0][i], p0.x[1][i])] = p0.id[i];
  std::map<std::int64_t, std::size_t> finalIndex;
  for (std::size_t i = 0; i < r.final.numReal; ++i) finalIndex[r.final.id[i]] = i;
  double worst = 0.0;
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < p0.numReal; ++i) {
    double x = p0.x[0][i], y = p0.x[1][i];
    (axis == 0 ? x : y) *= -1.0;
    const auto it = byPosition.find(key(x, y));
    if (it == byPosition.end()) continue;
    ++pairs;
    const std::size_t a = finalIndex.at(p0.id[i]), b = finalIndex.at(it->second);
    double mx = r.final.x[0][b], my = r.final.x[1][b];
    (axis == 0 ? mx : my) *= -1.0;
    worst = std::max(worst, std::hypot(r.final.x[0][a] - mx, r.final.x[1][a] - my));
  }
  EXPECT_EQ(pairs, p0.numReal) << "the lattice should be mirror-symmetric";
  return worst;
}

// 250 kt (per metre: 2D planar) deposited in a 2 m granite device at the centre of a 30 m
// granite disc, to 0.5 ms: a specific energy of 3e10 J/kg next to cold rock, the energy contrast
// at which the seed's in-house SPH lost symmetry and over-predicted internal energy. `timeLines`
// go into [time] (e.g. `stepping = "individual"`).
inline std::string burst250ktScene(const std::string& timeLines = "") {
  return R"(
[scene]
name = "burst_250kt"
dimension = "2d"
[sph]
density = "continuity"
form = "interface"
[time]
t_end = "0.5 ms"
)" + timeLines + R"(
[[materials]]
name = "granite"
eos = "tillotson"
library = "granite"
parameters = { minimum_pressure = 0.0 }
[[materials]]
name = "device"
eos = "tillotson"
library = "granite"
[[bodies]]
name = "device"
material = "device"
shape = "sphere"
center = [0.0, 0.0]
radius = "2 m"
spacing = "0.75 m"
density = 2680.0
pressure = 0.0
[[bodies]]
name = "rock"
material = "granite"
shape = "sphere"
center = [0.0, 0.0]
radius = "30 m"
spacing = "0.75 m"
density = 2680.0
pressure = 0.0
[[energy_deposits]]
name = "yield"
body = "device"
energy = "250 kt"
)";
}

}  // namespace ejecta::test
