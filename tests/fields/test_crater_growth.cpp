// Whether a crater was still growing when its run stopped (fields/crater_growth.hpp): from the
// rows crater_history.csv holds, its volume at the end against the last output at or before
// 80% of the run.
#include <gtest/gtest.h>

#include "fields/crater_growth.hpp"
#include "fields/crater_history.hpp"

namespace ejecta::fields {
namespace {

std::vector<std::string> history(const std::vector<std::pair<double, double>>& timeVolume,
                                 bool planar = false) {
  std::vector<std::string> rows;
  for (const auto& [t, v] : timeVolume) {
    CraterMetrics m;
    m.found = v > 0.0;
    m.volume = v;
    rows.push_back(craterHistoryRow(t, m, planar));
  }
  return rows;
}

TEST(CraterGrowth, AVolumeStillRisingOverTheLastFifthIsGrowing) {
  // Outputs every 10 ms to 100 ms: 80 ms is the comparison point; +10% since then.
  const auto g = craterGrowth(history({{0.0, 0.0}, {0.01, 1.0}, {0.05, 5.0}, {0.08, 10.0},
                                       {0.09, 10.5}, {0.1, 11.0}}));
  ASSERT_TRUE(g);
  EXPECT_DOUBLE_EQ(g->since, 0.08);
  EXPECT_NEAR(g->change, 0.1, 1e-12);
  EXPECT_TRUE(g->growing);
}

TEST(CraterGrowth, LessThanTwoPercentHasStopped) {
  const auto g = craterGrowth(history({{0.02, 9.0}, {0.06, 9.9}, {0.07, 9.95}, {0.1, 10.0}}, true));
  ASSERT_TRUE(g);
  EXPECT_DOUBLE_EQ(g->since, 0.07);  // the last output at or before 0.08 s
  EXPECT_NEAR(g->change, 10.0 / 9.95 - 1.0, 1e-12);
  EXPECT_FALSE(g->growing);
}

TEST(CraterGrowth, NoVerdictWithoutACraterAtBothTimesOrAHistoryReachingBack) {
  EXPECT_FALSE(craterGrowth(history({{0.1, 10.0}})));
  EXPECT_FALSE(craterGrowth(history({{0.09, 9.0}, {0.1, 10.0}})));   // nothing before 80 ms
  EXPECT_FALSE(craterGrowth(history({{0.05, 0.0}, {0.1, 10.0}})));   // none found at 50 ms
  EXPECT_FALSE(craterGrowth({"not,a,row"}));
}

}  // namespace
}  // namespace ejecta::fields
