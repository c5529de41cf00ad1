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
  // p = 1.53 lies within [0.5, 2] at the default formal order 1: Celik's band.
  EXPECT_TRUE(g.asymptotic);
  EXPECT_EQ(g.basis, UncertaintyBasis::ObservedOrder);
}

TEST(GridConvergence, RecoversAKnownPowerOfTheSpacing) {
  // phi = 2 + 0.5 h^2 at a constant ratio, and phi = 1 - 3 h^1.3 at unequal ratios (the fixed
  // point's q term): the order and the limit to round-off, in any order of the inputs.
  // (A second-order sequence, so a second-order method's: at formal order 1, p = 2 is the edge.)
  const GridConvergence a = gridConvergence({2.25, 1.0, 1.5}, {2 + 0.5 * 2.25 * 2.25, 2.5, 2 + 0.5 * 2.25}, 2.0);
  ASSERT_TRUE(a.valid);
  ASSERT_TRUE(a.asymptotic) << a.note;
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
  EXPECT_FALSE(osc.asymptotic);
  const GridConvergence flat = gridConvergence({1.0, 2.0, 4.0}, {3.0, 3.0, 3.5});
  EXPECT_FALSE(flat.valid);
  EXPECT_FALSE(flat.note.empty());
  EXPECT_EQ(flat.basis, UncertaintyBasis::None);
  EXPECT_EQ(flat.uncertainty, 0.0);
  EXPECT_THROW(gridConvergence({1.0, 2.0}, {1.0, 2.0}), std::invalid_argument);
  EXPECT_THROW(gridConvergence({1.0, 1.0, 2.0}, {1.0, 2.0, 3.0}), std::invalid_argument);
  EXPECT_THROW(gridConvergence({1.0, 2.0, -4.0}, {1.0, 2.0, 3.0}), std::invalid_argument);
  EXPECT_THROW(gridConvergence({1.0, 2.0, 4.0}, {1.0, 2.0}), std::invalid_argument);
  EXPECT_THROW(gridConvergence({1.0, 2.0, 4.0}, {1.0, 2.0, 3.0}, 0.0), std::invalid_argument);
}

TEST(GridConvergence, ChangesThatGrowAreDivergenceNotAnOrder) {
  // Case 1's rim (bench/headline.toml case1_rim, 2026-12-07) at 0.354, 0.25 and 0.177 m: 15.64,
  // 18.05 and 25.13% of the yield. The finer change (7.08 points) is larger than the coarser
  // (2.41) at a constant ratio: no converging power of h does that, though Celik's |ln| gives
  // p = 3.1. No order, and Roache's band at the formal order: 3 x 0.0708 / (sqrt 2 - 1).
  const GridConvergence rim =
      gridConvergence({0.35355, 0.25, 0.1768}, {0.15641239039906552, 0.1804890136184845, 0.25125358394669717});
  EXPECT_FALSE(rim.valid);
  EXPECT_FALSE(rim.asymptotic);
  EXPECT_NE(rim.note.find("monotone divergence"), std::string::npos) << rim.note;
  EXPECT_EQ(rim.basis, UncertaintyBasis::FormalFallback);
  EXPECT_NEAR(rim.uncertainty, 3.0 * (0.25125358394669717 - 0.1804890136184845) / (0.25 / 0.1768 - 1.0), 1e-12);
  // At unequal ratios a converging sequence can have a finer change larger than the coarser:
  // phi = 1 + h at h = 1, 2, 2.2 (changes 1 and 0.2; ln 2 / ln 1.1 = 7.3 > 5). It keeps its order.
  const GridConvergence unequal = gridConvergence({1.0, 2.0, 2.2}, {2.0, 3.0, 3.2});
  ASSERT_TRUE(unequal.valid) << unequal.note;
  EXPECT_NEAR(unequal.order, 1.0, 1e-9);
}

TEST(GridConvergence, AnOrderFasterThanTheMethodTakesRoachesFallbackBand) {
  // phi = 1 + h^4 at h = 1, 2, 4 (2, 17, 257): the order is 4. For a fourth-order method that is
  // the asymptotic range, and Celik's band (1.25 x 7.5 / 15 x 2 = 1.25) holds the error (1).
  const GridConvergence fourth = gridConvergence({1.0, 2.0, 4.0}, {2.0, 17.0, 257.0}, 4.0);
  ASSERT_TRUE(fourth.asymptotic) << fourth.note;
  EXPECT_NEAR(fourth.order, 4.0, 1e-9);
  EXPECT_NEAR(fourth.uncertainty, 1.25, 1e-9);
  // For a first-order method an order of 4 is not credible (above twice 1): no extrapolation is
  // claimed, and the band is Roache's, 3 x |e21| / (r21^1 - 1) = 3 x 15 / 1.
  const GridConvergence first = gridConvergence({1.0, 2.0, 4.0}, {2.0, 17.0, 257.0});
  EXPECT_TRUE(first.valid);
  EXPECT_FALSE(first.asymptotic);
  EXPECT_EQ(first.basis, UncertaintyBasis::FormalFallback);
  EXPECT_DOUBLE_EQ(first.bandOrder, 1.0);
  EXPECT_NEAR(first.uncertainty, 45.0, 1e-9);
  EXPECT_NE(first.note.find("above 2"), std::string::npos) << first.note;
}

TEST(GridConvergence, OscillatingChangesGetABandAtLeastHalfTheirSpread) {
  // EMI 19.0's peak bulge (runs of docs/whipple.md's headline rows, Courant 0.15) at 0.533, 0.4
  // and 0.2 mm: 8.357, 6.463 and 6.723 mm. The changes alternate; Celik's formula finds p = 6.44
  // and a band of 0.004 mm, which the coarser levels belie. Roache's band at order 1 is
  // 3 x 0.26 / (2 - 1) = 0.78 mm; half the spread (Stern et al. 2001) is 0.947 mm: the band.
  const GridConvergence g = gridConvergence({0.5333334e-3, 0.4e-3, 0.2e-3}, {8.357e-3, 6.463e-3, 6.723e-3});
  EXPECT_NEAR(g.order, 6.44, 0.005);
  EXPECT_TRUE(g.oscillatory);
  EXPECT_EQ(g.basis, UncertaintyBasis::FormalFallback);
  EXPECT_NEAR(g.uncertainty, 0.947e-3, 1e-12);
  // The labels say which band it is: the spread's, not Roache's with its factor of safety.
  EXPECT_TRUE(g.bandAtHalfSpread);
  EXPECT_EQ(describeBand(g, 3),
            "half the three finest's spread, wider than the fallback band (order 1, factor of safety 3)");
  // With the spread small, Roache's band governs: 1.0, 1.01, 0.995 at h = 1, 2, 4: 3 x 0.01 / 1.
  const GridConvergence small = gridConvergence({1.0, 2.0, 4.0}, {1.0, 1.01, 0.995});
  EXPECT_NEAR(small.uncertainty, 0.03, 1e-12);
  EXPECT_FALSE(small.bandAtHalfSpread);
  EXPECT_EQ(describeBand(small, 3), "fallback band (order 1, factor of safety 3)");
  // Celik's band in the asymptotic range (phi = 1 + h, order 1) and no band at all.
  EXPECT_EQ(describeBand(gridConvergence({1.0, 2.0, 4.0}, {2.0, 3.0, 5.0}), 3),
            "GCI band (observed order 1, factor of safety 1.25)");
  EXPECT_EQ(describeBand(gridConvergence({1.0, 2.0, 4.0}, {1.0, 1.0, 2.0}), 3), "");
}

TEST(GridConvergence, ASlowerOrderIsNotSpedUpAndNoOrderStillGetsABand) {
  // phi = 1 + h^0.3 at h = 1, 2, 4: p = 0.3, below 0.5. At the formal order 1 the band would be
  // 3 x 0.231 / 1 = 0.69 and miss the finest error (1); at the observed 0.3 it is 3.0 and holds it.
  auto phi = [](double h) { return 1.0 + std::pow(h, 0.3); };
  const GridConvergence slow = gridConvergence({1.0, 2.0, 4.0}, {phi(1.0), phi(2.0), phi(4.0)});
  EXPECT_EQ(slow.basis, UncertaintyBasis::FormalFallback);
  EXPECT_NEAR(slow.bandOrder, 0.3, 1e-9);
  EXPECT_NEAR(slow.uncertainty, 3.0, 1e-9);
  // Equal changes at a constant ratio (p = 0: the values do not follow a power of h): no order,
  // and the band at the formal order, 3 x 1 / (2 - 1).
  const GridConvergence none = gridConvergence({1.0, 2.0, 4.0}, {1.0, 2.0, 3.0});
  EXPECT_FALSE(none.valid);
  EXPECT_EQ(none.basis, UncertaintyBasis::FormalFallback);
  EXPECT_NEAR(none.uncertainty, 3.0, 1e-12);
  // Two equal coarse values leave no order either; the fine change still gives the band.
  const GridConvergence coarse = gridConvergence({1.0, 2.0, 4.0}, {1.0, 1.5, 1.5});
  EXPECT_FALSE(coarse.valid);
  EXPECT_EQ(coarse.basis, UncertaintyBasis::FormalFallback);
  EXPECT_NEAR(coarse.uncertainty, 1.5, 1e-12);
  // A value that is not a number: no order and no band (not a NaN band).
  const GridConvergence nan = gridConvergence({1.0, 2.0, 4.0}, {1.0, std::nan(""), 1.5});
  EXPECT_EQ(nan.basis, UncertaintyBasis::None);
  EXPECT_EQ(nan.uncertainty, 0.0);
  // The names the outputs carry (bench/headline.py matches the fallback's).
  EXPECT_STREQ(uncertaintyBasisName(UncertaintyBasis::FormalFallback), "formal-order fallback");
  EXPECT_STREQ(uncertaintyBasisName(UncertaintyBasis::ObservedOrder), "observed order");
  EXPECT_STREQ(uncertaintyBasisName(UncertaintyBasis::None), "none");
}

}  // namespace
}  // namespace ejecta::verify
