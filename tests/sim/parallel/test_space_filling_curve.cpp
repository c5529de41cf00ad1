// Hilbert keys (sim/parallel/space_filling_curve.hpp) and the one-rank decomposition. The curve's
// defining property is checked directly: over an aligned block of 2^k cells a side, the keys are
// a permutation of one contiguous range, and cells consecutive in key order are face neighbours
// (the curve never jumps; Morton order would jump between every quadrant).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <vector>

#include "sim/parallel/decomposition.hpp"
#include "sim/parallel/space_filling_curve.hpp"

namespace ejecta {
namespace {

void expectContinuousCurve(int dimension, std::uint32_t side) {
  struct Cell {
    std::uint64_t key;
    std::array<std::uint32_t, 3> at;
  };
  std::vector<Cell> cells;
  const std::uint32_t nz = dimension == 3 ? side : 1;
  for (std::uint32_t z = 0; z < nz; ++z)
    for (std::uint32_t y = 0; y < side; ++y)
      for (std::uint32_t x = 0; x < side; ++x)
        cells.push_back({hilbertKey({x, y, z}, dimension), {x, y, z}});
  std::sort(cells.begin(), cells.end(), [](const Cell& a, const Cell& b) { return a.key < b.key; });
  // A contiguous range of keys: the block is one piece of the curve.
  EXPECT_EQ(cells.back().key - cells.front().key, cells.size() - 1) << dimension << "D";
  for (std::size_t k = 1; k < cells.size(); ++k) {
    int steps = 0;
    for (int d = 0; d < 3; ++d)
      steps += std::abs(static_cast<int>(cells[k].at[static_cast<std::size_t>(d)]) -
                        static_cast<int>(cells[k - 1].at[static_cast<std::size_t>(d)]));
    ASSERT_EQ(steps, 1) << dimension << "D: keys " << cells[k - 1].key << " and " << cells[k].key;
  }
}

TEST(HilbertCurve, IsContinuousIn2d) { expectContinuousCurve(2, 32); }
TEST(HilbertCurve, IsContinuousIn3d) { expectContinuousCurve(3, 16); }

TEST(HilbertCurve, KeysOfParticlesFollowTheirCells) {
  ParticleSet p;
  for (double x : {0.1, 0.9, 0.5})
    p.append({x, 0.25, 0.0}, {0, 0, 0}, 1.0, 1.0, 0.0, 0.1, 0);
  KeyBox box;
  box.hi = {1.0, 1.0, 1.0};
  const std::vector<std::uint64_t> keys = hilbertKeys(p, p.numReal, box, 1);
  // In 1D the key is the position itself, scaled to 63 bits.
  EXPECT_LT(keys[0], keys[2]);
  EXPECT_LT(keys[2], keys[1]);
  // A position outside the box takes the key of the nearest face's cell.
  p.x[0][0] = -3.0;
  EXPECT_EQ(hilbertKeys(p, 1, box, 1)[0], 0u);
}

TEST(Decomposition, OneRankOwnsEveryKey) {
  SerialCommunicator one;
  const std::vector<std::uint64_t> keys{5, 1, 9}, weights{1, 1, 1};
  Decomposition d;
  d.splitters = balancedSplitters(keys, weights, one);
  ASSERT_EQ(d.splitters.size(), 2u);
  for (std::uint64_t k : {0ull, 7ull, ~0ull}) EXPECT_EQ(d.owner(k), 0);
}

}  // namespace
}  // namespace ejecta
