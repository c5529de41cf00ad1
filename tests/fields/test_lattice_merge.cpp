// The sums a distributed run's grids are merged from (fields/lattice_merge.hpp): a lattice
// survives its byte form exactly, and the sum of the lattices of the parts of a particle set is
// the lattice of the whole, voxel by voxel, to float round-off, with the same blocks; the
// exact order statistic behind the default voxel (sim/parallel/order_statistics.hpp) on one rank.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "fields/grid_set.hpp"
#include "fields/lattice_merge.hpp"
#include "sim/parallel/order_statistics.hpp"

namespace ejecta::fields {
namespace {

// A ball of particles of varied h and temperature (3D) or its meridian half-disc (RZ).
ParticleSet ball(Geometry g, int n) {
  ParticleSet p;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  while (p.size() < static_cast<std::size_t>(n)) {
    const double x = g == Geometry::Axisymmetric ? std::abs(u(rng)) : u(rng), y = u(rng);
    const double z = g == Geometry::Spatial ? u(rng) : 0.0;
    if (x * x + y * y + z * z > 1.0) continue;
    p.append({x, y, z}, {}, 1e-3 * (1.5 + u(rng)), 2000.0, 1e5, 0.12 + 0.03 * u(rng), 0);
  }
  p.numReal = p.size();
  for (std::size_t i = 0; i < p.numReal; ++i) p.temperature[i] = 300.0 + 200.0 * p.x[1][i];
  return p;
}

ParticleSet part(const ParticleSet& p, std::size_t begin, std::size_t end) {
  std::vector<std::size_t> rows(end - begin);
  for (std::size_t i = 0; i < rows.size(); ++i) rows[i] = begin + i;
  ParticleSet q = p;
  q.permute(rows);
  q.numReal = rows.size();
  return q;
}

TEST(LatticeMerge, BytesRoundTripExactly) {
  const ParticleSet p = ball(Geometry::Spatial, 400);
  ParticleContext ctx;
  const SparseLattice a = splatParticles(p, ctx, {p.temperature}, 0.05);
  const SparseLattice b = latticeFromBytes(latticeBytes(a));
  ASSERT_EQ(a.blockCount(), b.blockCount());
  EXPECT_EQ(a.voxel(), b.voxel());
  EXPECT_EQ(a.channels(), b.channels());
  for (std::size_t k = 0; k < a.blockCount(); ++k) {
    EXPECT_EQ(a.blockOrigin(k), b.blockOrigin(k));
    for (int c = 0; c < a.channels(); ++c)
      EXPECT_TRUE(std::equal(a.data(k, c), a.data(k, c) + a.blockVolume(), b.data(k, c)));
  }
  Bytes truncated = latticeBytes(a);
  truncated.pop_back();
  EXPECT_THROW(latticeFromBytes(truncated), std::invalid_argument);
}

TEST(LatticeMerge, TheSumOfThePartsIsTheWhole) {
  for (const Geometry g : {Geometry::Spatial, Geometry::Axisymmetric}) {
    const ParticleSet p = ball(g, g == Geometry::Spatial ? 1500 : 600);
    ParticleContext ctx;
    ctx.geometry = g;
    const double voxel = 0.04;
    const SparseLattice whole = splatParticles(p, ctx, {p.temperature}, voxel);
    // Three unequal parts, as three ranks hold them.
    const std::size_t n = p.numReal, cut1 = n / 5, cut2 = n / 2;
    SparseLattice sum = splatParticles(part(p, 0, cut1), ctx, {part(p, 0, cut1).temperature}, voxel);
    for (const auto& [b, e] : {std::pair{cut1, cut2}, std::pair{cut2, n}}) {
      const ParticleSet q = part(p, b, e);
      accumulate(sum, splatParticles(q, ctx, {q.temperature}, voxel));
    }
    EXPECT_EQ(sum.blockCount(), whole.blockCount());
    float largest = 0.0f;
    for (std::size_t k = 0; k < whole.blockCount(); ++k)
      for (int v = 0; v < whole.blockVolume(); ++v) largest = std::max(largest, whole.data(k, 1)[v]);
    double worst = 0.0;
    for (std::size_t k = 0; k < whole.blockCount(); ++k) {
      const Index3& o = whole.blockOrigin(k);
      const long s = sum.findBlock(o[0], o[1], o[2]);
      ASSERT_GE(s, 0);
      for (int c = 0; c < 2; ++c)
        for (int v = 0; v < whole.blockVolume(); ++v)
          worst = std::max(worst, static_cast<double>(std::abs(
                                      whole.data(k, c)[v] - sum.data(static_cast<std::size_t>(s), c)[v])));
    }
    // float32 sums in another order: a few ulps of the largest value (2^-23 = 1.2e-7 each).
    EXPECT_LE(worst, 1e-6 * largest) << geometryName(g);
    EXPECT_GT(largest, 0.0f);
  }
  SparseLattice a(3, 0.1, 2), other(3, 0.2, 2);
  EXPECT_THROW(accumulate(a, other), std::invalid_argument);
}

TEST(OrderStatistics, KthSmallestIsTheSortedElementOnOneRank) {
  std::mt19937 rng(11);
  std::normal_distribution<double> normal(0.0, 3.0);
  std::vector<double> values;
  for (int i = 0; i < 1000; ++i) values.push_back(normal(rng));
  values.push_back(0.0);
  values.push_back(-0.0);
  values.push_back(std::numeric_limits<double>::infinity());
  values.push_back(-std::numeric_limits<double>::denorm_min());
  values.push_back(values[5]);  // a repeated value
  std::vector<double> sorted = values;
  std::sort(sorted.begin(), sorted.end());
  const SerialCommunicator one;
  for (std::size_t k = 0; k < sorted.size(); k += 7)
    EXPECT_EQ(kthSmallest(values, k, one), sorted[k]) << k;
  EXPECT_EQ(kthSmallest(values, sorted.size() - 1, one), sorted.back());
  EXPECT_EQ(upperMedian(values, one), sorted[sorted.size() / 2]);
  EXPECT_THROW(kthSmallest(values, sorted.size(), one), std::out_of_range);
}

}  // namespace
}  // namespace ejecta::fields
