// Grid convergence (sim/verify/grid_convergence, issue 23): the observed order, Richardson's
// extrapolation and the GCI against Celik et al. (2008)'s worked example and against sequences
// made from a known power of h, with the cases the procedure flags or refuses.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/verify/grid_convergence.hpp"

namespace ejecta::verify {
namespace {

TEST(GridConvergence, ReproducesCelikEtAl2008TableOne) {
  // Celik et al. (2008), J. Fluids Eng. 130, 078001, Table 1, first column: N = 18000, 8000,
  // 4500 cells (h ~ N^(-1/2): r21 = 1.5, r32 = 1.333), phi = 6.063, 5.972, 5.863; published
  // p = 1.53, phi_ext = 6.1685, e_a = 1.5%, e_ext = 1.71%, GCI_fine = 2.17% (rounded as printed).
  const GridConvergence g = gridConvergence({1 / std::sqrt(18000.0), 1 / std::sqrt(8000.0), 1 / std::sqrt(4500.0)},
                                            {6.063, 5.972, 5.863});
  ASSERT_TRUE(g.valid) << g.note;
  EXPECT_NEAR(g.order, 1.53, 0.005);
  EXPECT_NEAR(g.extrapolated, 6.1685, 0.00005);
  EXPECT_NEAR(g.relativeChange, 0.015, 0.0005);
  EXPECT_NEAR(g.extrapolatedError, 0.0171, 0.00005);
  EXPECT_NEAR(g.gci, 0.0217, 0.00005);
  EXPECT_FALSE(g.oscillatory);
}

TEST(GridConvergence, RecoversAKnownPowerOfTheSpacing) {
  // phi = 2 + 0.5 h^2 at a constant ratio, and phi = 1 - 3 h^1.3 at unequal ratios (the fixed
  // point's q term): the order and the limit to round-off, in any order of the inputs.
  const GridConvergence a = gridConvergence({2.25, 1.0, 1.5}, {2 + 0.5 * 2.25 * 2.25, 2.5, 2 + 0.5 * 2.25});
  ASSERT_TRUE(a.valid);
  EXPECT_NEAR(a.order, 2.0, 1e-10);
  EXPECT_NEAR(a.extrapolated, 2.0, 1e-12);
  // The GCI bounds the finest value's error: 0.5 against 1.25 x (0.625/2.5)/(1.5^2 - 1) x 2.5.
  EXPECT_NEAR(a.uncertainty, 1.25 * 0.625 / 1.25, 1e-12);
  EXPECT_GE(a.uncertainty, 0.5);
  auto phi = [](double h) { return 1.0 - 3.0 * std::pow(h, 1.3); };
  const GridConvergence b = gridConvergence({0.1, 0.14, 0.2}, {phi(0.1), phi(0.14), phi(0.2)});
  ASSERT_TRUE(b.valid) << b.note;
  EXPECT_NEAR(b.order, 1.3, 1e-9);
  EXPECT_NEAR(b.extrapolated, 1.0, 1e-11);
  // Four levels: the three finest are used.
  const GridConvergence c = gridConvergence({0.1, 0.14, 0.2, 0.3}, {phi(0.1), phi(0.14), phi(0.2), 42.0});
  EXPECT_NEAR(c.order, 1.3, 1e-9);
}

TEST(GridConvergence, FlagsOscillationAndRefusesWhatHasNoOrder) {
  const GridConvergence osc = gridConvergence({1.0, 2.0, 4.0}, {1.0, 1.1, 0.95});
  EXPECT_TRUE(osc.oscillatory);
  EXPECT_NE(osc.note.find("oscillatory"), std::string::npos);
  const GridConvergence flat = gridConvergence({1.0, 2.0, 4.0}, {3.0, 3.0, 3.5});
  EXPECT_FALSE(flat.valid);
  EXPECT_FALSE(flat.note.empty());
  EXPECT_THROW(gridConvergence({1.0, 2.0}, {1.0, 2.0}), std::invalid_argument);
  EXPECT_THROW(gridConvergence({1.0, 1.0, 2.0}, {1.0, 2.0, 3.0}), std::invalid_argument);
  EXPECT_THROW(gridConvergence({1.0, 2.0, -4.0}, {1.0, 2.0, 3.0}), std::invalid_argument);
  EXPECT_THROW(gridConvergence({1.0, 2.0, 4.0}, {1.0, 2.0}), std::invalid_argument);
}

}  // namespace
}  // namespace ejecta::verify
