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

TEST(Neighbours, MatchBruteForce1D) { checkQueriesAndPairs<1>(400); }
TEST(Neighbours, MatchBruteForce2D) { checkQueriesAndPairs<2>(800); }
TEST(Neighbours, MatchBruteForce3D) { checkQueriesAndPairs<3>(1500); }

}  // namespace
}  // namespace ejecta
