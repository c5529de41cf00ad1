// The energy ledger (sim/energy_ledger, issue 3 and 4): per-material kinetic and internal energy
// in energy.csv every step and in summary.json, and for an impact the share of the impactor's
// kinetic energy the target holds. The per-material sums must add up to the run's totals, and
// the t = 0 partition must survive a restart.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "sim/state/conservation.hpp"
#include "sim/run/energy_ledger.hpp"
#include "sim/run/run.hpp"
#include "sim/io/snapshot.hpp"
#include "tests/support/tiny_impact.hpp"

namespace fs = std::filesystem;

namespace ejecta {
namespace {

// The shared tiny impact, with a material name that needs escaping in the ledger's keys.
const std::string kImpact = [] {
  test::TinyImpact o;
  o.tEnd = "40 us";
  o.snapshotInterval = "20 us";
  o.impactorMaterial = "Al 2024";
  return test::tinyImpactScene(o);
}();

TEST(EnergyLedger, GroupsAndKeys) {
  const Scene scene = parseScene(kImpact, "ledger.toml");
  const LedgerGroups g = ledgerGroups(scene);
  EXPECT_EQ(g.impactor, std::vector<int>{1});
  EXPECT_EQ(g.target, std::vector<int>{0});
  EXPECT_EQ(ledgerKey("Al 2024"), "Al_2024");
  EXPECT_EQ(ledgerKey("rubble-crust_2"), "rubble-crust_2");
}

std::vector<std::vector<double>> readCsv(const fs::path& path, std::vector<std::string>& header) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::stringstream h(line);
  header.clear();
  for (std::string cell; std::getline(h, cell, ',');) header.push_back(cell);
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::stringstream r(line);
    std::vector<double> row;
    for (std::string cell; std::getline(r, cell, ',');) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

TEST(EnergyLedger, ImpactRunPartitionAddsUpAndSurvivesRestart) {
  const fs::path dir = fs::temp_directory_path() / ("ejecta_ledger_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  RunOptions options;
  options.outDir = dir.string();
  options.threads = 2;
  options.sceneSource = kImpact;
  const RunOutcome r = runScene(parseScene(kImpact, "ledger.toml"), options);
  ASSERT_TRUE(r.ok) << r.error;

  std::vector<std::string> header;
  const auto rows = readCsv(dir / "energy.csv", header);
  ASSERT_EQ(header.size(), 15u);
  EXPECT_EQ(header[10], "granite_kinetic_J");
  EXPECT_EQ(header[13], "Al_2024_internal_J");
  EXPECT_EQ(header[14], "target_share");
  ASSERT_GT(rows.size(), 10u);
  for (const auto& row : rows) {
    // The per-material columns are the same sums split by material: equal to rounding of the
    // 12 printed digits.
    EXPECT_NEAR(row[10] + row[12], row[3], 1e-10 * row[5]);
    EXPECT_NEAR(row[11] + row[13], row[4], 1e-10 * row[5]);
  }

  std::ifstream in(dir / "summary.json");
  const nlohmann::json x = nlohmann::json::parse(in)["extras"];
  const double ke0 = x["impactor_kinetic_energy_J"].get<double>();
  // The impactor's kinetic energy is 1/2 M v^2 of the aluminium as built (snapshot 0).
  SnapshotInfo first;
  const ParticleSet p0 = readSnapshot((dir / "snapshots" / "snap_0000.h5").string(), first);
  double aluminium = 0.0;
  for (std::size_t i = 0; i < p0.numReal; ++i)
    if (p0.material[i] == 1) aluminium += p0.mass[i];
  EXPECT_NEAR(ke0, 0.5 * aluminium * 3000.0 * 3000.0, 1e-9 * ke0);
  EXPECT_DOUBLE_EQ(x["energy_Al_2024_kinetic_initial_J"].get<double>(), ke0);
  EXPECT_DOUBLE_EQ(x["energy_granite_kinetic_initial_J"].get<double>(), 0.0);
  const double gain = x["target_kinetic_gain_J"].get<double>() + x["target_internal_gain_J"].get<double>();
  EXPECT_NEAR(x["target_share_of_impactor_energy"].get<double>(), gain / ke0, 1e-12);
  // energy.csv's target_share column is the same share over time: 0 at t = 0, the summary's
  // value at the end (to the 12 printed digits).
  EXPECT_DOUBLE_EQ(rows.front()[14], 0.0);
  EXPECT_NEAR(rows.back()[14], gain / ke0, 1e-10);
  // 40 us after a 3 km/s contact the target has taken a large share of the energy, and cannot
  // have more than all of it (energy error 2e-4).
  EXPECT_GT(gain / ke0, 0.2);
  EXPECT_LT(gain / ke0, 1.0);
  // The typed partition the run hands back is what summary.json holds.
  ASSERT_TRUE(r.ledger.impact.has_value());
  EXPECT_FALSE(r.ledger.source.has_value());  // no deposit, no detonation
  EXPECT_EQ(r.ledger.impact->impactorKinetic, ke0);
  EXPECT_EQ(r.ledger.impact->targetKineticGain, x["target_kinetic_gain_J"].get<double>());
  ASSERT_TRUE(r.ledger.impact->targetShareOfImpactorEnergy.has_value());
  EXPECT_EQ(*r.ledger.impact->targetShareOfImpactorEnergy,
            x["target_share_of_impactor_energy"].get<double>());
  ASSERT_EQ(r.ledger.materials.size(), 2u);
  EXPECT_EQ(r.ledger.materials[1].key, "Al_2024");
  EXPECT_EQ(r.ledger.materials[1].kinetic, x["energy_Al_2024_kinetic_J"].get<double>());

  // The t = 0 partition travels in every snapshot, so a restart reports the same reference.
  SnapshotInfo info;
  readSnapshot((dir / "snapshots" / "snap_0001.h5").string(), info);
  ASSERT_EQ(info.initialMaterialKinetic.size(), 2u);
  EXPECT_DOUBLE_EQ(info.initialMaterialKinetic[1], x["energy_Al_2024_kinetic_initial_J"].get<double>());
  EXPECT_DOUBLE_EQ(info.initialMaterialInternal[0], 0.0);
  fs::remove_all(dir);
}

TEST(EnergyLedger, PerMaterialTotalsSumToTheTotals) {
  ParticleSet p;
  p.append({0, 0, 0}, {1, 2, 0}, 2.0, 1.0, 10.0, 0.1, 0);
  p.append({1, 0, 0}, {0, 0, 3}, 3.0, 1.0, 20.0, 0.1, 1);
  p.append({2, 0, 0}, {1, 0, 0}, 1.0, 1.0, 5.0, 0.1, 1);
  p.numReal = p.size();
  const ConservedTotals all = conservedTotals(p);
  const std::vector<ConservedTotals> by = conservedTotalsByMaterial(p, 2);
  EXPECT_DOUBLE_EQ(by[0].kinetic, 5.0);   // 1/2 * 2 * (1 + 4)
  EXPECT_DOUBLE_EQ(by[1].kinetic, 14.0);  // 1/2 * 3 * 9 + 1/2 * 1 * 1
  EXPECT_DOUBLE_EQ(by[0].internal + by[1].internal, all.internal);
  EXPECT_DOUBLE_EQ(by[0].kinetic + by[1].kinetic, all.kinetic);
}

}  // namespace
}  // namespace ejecta
