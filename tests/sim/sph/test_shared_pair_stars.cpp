// SharedPairStars (sim/sph/shared_pair_stars.hpp): the pairs both of whose particles a Godunov
// force pass sums are solved once, by the lower particle, and each side reads the state as it
// sees it. Here the "solver" encodes the pair in its result, so that a state handed to the wrong
// particle, from the wrong pair or with the wrong sign is told apart exactly; on the pairs of a 2D
// gas block (gather lists and the wider kernels' partners), with every particle summed and with a
// subset, on one and two threads.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "sim/setup/bodies.hpp"
#include "sim/setup/scene.hpp"
#include "sim/solid/materials.hpp"
#include "sim/sph/density_pass.hpp"
#include "sim/sph/hydro_workspace.hpp"
#include "sim/sph/kernel.hpp"
#include "sim/sph/shared_pair_stars.hpp"
#include "support/fluid_option_checks.hpp"

namespace ejecta {
namespace {

// The encoded state of the pair solved with `lower` on the left.
StarState encoded(std::size_t lower, std::size_t upper) {
  return {1000.0 * static_cast<double>(lower) + static_cast<double>(upper),
          static_cast<double>(lower) + 0.5 * static_cast<double>(upper)};
}

struct Block {
  ParticleSet p;
  HydroWorkspace ws{SphOptions{}, Geometry::Planar};
};

Block gasBlock() {
  const Scene scene = parseScene(test::optionGasScene("", "2d"), "shared.toml",
                                 {"bodies[0].spacing=0.05"});
  Block b{buildParticles(scene, MaterialTable::fromScene(scene))};
  // A smoothing length that varies over the block, so that the pairs include partners whose wider
  // kernel reaches a particle its own does not.
  for (std::size_t i = 0; i < b.p.numReal; ++i) b.p.h[i] *= 1.0 + 0.4 * b.p.x[0][i];
  b.ws.grid.build(b.p, 2, 0.2);
  b.ws.lists.reset(b.p.size(), omp_get_max_threads());
  b.ws.sph.eta = 1.2;
  EXPECT_FALSE(runDensityPass(b.p, b.ws).has_value());
  b.ws.lists.findGhostGathers<2>(b.p, b.ws.grid, kKernelSupport);
  b.ws.lists.buildPairs<2>(b.p, kKernelSupport);
  return b;
}

// Every summed particle's walk over its pairs gives each partner the state expected of it.
void expectEachSideReadsItsPair(const Block& b, const std::vector<std::size_t>* summed, int threads) {
  const std::size_t n = b.p.numReal;
  std::vector<char> isSummed(n, summed ? 0 : 1);
  if (summed)
    for (std::size_t i : *summed) isSummed[i] = 1;
  // The pairs both sides sum, each counted once: the solves expected.
  std::size_t expectedSolves = 0, sharedSeen = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (isSummed[i])
      for (std::uint32_t j : b.ws.lists.pairs(i)) expectedSolves += j < n && j > i && isSummed[j];
  ASSERT_GT(expectedSolves, 100u);

  // The thread count restored however the checks below end (a failed ASSERT returns early).
  struct Threads {
    int before = omp_get_max_threads();
    ~Threads() { omp_set_num_threads(before); }
  } restore;
  omp_set_num_threads(threads);
  SharedPairStars stars;
  std::atomic<std::size_t> solves{0};
  stars.solveAll(b.ws.lists, n, summed, [&](std::size_t i, std::size_t j) {
    ++solves;
    EXPECT_LT(i, j);
    return encoded(i, j);
  });
  EXPECT_EQ(solves.load(), expectedSolves);
  for (std::size_t i = 0; i < n; ++i) {
    if (!isSummed[i]) continue;
    SharedPairStars::Walk walk = stars.walk(i, 0);
    for (std::uint32_t j : b.ws.lists.pairs(i)) {
      const std::uint32_t at = walk.index(j);
      if (j >= n || !isSummed[j] || j == i) {
        EXPECT_EQ(at, SharedPairStars::kNotShared) << i << " with " << j;
        continue;
      }
      ASSERT_NE(at, SharedPairStars::kNotShared) << i << " with " << j;
      ++sharedSeen;
      const StarState s = stars.star(at);
      const StarState want = i < j ? encoded(i, j) : StarState{encoded(j, i).P, -encoded(j, i).u};
      EXPECT_EQ(s.P, want.P) << i << " with " << j;
      EXPECT_EQ(s.u, want.u) << i << " with " << j;
    }
  }
  EXPECT_EQ(sharedSeen, 2 * expectedSolves);  // each solved pair read from both sides
}

TEST(SharedPairStars, EachSideOfASummedPairReadsTheLowerOnesSolve) {
  const Block b = gasBlock();
  for (int threads : {1, 2}) expectEachSideReadsItsPair(b, nullptr, threads);
}

TEST(SharedPairStars, OnlyPairsOfSummedParticlesAreShared) {
  const Block b = gasBlock();
  std::vector<std::size_t> summed;
  for (std::size_t i = 0; i < b.p.numReal; i += 3) summed.push_back(i);
  for (std::size_t i = 101; i < 110; ++i) summed.push_back(i);  // a cluster of neighbours
  std::sort(summed.begin(), summed.end());
  summed.erase(std::unique(summed.begin(), summed.end()), summed.end());
  for (int threads : {1, 2}) expectEachSideReadsItsPair(b, &summed, threads);
}

// The upper particle finds a state through its own pair list: a list that holds a summed partner
// below it which does not list it back would read another pair's state, so it is refused.
TEST(SharedPairStars, PairListsThatAreNotSymmetricAreRefused) {
  ParticleSet p;
  p.append({0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, 1.0, 1.0, 1.0, 1.0, 0);
  p.append({0.5, 0.0, 0.0}, {0.0, 0.0, 0.0}, 1.0, 1.0, 1.0, 1.0, 0);
  NeighbourLists lists;
  lists.reset(p.size(), 1);
  const std::uint32_t first[] = {0, 1}, second[] = {1};  // 0 within 1's support, not listed
  lists.storeGather(0, 0, first, 2);
  lists.storeGather(0, 1, second, 1);
  lists.buildPairs<1>(p, kKernelSupport);
  ASSERT_EQ(lists.pairs(0).size(), 2u);
  ASSERT_EQ(lists.pairs(1).size(), 1u);
  SharedPairStars stars;
  EXPECT_THROW(stars.solveAll(lists, p.numReal, nullptr,
                              [](std::size_t i, std::size_t j) { return encoded(i, j); }),
               std::logic_error);
}

}  // namespace
}  // namespace ejecta
