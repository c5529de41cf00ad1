// Neighbour search against brute force: cell-grid queries, and the symmetric pair lists built
// from per-particle gather lists, on random particles with strongly varying h.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "sim/sph/cell_grid.hpp"
#include "sim/sph/neighbour_lists.hpp"

namespace ejecta {
namespace {

template <int D>
ParticleSet randomParticles(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> pos(-1.0, 1.0), logh(std::log(0.02), std::log(0.3));
  ParticleSet p;
  for (std::size_t i = 0; i < n; ++i)
    p.append({pos(rng), D > 1 ? pos(rng) : 0.0, D > 2 ? pos(rng) : 0.0}, {0, 0, 0}, 1.0, 1.0,
             1.0, std::exp(logh(rng)), 0);
  return p;
}

template <int D>
double distance(const ParticleSet& p, std::size_t i, std::size_t j) {
  double r2 = 0;
  for (int d = 0; d < D; ++d) r2 += (p.x[d][i] - p.x[d][j]) * (p.x[d][i] - p.x[d][j]);
  return std::sqrt(r2);
}

template <int D>
void checkQueriesAndPairs(std::size_t n) {
  ParticleSet p = randomParticles<D>(n, 7 + D);
  CellGrid grid;
  grid.build(p, D, 0.1);  // cells smaller than many supports: multi-cell queries are exercised
  NeighbourLists lists;
  lists.reset(n, 1);
  std::vector<std::uint32_t> found;
  for (std::size_t i = 0; i < n; ++i) {
    found.clear();
    const double point[3] = {p.x[0][i], p.x[1][i], p.x[2][i]};
    grid.query<D>(p, point, 2.0 * p.h[i], found);
    std::set<std::uint32_t> got(found.begin(), found.end()), want;
    for (std::size_t j = 0; j < n; ++j)
      if (distance<D>(p, i, j) < 2.0 * p.h[i]) want.insert(static_cast<std::uint32_t>(j));
    ASSERT_EQ(got, want) << "particle " << i;
    ASSERT_EQ(got.size(), found.size()) << "duplicates in the query result";
    lists.storeGather(0, i, found.data(), found.size());
  }
  lists.buildPairs<D>(p, 2.0);
  for (std::size_t i = 0; i < n; ++i) {
    const auto pairs = lists.pairs(i);
    std::set<std::uint32_t> got(pairs.begin(), pairs.end()), want;
    for (std::size_t j = 0; j < n; ++j)
      if (distance<D>(p, i, j) < 2.0 * std::max(p.h[i], p.h[j]))
        want.insert(static_cast<std::uint32_t>(j));
    ASSERT_EQ(got, want) << "pairs of particle " << i;
    ASSERT_EQ(got.size(), pairs.size()) << "duplicate pairs";
  }
}

// The kernels reaching a point (individual time steps' partner search, CellGrid::recordReach and
// queryReaching) against brute force, on particles whose h spans 15x plus a few 4x wider still
// (a blast's hot centre, supports past the box); and the active particles' pair lists built from
// them equal to those of the full build, in the same order.
template <int D>
void checkReachingAndActivePairs(std::size_t n) {
  ParticleSet p = randomParticles<D>(n, 11 + D);
  for (std::size_t i = 0; i < n; i += n / 5) p.h[i] *= 4.0;
  CellGrid grid;
  grid.build(p, D, 0.1);
  grid.recordReach(p, 2.0);
  std::vector<std::uint32_t> found;
  for (std::size_t i = 0; i < n; i += 3) {
    const double point[3] = {p.x[0][i], p.x[1][i], p.x[2][i]};
    for (double beyond : {0.0, 2.0 * p.h[i]}) {
      found.clear();
      grid.queryReaching<D>(point, grid.reachInto(point), found, beyond);
      std::set<std::uint32_t> got;  // the caller's own test: r < 2 h_j
      for (std::uint32_t j : found)
        if (distance<D>(p, i, j) < 2.0 * p.h[j]) got.insert(j);
      std::set<std::uint32_t> want;
      for (std::size_t j = 0; j < n; ++j) {
        const double r = distance<D>(p, i, j);
        if (r >= beyond && r < 2.0 * p.h[j]) want.insert(static_cast<std::uint32_t>(j));
      }
      ASSERT_EQ(got, want) << "particle " << i << ", beyond " << beyond;
      ASSERT_EQ(std::set<std::uint32_t>(found.begin(), found.end()).size(), found.size())
          << "duplicates in the query result";
    }
  }
  NeighbourLists full, some;
  full.reset(n, 1);
  some.reset(n, 1);
  for (std::size_t i = 0; i < n; ++i) {
    found.clear();
    const double point[3] = {p.x[0][i], p.x[1][i], p.x[2][i]};
    grid.query<D>(p, point, 2.0 * p.h[i], found);
    full.storeGather(0, i, found.data(), found.size());
    some.storeGather(0, i, found.data(), found.size());
  }
  full.buildPairs<D>(p, 2.0);
  std::vector<std::size_t> active;
  for (std::size_t i = 1; i < n; i += 4) active.push_back(i);
  some.buildActivePairs<D>(p, grid, 2.0, active);
  for (std::size_t i : active) {
    const auto a = full.pairs(i), b = some.pairs(i);
    ASSERT_TRUE(std::equal(a.begin(), a.end(), b.begin(), b.end())) << "pairs of particle " << i;
  }
  EXPECT_TRUE(some.pairs(0).empty());  // an inactive particle gets no pairs
}

TEST(Neighbours, ReachingKernelsAndActivePairs1D) { checkReachingAndActivePairs<1>(400); }
TEST(Neighbours, ReachingKernelsAndActivePairs2D) { checkReachingAndActivePairs<2>(800); }
TEST(Neighbours, ReachingKernelsAndActivePairs3D) { checkReachingAndActivePairs<3>(1500); }

TEST(Neighbours, MatchBruteForce1D) { checkQueriesAndPairs<1>(400); }
TEST(Neighbours, MatchBruteForce2D) { checkQueriesAndPairs<2>(800); }
TEST(Neighbours, MatchBruteForce3D) { checkQueriesAndPairs<3>(1500); }

}  // namespace
}  // namespace ejecta
