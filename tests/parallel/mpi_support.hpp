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

#include "sim/parallel/communicator.hpp"
#include "sim/run/simulation.hpp"
#include "sim/setup/bodies.hpp"
#include "sim/setup/scene.hpp"

namespace ejecta::test {

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

// Runs `scene` to its t_end on `ranks` (one thread each), without files.
inline RankedRun runOn(const Scene& scene, std::shared_ptr<const Communicator> ranks) {
  MaterialTable materials = MaterialTable::fromScene(scene);
  ParticleSet particles = buildParticles(scene, materials);
  Simulation sim(scene, std::move(particles), std::move(materials), 1, ranks);
  sim.initialise();
  const double tEnd = scene.time.tEnd;
  while (sim.time() < tEnd * (1.0 - 1e-12)) sim.step(tEnd);
  RankedRun out;
  out.steps = sim.stepCount();
  out.time = sim.time();
  out.totals = sim.totals();
  out.stats = sim.domain().stats();
  sim.collectParticles();
  out.particles = sim.outputParticles();
  if (!sim.domain().distributed()) sortById(out.particles);
  return out;
}

// The largest difference between two runs' values of any stored floating-point field, over the
// largest magnitude of that field (so a field that is zero nearly everywhere is not judged by
// its tiny entries), with the field's name. Integer fields must match exactly.
struct FieldDifference {
  double relative = 0.0;
  std::string field;
};

inline FieldDifference compareParticles(const ParticleSet& a, const ParticleSet& b) {
  FieldDifference worst;
  EXPECT_EQ(a.numReal, b.numReal);
  if (a.numReal != b.numReal) return {1.0, "particle count"};
  for (const Field& f : a.fields()) {
    if (f.storage.kind == FieldStorage::Kind::Derived || f.spec.output == FieldOutput::None) continue;
    const Field* g = b.field(f.spec.name);
    EXPECT_NE(g, nullptr) << f.spec.name;
    if (!g) continue;
    if (f.storage.kind == FieldStorage::Kind::Int32) {
      EXPECT_TRUE(a.*f.storage.int32 == b.*g->storage.int32) << f.spec.name;
      continue;
    }
    if (f.storage.kind == FieldStorage::Kind::Int64) {
      EXPECT_TRUE(a.*f.storage.int64 == b.*g->storage.int64) << f.spec.name;
      continue;
    }
    for (int c = 0; c < f.spec.components; ++c) {
      const std::vector<double>& x = a.column(f, c);
      const std::vector<double>& y = b.column(*g, c);
      double scale = 0.0, diff = 0.0;
      for (std::size_t i = 0; i < a.numReal; ++i) {
        if (std::isinf(x[i]) && x[i] == y[i]) continue;  // lighting times of non-explosives
        scale = std::max(scale, std::abs(x[i]));
        diff = std::max(diff, std::abs(x[i] - y[i]));
      }
      const double relative = scale > 0.0 ? diff / scale : diff;
      if (!(relative <= worst.relative)) worst = {relative, f.spec.name + "[" + std::to_string(c) + "]"};
    }
  }
  return worst;
}

}  // namespace ejecta::test
