// The decomposition and the halos on 2 and 3 ranks (CTest runs this binary under mpirun): every
// particle owned once with its fields intact, rebalancing by cost, and halos that hold every
// neighbour each rank's particles have. Each rank builds the whole scene (as a run does), so the
// checks can compare a rank's share with the whole set directly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "parallel/mpi_support.hpp"
#include "sim/parallel/distributed_domain.hpp"
#include "sim/parallel/order_statistics.hpp"
#include "sim/sph/kernel.hpp"

namespace ejecta::test {
namespace {

std::shared_ptr<const Communicator> world() { return worldCommunicator(); }

ParticleSet wholeScene(const std::string& relative, const std::vector<std::string>& overrides) {
  const Scene scene = sceneFile(relative, overrides);
  return buildParticles(scene, MaterialTable::fromScene(scene));
}

// Each rank's share gathered at rank 0 is the whole set, field for field, bit for bit.
void expectWholeSetAtRoot(const DistributedDomain& domain, const ParticleSet& share,
                          const ParticleSet& whole) {
  const ParticleSet gathered = domain.gatherToRoot(share);
  if (!world()->isRoot()) return;
  ParticleSet sorted = whole;
  sortById(sorted);
  const FieldDifference d = compareParticles(sorted, gathered);
  EXPECT_EQ(d.relative, 0.0) << d.field;
  std::set<std::int64_t> ids(gathered.id.begin(), gathered.id.end());
  EXPECT_EQ(ids.size(), whole.numReal);  // each particle once
}

TEST(MpiDecomposition, EveryParticleIsOwnedOnceAndKeepsItsFields) {
  for (const char* scene : {"verification/sedov_2d.toml", "verification/sedov_3d.toml"}) {
    const ParticleSet whole = wholeScene(scene, {"bodies[0].spacing=0.05"});
    const int dim = std::string(scene).find("3d") != std::string::npos ? 3 : 2;
    DistributedDomain domain(world(), dim);
    ParticleSet share = whole;
    domain.keepShare(share);
    // Equal weights: each rank holds its share of the particles to within a few (ties of keys).
    const double fair = static_cast<double>(whole.numReal) / world()->size();
    EXPECT_NEAR(static_cast<double>(share.numReal), fair, 0.01 * fair + 2) << scene;
    expectWholeSetAtRoot(domain, share, whole);
  }
}

TEST(MpiDecomposition, RebalancingByCostPreservesParticlesAndEvensTheCost) {
  const ParticleSet whole = wholeScene("verification/sedov_2d.toml", {"bodies[0].spacing=0.02"});
  DistributedDomain domain(world(), 2);
  ParticleSet share = whole;
  domain.keepShare(share);
  // Particles on the left cost ten times more (a solid beside a gas): equal counts are then far
  // out of balance, and new splitters must even the cost.
  auto costs = [](const ParticleSet& p) {
    std::vector<std::uint64_t> c(p.numReal);
    for (std::size_t i = 0; i < p.numReal; ++i) c[i] = p.x[0][i] < 0.0 ? 10 : 1;
    return c;
  };
  domain.rebalance(share, costs(share));
  EXPECT_GT(domain.stats().lastImbalance, 0.1);  // measured before: the left ranks were loaded
  EXPECT_EQ(domain.stats().rebalances, 2);
  const std::vector<std::uint64_t> after = costs(share);
  const double mine = std::accumulate(after.begin(), after.end(), 0.0);
  // One particle's cost (10) over a rank's (~9,000) is the finest the split can do.
  EXPECT_LT(loadImbalance(mine, *world()), 0.01);
  expectWholeSetAtRoot(domain, share, whole);
  // In balance now: a second call keeps the splitters and moves nothing.
  const std::size_t migrated = domain.stats().migrated;
  domain.rebalance(share, costs(share));
  EXPECT_EQ(domain.stats().rebalances, 2);
  EXPECT_EQ(domain.stats().migrated, migrated);
}

// Every pair within the kernel support of the larger h (what the force pass sums) has both
// particles on the rank of each, as a real particle or a halo.
void expectCompleteHalos(const std::string& scene, int dim, const std::string& spacing) {
  ParticleSet whole = wholeScene(scene, {"bodies[0].spacing=" + spacing});
  // Uneven h (every third particle's support 1.6x wider) so that max(h_i, h_j) matters.
  for (std::size_t i = 0; i < whole.numReal; ++i)
    if (whole.id[i] % 3 == 0) whole.h[i] *= 1.6;
  DistributedDomain domain(world(), dim);
  ParticleSet share = whole;
  domain.keepShare(share);
  domain.halos().build(share, dim, kKernelSupport, *world());
  std::set<std::int64_t> present(share.id.begin(), share.id.end());
  std::size_t pairs = 0, missing = 0;
  for (std::size_t i = 0; i < share.numReal; ++i)
    for (std::size_t j = 0; j < whole.numReal; ++j) {
      double r2 = 0.0;
      for (int d = 0; d < dim; ++d) {
        const double dx = share.x[static_cast<std::size_t>(d)][i] - whole.x[static_cast<std::size_t>(d)][j];
        r2 += dx * dx;
      }
      const double reach = kKernelSupport * std::max(share.h[i], whole.h[j]);
      if (r2 >= reach * reach) continue;
      ++pairs;
      missing += present.count(whole.id[j]) == 0;
    }
  EXPECT_GT(pairs, share.numReal);
  EXPECT_EQ(missing, 0u) << scene << " rank " << world()->rank();
  // The halo is a rind, not a copy of everything: at these sizes (600 particles a rank in 2D,
  // 2,700 in 3D) fewer than this rank's own particles (twice in 3D, where the rind is thicker).
  EXPECT_GT(domain.halos().received(), 0u);
  EXPECT_LT(domain.halos().received(), share.numReal * (dim == 3 ? 2 : 1)) << scene;
}

TEST(MpiDecomposition, HalosHoldEveryNeighbourIn2d) {
  expectCompleteHalos("verification/sedov_2d.toml", 2, "0.025");
}
TEST(MpiDecomposition, HalosHoldEveryNeighbourIn3d) {
  expectCompleteHalos("verification/sedov_3d.toml", 3, "0.05");
}

}  // namespace
}  // namespace ejecta::test

namespace ejecta::test {
namespace {

// The k-th smallest of values spread unevenly over the ranks (one rank holds none) is the
// element a sort of all of them gives, on every rank: the default voxel of a distributed
// run's grids is the one-rank run's exactly.
TEST(MpiOrderStatistics, KthSmallestOverRanksIsTheSortedElement) {
  const auto world = worldCommunicator();
  std::vector<double> all;
  for (int i = 0; i < 500; ++i) all.push_back(std::sin(1.7 * i) * std::exp(0.01 * i) - (i % 3 == 0 ? 0.0 : 0.3));
  std::vector<double> mine;
  for (std::size_t i = 0; i < all.size(); ++i)
    if (world->rank() != 1 && static_cast<int>(i * i % 7) % world->size() == world->rank()) mine.push_back(all[i]);
  std::vector<double> held = mine;
  // What every rank holds, by gathering it (for the check only).
  std::vector<double> gathered;
  for (const Bytes& b : world->allGather({reinterpret_cast<const std::byte*>(held.data()), held.size() * sizeof(double)}))
    for (double v : fromBytes<double>(b)) gathered.push_back(v);
  std::sort(gathered.begin(), gathered.end());
  ASSERT_FALSE(gathered.empty());
  for (std::size_t k = 0; k < gathered.size(); k += 13) EXPECT_EQ(kthSmallest(mine, k, *world), gathered[k]) << k;
  EXPECT_EQ(upperMedian(mine, *world), gathered[gathered.size() / 2]);
}

}  // namespace
}  // namespace ejecta::test
