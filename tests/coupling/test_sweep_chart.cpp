// What sweep.png plots (coupling/sweep_chart.hpp): the x column chosen from the sweep's axes and the
// collected summary values, the tick labels, and when no chart is drawn.
#include <gtest/gtest.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "coupling/sweep_chart.hpp"

namespace ejecta::coupling {
namespace {

using Columns = std::map<std::string, std::vector<std::optional<double>>>;

Columns shares(std::vector<std::optional<double>> share, Columns more = {}) {
  more["target_share_of_yield"] = std::move(share);
  return more;
}

TEST(SweepChart, PlainNumbersAreTheXAxis) {
  const SweepChartChoice c =
      chooseSweepChart({{"sph.eta", {"1.2", "1.5", "2e0"}}}, shares({0.3, 0.31, 0.29}));
  ASSERT_TRUE(c.draw);
  EXPECT_FALSE(c.bars);
  EXPECT_EQ(c.x, "sph.eta");
  EXPECT_EQ(c.y, "target_share_of_yield");
}

TEST(SweepChart, AMoveAlongOneCoordinateChartsAgainstTheDepthOfBurst) {
  const SweepAxis axis{"bodies[0].center",
                       {"[0.0, \"26.53 m\"]", "[0.0, \"29.53 m\"]", "[0.0, \"34.79 m\"]"}};
  // RZ: the scaled depth of burst is reported and preferred.
  SweepChartChoice c = chooseSweepChart(
      {axis}, shares({0.5, 0.3, 0.1}, {{"depth_of_burst_m", {8.47, 5.47, 0.21}},
                                       {"scaled_depth_of_burst_m_per_kt3", {1.8, 1.2, 0.05}}}));
  ASSERT_TRUE(c.draw);
  EXPECT_FALSE(c.bars);
  EXPECT_EQ(c.x, "scaled_depth_of_burst_m_per_kt3");
  // 2D planar: only the depth itself.
  c = chooseSweepChart({axis}, shares({0.5, 0.3, 0.1}, {{"depth_of_burst_m", {8.47, 5.47, 0.21}}}));
  EXPECT_EQ(c.x, "depth_of_burst_m");
  // Two variants at one depth cannot be told apart on that axis: bars.
  c = chooseSweepChart({axis}, shares({0.5, 0.3, 0.1}, {{"depth_of_burst_m", {8.47, 8.47, 0.21}}}));
  EXPECT_TRUE(c.bars);
  // No depth of burst reported: bars.
  c = chooseSweepChart({axis}, shares({0.5, 0.3, 0.1}));
  EXPECT_TRUE(c.bars);
}

TEST(SweepChart, PositionsOnAWallAndQuantitiesAreBars) {
  // Case 1: the device moves in both coordinates: a bar per location, whatever the depths.
  const SweepAxis wall{"bodies[0].center", {"[0.0, \"31.99 m\"]", "[\"0.751 m\", \"32.147 m\"]"}};
  SweepChartChoice c =
      chooseSweepChart({wall}, shares({0.2, 0.3}, {{"depth_of_burst_m", {3.0, 2.8}}}));
  ASSERT_TRUE(c.draw);
  EXPECT_TRUE(c.bars);
  EXPECT_EQ(c.x, "label");
  EXPECT_EQ(c.xlabel, "bodies[0].center");
  // Yields with units are categories too.
  c = chooseSweepChart({{"energy_deposits[0].energy", {"100 kt", "250 kt"}}}, shares({0.2, 0.21}));
  EXPECT_TRUE(c.bars);
}

TEST(SweepChart, ImpactSweepsChartTheImpactorsShare) {
  Columns cols;
  cols["target_share_of_impactor_energy"] = {0.9, 0.92};
  const SweepChartChoice c = chooseSweepChart({{"bodies[0].radius", {"0.5", "1"}}}, cols);
  ASSERT_TRUE(c.draw);
  EXPECT_EQ(c.y, "target_share_of_impactor_energy");
}

TEST(SweepChart, NothingToDrawSaysWhy) {
  SweepChartChoice c = chooseSweepChart({{"sph.eta", {"1.2", "1.5"}}}, {});
  EXPECT_FALSE(c.draw);
  EXPECT_NE(c.why.find("no variant reports a share"), std::string::npos) << c.why;
  c = chooseSweepChart({{"sph.eta", {"1.2", "1.5"}}}, shares({0.3, std::nullopt}));
  EXPECT_FALSE(c.draw);
  EXPECT_NE(c.why.find("did it fail?"), std::string::npos) << c.why;
}

TEST(SweepChart, ValuesAndLabels) {
  EXPECT_EQ(plainNumber(" 2.5 "), 2.5);
  EXPECT_FALSE(plainNumber("2.5 m"));
  EXPECT_FALSE(plainNumber("[1, 2]"));
  EXPECT_FALSE(plainNumber(""));
  const auto parts = vectorComponents("[0.0, \"2 m\", [1, 2]]");
  ASSERT_TRUE(parts);
  ASSERT_EQ(parts->size(), 3u);
  EXPECT_EQ((*parts)[1], "\"2 m\"");
  EXPECT_EQ((*parts)[2], "[1, 2]");
  EXPECT_FALSE(vectorComponents("100 kt"));
  EXPECT_TRUE(vectorComponents("[]")->empty());
  EXPECT_EQ(sweepVariantLabel({"[0.0, \"26.53 m\"]", "100 kt"}), "[0.0, 26.53 m]; 100 kt");
}

// --vary parsing: values split on commas outside brackets and quotes; axes zip.
TEST(SweepAxes, ValuesSplitOutsideBracketsAndQuotes) {
  const SweepAxis a = parseSweepAxis("detonations[0].point = [0.0, \"-2 m\"], [0.0, \"-3 m\"]");
  EXPECT_EQ(a.key, "detonations[0].point");
  EXPECT_EQ(a.values, (std::vector<std::string>{"[0.0, \"-2 m\"]", "[0.0, \"-3 m\"]"}));
  EXPECT_EQ(parseSweepAxis("x=\"1,5 m\",2").values, (std::vector<std::string>{"\"1,5 m\"", "2"}));
  EXPECT_FALSE(splitOutsideBrackets("[1, 2").has_value());
  EXPECT_THROW(parseSweepAxis("x=[1, 2"), std::invalid_argument);
  EXPECT_THROW(parseSweepAxis("x=1,,2"), std::invalid_argument);
  EXPECT_THROW(parseSweepAxis("=1,2"), std::invalid_argument);
  const auto variants = sweepVariants({parseSweepAxis("a=1,2"), parseSweepAxis("b=x,y")});
  ASSERT_EQ(variants.size(), 2u);
  EXPECT_EQ(variants[1], (std::vector<std::string>{"a=2", "b=y"}));
  EXPECT_THROW(sweepVariants({parseSweepAxis("a=1,2"), parseSweepAxis("b=x")}), std::invalid_argument);
}

}  // namespace
}  // namespace ejecta::coupling
