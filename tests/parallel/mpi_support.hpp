#pragma once
// Shared by the distributed tests: a run of a scene on given ranks, and the comparison of two
// runs' particles field by field, matched by particle id.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

#include "sim/io/particle_difference.hpp"
#include "sim/parallel/communicator.hpp"
#include "sim/run/simulation.hpp"
#include "sim/setup/bodies.hpp"
#include "sim/setup/scene.hpp"

namespace ejecta::test {

// A scene of scenes/ (path relative to it) with --set overrides.
inline Scene sceneFile(const std::string& relative, const std::vector<std::string>& overrides = {}) {
  return loadScene(std::string(EJECTA_SOURCE_DIR) + "/scenes/" + relative, overrides);
}

// What a run ends with: on rank 0 every particle, in id order.
struct RankedRun {
  ParticleSet particles;
  long steps = 0;
  double time = 0.0;
  ConservedTotals totals;
  DomainStats stats;
};

inline void sortById(ParticleSet& p) {
  std::vector<std::size_t> order(p.numReal);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p.id[a] < p.id[b]; });
  p.permute(order);
}

// Runs `scene` to its t_end on `ranks` (one thread each), without files. `whole`: every rank
// builds the whole scene (as a restart reads a whole snapshot) rather than its slice.
inline RankedRun runOn(const Scene& scene, std::shared_ptr<const Communicator> ranks, bool whole = false) {
  MaterialTable materials = MaterialTable::fromScene(scene);
  ParticleSet particles = buildParticles(scene, materials, whole ? nullptr : ranks.get());
  Simulation sim(scene, std::move(particles), std::move(materials), 1, ranks);
  sim.initialise();
  const double tEnd = scene.time.tEnd;
  while (sim.time() < tEnd * (1.0 - 1e-12)) sim.step(tEnd);
  RankedRun out;
  out.steps = sim.stepCount();
  out.time = sim.time();
  out.totals = sim.totals();
  out.stats = sim.domain().stats();
  out.particles = sim.gatheredParticles();
  if (!sim.domain().distributed()) sortById(out.particles);
  return out;
}

// The largest relative difference of any stored field (sim/io/particle_difference.hpp), failing
// the test when the two sets do not hold the same particles.
inline FieldDifference compareParticles(const ParticleSet& a, const ParticleSet& b) {
  try {
    return largestDifference(particleDifferences(a, b));
  } catch (const std::invalid_argument& e) {
    ADD_FAILURE() << e.what();
    return {"particle ids", 1.0, 1.0};
  }
}

}  // namespace ejecta::test
