// The run summary's typed parts and their one serialisation into summary.json's extras
// (sim/run/summary.hpp, sim/run/gauge_summary.hpp, sim/run/energy_ledger.hpp,
// fields/crater_summary.hpp): the checked readers refuse a missing key or a wrong type instead of
// reading 0, and each part writes the keys docs/output_format.md documents.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "fields/crater_summary.hpp"
#include "sim/run/energy_ledger.hpp"
#include "sim/run/gauge_summary.hpp"
#include "sim/run/summary.hpp"

namespace ejecta {
namespace {

std::vector<std::string> keys(const RunSummary& s) {
  std::vector<std::string> out;
  for (const auto& [k, v] : s.extras) out.push_back(k);
  return out;
}

TEST(RunSummaryExtras, CheckedReadersThrowOnAMissingKeyOrAnotherType) {
  RunSummary s;
  s.extras = {{"depth_m", 2.5}, {"steps", std::int64_t{7}}, {"found", true},
              {"note", std::string("ok")}, {"depth_m", 3.5}};
  EXPECT_TRUE(s.has("depth_m"));
  EXPECT_FALSE(s.has("depht_m"));
  EXPECT_EQ(s.number("depth_m"), 3.5);  // the later duplicate, as summary.json keeps it
  EXPECT_EQ(s.integer("steps"), 7);
  EXPECT_TRUE(s.flag("found"));
  EXPECT_EQ(s.text("note"), "ok");
  try {
    s.number("depht_m");
    ADD_FAILURE() << "a mistyped key read as a number";
  } catch (const std::out_of_range& e) {
    EXPECT_NE(std::string(e.what()).find("'depht_m'"), std::string::npos) << e.what();
  }
  EXPECT_THROW(s.number("steps"), std::out_of_range);  // an integer is not a double
  EXPECT_THROW(s.text("found"), std::out_of_range);
  EXPECT_THROW(s.flag("note"), std::out_of_range);
  EXPECT_THROW(s.integer("depth_m"), std::out_of_range);
}

TEST(GaugeSummaries, PulsesFromTheHistoryAndTheirKeys) {
  GaugePressures h;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int k = 0; k < 200; ++k) h.time.push_back(k * 1e-6);
  h.names = {"near", "never", "flat"};
  h.pressure.resize(3);
  const double arrival = h.time[20];
  for (double t : h.time) {
    // 1 bar ambient, then from 20 us a pulse of 1 MPa over it decaying with theta = 30 us.
    h.pressure[0].push_back(t < arrival ? 1e5 : 1e5 + 1e6 * std::exp(-(t - arrival) / 30e-6));
    h.pressure[1].push_back(nan);  // no particle ever reached it
    h.pressure[2].push_back(1e5);  // nothing arrived
  }
  const std::vector<GaugeSummary> g = gaugeSummaries(h);
  ASSERT_EQ(g.size(), 2u);
  EXPECT_EQ(g[0].name, "near");
  EXPECT_EQ(g[0].peakPressure, 1.1e6);
  EXPECT_EQ(g[0].peakTime, arrival);
  ASSERT_TRUE(g[0].decayTime && g[0].decayFit && g[0].arrival);
  EXPECT_NEAR(*g[0].decayTime, 30e-6, 0.1e-6);
  EXPECT_FALSE(g[0].decayNote);
  EXPECT_EQ(g[1].name, "flat");
  EXPECT_FALSE(g[1].arrival);  // no rise over the ambient: no pulse to measure

  RunSummary s;
  addToSummary(g, s);
  EXPECT_EQ(keys(s), (std::vector<std::string>{"gauge_near_peak_pressure_Pa",
                                               "gauge_near_peak_time_s", "gauge_near_arrival_s",
                                               "gauge_near_decay_time_s", "gauge_near_decay_fit_s",
                                               "gauge_flat_peak_pressure_Pa",
                                               "gauge_flat_peak_time_s"}));
  EXPECT_EQ(s.number("gauge_near_decay_time_s"), *g[0].decayTime);
}

TEST(CraterSummaries, PlanarAndAxisymmetricKeys) {
  fields::CraterMetrics m;
  m.found = true;
  m.depth = 0.1;
  m.apparentDiameter = 0.4;
  m.rimDiameter = 0.5;
  m.rimHeight = 0.02;
  m.volume = 0.003;
  m.excavatedMass = 8.0;
  m.elongation = 1.1;
  RunSummary rz, planar, failed;
  fields::addToSummary(fields::craterSummary(m, false), rz);
  fields::addToSummary(fields::craterSummary(m, true), planar);
  fields::addToSummary(fields::craterFailure("crater measurement failed: no target"), failed);
  EXPECT_EQ(keys(rz), (std::vector<std::string>{
                          "crater_found", "crater_depth_m", "crater_apparent_diameter_m",
                          "crater_rim_diameter_m", "crater_rim_height_m", "crater_volume_m3",
                          "crater_excavated_mass_kg", "crater_elongation"}));
  EXPECT_EQ(rz.number("crater_volume_m3"), 0.003);
  EXPECT_EQ(planar.number("crater_area_m2"), 0.003);
  EXPECT_EQ(planar.number("crater_excavated_mass_kg_per_m"), 8.0);
  EXPECT_FALSE(planar.has("crater_elongation"));
  EXPECT_EQ(keys(failed), (std::vector<std::string>{"crater_found", "crater_note"}));
  EXPECT_FALSE(failed.flag("crater_found"));
}

TEST(LedgerSummaries, ADelayedDepositThatFiredAndOneThatDidNot) {
  LedgerSummary l;
  l.materials.push_back({"granite", 0.0, 0.0, 5.0, 6.0});
  LedgerSummary::Source src;
  src.yield = 4.184e12;
  src.yieldKt = 1.0;
  src.dimension = 2;
  DepositFiring f;
  f.time = 1e-3;
  f.step = 42;
  f.point = {0.0, 3.0, 0.0};
  src.deposits.push_back({"deposit_late", true, f});
  src.deposits.push_back({"deposit_never", true, std::nullopt});
  src.deposits.push_back({"deposit_now", false, std::nullopt});
  src.targetShareOfYield = 0.2;
  src.depthOfBurst = 1.5;
  src.scaledDepthOfBurst = 1.5;
  l.source = src;
  RunSummary s;
  addToSummary(l, s);
  EXPECT_EQ(keys(s), (std::vector<std::string>{
                         "energy_granite_kinetic_initial_J", "energy_granite_internal_initial_J",
                         "energy_granite_kinetic_J", "energy_granite_internal_J", "yield_J",
                         "yield_kt", "deposit_late_fired", "deposit_late_fired_time_s",
                         "deposit_late_fired_step", "deposit_late_point_x_m",
                         "deposit_late_point_y_m", "deposit_never_fired", "deposit_now_fired",
                         "deposit_now_fired_time_s", "target_share_of_yield", "depth_of_burst_m",
                         "scaled_depth_of_burst_m_per_kt3"}));
  EXPECT_TRUE(s.flag("deposit_late_fired"));
  EXPECT_FALSE(s.flag("deposit_never_fired"));
  EXPECT_TRUE(s.flag("deposit_now_fired"));
  EXPECT_EQ(s.integer("deposit_late_fired_step"), 42);
  EXPECT_EQ(s.number("deposit_late_point_y_m"), 3.0);
}

}  // namespace
}  // namespace ejecta
