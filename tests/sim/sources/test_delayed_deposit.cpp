// Delayed energy deposits (EnergyDepositSpec::time > 0, issue 4: the follower's burst after the
// impactor): the total energy jumps by exactly the deposit at its time and is conserved after; a
// Sedov blast from a deposit at t0 in gas at rest matches the exact radius at t - t0; the time
// step drops in the step after the deposit; the ledger measures the device's share from the
// target's energy just before it; restarts neither lose nor repeat it; empty regions are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <unistd.h>
#include <variant>

#include "sim/setup/bodies.hpp"
#include "sim/run/energy_ledger.hpp"
#include "sim/exact/sedov.hpp"
#include "sim/solid/materials.hpp"
#include "sim/run/run.hpp"
#include "sim/run/simulation.hpp"

namespace fs = std::filesystem;

namespace ejecta {
namespace {

constexpr double kT0 = 0.05;           // the deposit's time [s]
constexpr double kSedovSpan = 0.12152;  // t - t0 at which the exact shock is at 0.35 m (E = 1 J/m)

// scenes/verification/sedov_2d.toml at `spacing`, with the blast delayed to t0 = 0.05 s: gas at
// rest (P0 = 1e-4 Pa, the strong-shock limit) for 0.05 s, then E = 1 J/m in a Gaussian of width
// `width` at the centre, run to t0 + 0.12152 s, when the exact shock is at R = 0.35 m.
std::string sedovScene(double spacing, double width, const std::string& snapshotInterval,
                       const std::string& center = "[0.0, 0.0]") {
  std::ostringstream s;
  s << R"(
[scene]
name = "delayed_sedov"
dimension = "2d"
[domain]
x = { min = -0.5, max = 0.5, boundary = "wall" }
y = { min = -0.5, max = 0.5, boundary = "wall" }
[sph]
kernel = "cubic_spline"
eta = 1.2
[time]
t_end = ")" << kT0 + kSedovSpan << R"( s"
[output]
snapshot_interval = ")" << snapshotInterval << R"("
[[materials]]
name = "gas"
eos = "ideal_gas"
gamma = 1.4
[[bodies]]
name = "ambient"
material = "gas"
shape = "box"
min = [-0.5, -0.5]
max = [0.5, 0.5]
lattice = "hexagonal"
spacing = )" << spacing << R"(
density = 1.0
pressure = 1e-4
[[energy_deposits]]
name = "blast"
energy = "1 J"
time = ")" << kT0 << R"( s"
center = )" << center << R"(
profile = "gaussian"
width = )" << width << "\n";
  return s.str();
}

// `text` with the line starting with `key` replaced by `line`.
std::string replaceLine(std::string text, const std::string& key, const std::string& line) {
  const std::size_t at = text.find("\n" + key) + 1;
  text.replace(at, text.find('\n', at) - at, line);
  return text;
}

std::string tempDir(const std::string& tag) {
  const fs::path dir = fs::temp_directory_path() /
                       ("ejecta_delayed_" + tag + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir.string();
}

double extra(const RunSummary& s, const std::string& key) {
  for (const auto& [k, v] : s.extras)
    if (k == key) {
      if (const double* d = std::get_if<double>(&v)) return *d;
      if (const std::int64_t* i = std::get_if<std::int64_t>(&v)) return static_cast<double>(*i);
      if (const bool* b = std::get_if<bool>(&v)) return *b ? 1.0 : 0.0;
    }
  ADD_FAILURE() << "no summary extra '" << key << "'";
  return std::numeric_limits<double>::quiet_NaN();
}

Simulation makeSimulation(const Scene& scene) {
  MaterialTable materials = MaterialTable::fromScene(scene);
  ParticleSet particles = buildParticles(scene, materials);
  Simulation sim(scene, std::move(particles), std::move(materials), 1);
  sim.initialise();
  return sim;
}

TEST(DelayedDeposit, SceneKeyTimeIsParsedAndChecked) {
  const Scene scene = parseScene(sedovScene(0.04, 0.03, "0.1 s"), "sedov.toml");
  ASSERT_EQ(scene.deposits.size(), 1u);
  EXPECT_DOUBLE_EQ(scene.deposits[0].time, kT0);
  // The particles are built without it: the gas holds only its ambient energy at t = 0.
  const MaterialTable materials = MaterialTable::fromScene(scene);
  const ParticleSet p = buildParticles(scene, materials);
  const double uAmbient = 1e-4 / (0.4 * 1.0);
  for (std::size_t i = 0; i < p.numReal; ++i) ASSERT_NEAR(p.u[i], uAmbient, 1e-15);
  // A deposit at or after t_end would never fire; a negative time is no time.
  for (const std::string bad : {"1 s", "-1 ms"}) {
    std::string text = sedovScene(0.04, 0.03, "0.1 s");
    text = replaceLine(text, "time = ", "time = \"" + bad + "\"");
    try {
      parseScene(text, "bad.toml");
      ADD_FAILURE() << "accepted time = " << bad;
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find("energy_deposits[0]"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("time"), std::string::npos) << e.what();
    }
  }
}

// The jump, the time step and conservation after it, stepping the simulation by hand.
TEST(DelayedDeposit, EnergyJumpsByExactlyTheDepositAndTheStepAfterUsesTheNewTimeStep) {
  const Scene scene = parseScene(sedovScene(0.04, 0.03, "1 s"), "sedov.toml");
  Simulation sim = makeSimulation(scene);
  const double E = 1.0;
  double jump = 0.0;
  while (sim.depositFirings().empty()) {
    const double before = sim.totals().total();
    const double dtPlanned = sim.dtNext();
    const double timeBefore = sim.time();
    sim.step(scene.time.tEnd);
    if (sim.depositFirings().empty()) {
      // Steps are cut to land on the deposit's time, never across it.
      EXPECT_LE(sim.time(), kT0 * (1 + 1e-12));
      continue;
    }
    // It fired at the start of this step, at exactly its time.
    ASSERT_EQ(sim.depositFirings().size(), 1u);
    EXPECT_NEAR(sim.depositFirings()[0].time, kT0, 1e-12 * kT0);
    EXPECT_NEAR(timeBefore, kT0, 1e-12 * kT0);
    // The total jumped by E plus this step's leapfrog error: the first step of a blast, whose
    // error (2.4e-6 E here) is that of the first step of the same blast set off at t = 0
    // (checked below); 1e-5 E bounds it. The jump itself is exact: see the next test.
    jump = sim.totals().total() - before;
    EXPECT_NEAR(jump, E, 1e-5 * E);
    EXPECT_NEAR(sim.delayedEnergyAdded(), E, 0.0);
    // The time step: the gas at rest allowed dt ~ C h / c0 with c0 = sqrt(1.4e-4) = 0.012 m/s;
    // the deposit raises c to ~10 m/s at the centre. The step that fired took the CFL step of
    // the new state (<= C h / c for every particle, c of the state it ends with, which differs
    // from the deposit's by one step's change), not the one planned before it.
    const ParticleSet& p = sim.particles();
    double cfl = std::numeric_limits<double>::max();
    for (std::size_t i = 0; i < p.numReal; ++i) cfl = std::min(cfl, scene.sph.courant * p.h[i] / p.cs[i]);
    EXPECT_LE(sim.lastDt(), 1.05 * cfl);
    EXPECT_LT(sim.lastDt(), dtPlanned / 100.0) << "planned " << dtPlanned;
    RecordProperty("dt_planned_before_s", std::to_string(dtPlanned));
    RecordProperty("dt_after_s", std::to_string(sim.lastDt()));
  }
  // Conserved after it: the run's total stays at E0 + E. The Sedov runs' energy error is a few
  // 1e-4 at these resolutions (docs/verification.md); 2e-3 of E bounds it with room to spare.
  const double afterJump = sim.totals().total();
  for (int k = 0; k < 400 && sim.time() < kT0 + 0.03; ++k) sim.step(scene.time.tEnd);
  EXPECT_NEAR(sim.totals().total(), afterJump, 2e-3 * E);
  EXPECT_EQ(sim.depositFirings().size(), 1u);  // fires once
  // The same blast at t = 0: its first step changes the total by the same leapfrog error. The gas
  // before t0 has moved only by the walls' 1e-4 Pa, so the two first steps agree closely.
  const Scene zeroScene = parseScene(replaceLine(sedovScene(0.04, 0.03, "1 s"), "time = ", "time = \"0 s\""),
                                     "sedov0.toml");
  Simulation zero = makeSimulation(zeroScene);
  const double zeroBefore = zero.totals().total();
  zero.step(zeroScene.time.tEnd);
  EXPECT_NEAR(jump - E, zero.totals().total() - zeroBefore, 1e-3 * std::abs(jump - E));
  RecordProperty("first_step_error_delayed", std::to_string(jump - E));
  RecordProperty("first_step_error_at_zero", std::to_string(zero.totals().total() - zeroBefore));
}

// applyDeposit adds exactly E (sum m du), over the particles in the region at that moment, and
// returns the centroid of what it added.
TEST(DelayedDeposit, ApplyDepositAddsExactlyTheEnergyWhereTheParticlesAreNow) {
  const Scene scene = parseScene(sedovScene(0.04, 0.03, "1 s", "[0.1, -0.2]"), "sedov.toml");
  const MaterialTable materials = MaterialTable::fromScene(scene);
  ParticleSet p = buildParticles(scene, materials);
  // Move every particle by (0.05, 0): the deposit follows the particles, not their start.
  for (std::size_t i = 0; i < p.numReal; ++i) p.x[0][i] += 0.05;
  const double before = conservedTotals(p).total();
  const std::array<double, 3> c = applyDeposit(scene, 0, bodyFirstIds(scene, materials), p, kT0);
  // Sum of ~100 terms m du: rounding at 1e-14 of E.
  EXPECT_NEAR(conservedTotals(p).total() - before, 1.0, 1e-12);
  EXPECT_NEAR(c[0], 0.1, 0.01);  // a Gaussian of 0.03 m over a 0.04 m lattice: within a quarter
  EXPECT_NEAR(c[1], -0.2, 0.01);  // spacing of its centre
}

// A Sedov blast set off at t0 in gas at rest: its shock is at the exact radius R(t - t0). The same
// blast at t = 0 run for t - t0 gives the same state (the gas before t0 stays at rest).
TEST(DelayedDeposit, SedovBlastFromADelayedDepositMatchesTheExactRadiusAtTMinusT0) {
  const double spacing = 0.02, width = 0.03;
  const Scene scene = parseScene(sedovScene(spacing, width, "1 s"), "sedov.toml");
  RunOptions options;
  options.threads = 1;
  Simulation sim = [&] {
    MaterialTable materials = MaterialTable::fromScene(scene);
    ParticleSet particles = buildParticles(scene, materials);
    return Simulation(scene, std::move(particles), std::move(materials), 1);
  }();
  const RunOutcome out = runSimulation(sim, options);
  ASSERT_TRUE(out.ok) << out.error;
  EXPECT_NEAR(extra(out.summary, "deposit_blast_fired_time_s"), kT0, 1e-12 * kT0);
  // The relative energy error counts the deposit as a source: measured against E0 + E.
  EXPECT_LT(std::abs(out.summary.energy.relativeError), 2e-3);
  RecordProperty("energy_error", std::to_string(out.summary.energy.relativeError));

  const exact::SedovSolution exactBlast(2, 1.4, 1.0, 1.0);
  const double R = exactBlast.shockRadius(sim.time() - kT0);
  EXPECT_NEAR(R, 0.35, 1e-3);
  // Shock radius: the peak of the mass-weighted density binned in r (bins of one spacing).
  const ParticleSet& p = sim.particles();
  const int bins = 30;
  std::vector<double> rho(bins, 0.0), mass(bins, 0.0);
  for (std::size_t i = 0; i < p.numReal; ++i) {
    const int b = static_cast<int>(std::hypot(p.x[0][i], p.x[1][i]) / spacing);
    if (b < bins) { rho[b] += p.mass[i] * p.rho[i]; mass[b] += p.mass[i]; }
  }
  int peak = 0;
  for (int b = 0; b < bins; ++b) {
    if (mass[b] > 0) rho[b] /= mass[b];
    if (rho[b] > rho[peak]) peak = b;
  }
  const double rPeak = (peak + 0.5) * spacing;
  // At 17 spacings to the shock, SPH smears it over ~2h = 2.4 spacings and the bins quantise it
  // to a spacing (5.7% of R); measured: 0.3500 m against 0.3500 m. 6% of R allows one bin. A
  // blast set off at t = 0 instead of t0 would be at R(t) = 0.416 m (+19%), none at all at 0.
  EXPECT_NEAR(rPeak, R, 0.06 * R) << "peak at " << rPeak << " m, exact " << R << " m";
  RecordProperty("shock_radius_m", std::to_string(rPeak));
  RecordProperty("shock_radius_exact_m", std::to_string(R));

  // The same blast at t = 0 for t - t0: the delayed run's particles end where its particles do.
  std::string atZero = sedovScene(spacing, width, "1 s");
  atZero = replaceLine(atZero, "time = ", "time = \"0 s\"");
  atZero = replaceLine(atZero, "t_end = ", "t_end = \"" + std::to_string(kSedovSpan) + " s\"");
  const Scene zeroScene = parseScene(atZero, "sedov0.toml");
  ASSERT_NEAR(zeroScene.time.tEnd, kSedovSpan, 1e-12);
  Simulation zero = [&] {
    MaterialTable materials = MaterialTable::fromScene(zeroScene);
    ParticleSet particles = buildParticles(zeroScene, materials);
    return Simulation(zeroScene, std::move(particles), std::move(materials), 1);
  }();
  ASSERT_TRUE(runSimulation(zero, options).ok);
  const ConservedTotals a = sim.totals(), b = zero.totals();
  // Before t0 the gas moves only by the ambient pressure's imbalance at the walls (1e-4 Pa
  // against the blast's ~1 Pa), so the kinetic energies agree to a fraction of a percent.
  EXPECT_NEAR(a.kinetic, b.kinetic, 5e-3 * b.kinetic);
  RecordProperty("kinetic_delayed_over_at_zero", std::to_string(a.kinetic / b.kinetic));
}

// The device's share is measured from the target's energy just before the deposit, so what an
// impactor gave the target first is not counted as the device's.
std::string impactThenBurst(const std::string& tEnd, const std::string& interval) {
  return R"(
[scene]
name = "impact_then_burst"
dimension = "2d"
[sph]
density = "continuity"
form = "interface"
[time]
t_end = ")" + tEnd + R"("
[output]
snapshot_interval = ")" + interval + R"("
[[materials]]
name = "granite"
eos = "tillotson"
library = "granite"
[[materials]]
name = "aluminium"
eos = "mie_gruneisen"
library = "Al-2024"
[[materials]]
name = "device"
eos = "tillotson"
library = "granite"
[[bodies]]
name = "impactor"
material = "aluminium"
shape = "sphere"
center = [0.0, "0.06 m"]
radius = "0.05 m"
spacing = "0.02 m"
density = "2785 kg/m^3"
pressure = 0.0
velocity = [0.0, "-3 km/s"]
[[bodies]]
name = "device"
material = "device"
shape = "sphere"
center = [0.0, "0.36 m"]
radius = "0.06 m"
spacing = "0.02 m"
density = "2680 kg/m^3"
pressure = 0.0
velocity = [0.0, "-3 km/s"]
[[bodies]]
name = "target"
material = "granite"
shape = "box"
min = ["-0.5 m", "-0.4 m"]
max = ["0.5 m", 0.0]
spacing = "0.02 m"
density = "2680 kg/m^3"
pressure = 0.0
[[energy_deposits]]
name = "yield"
body = "device"
energy = "1e9 J"
time = "60 us"
)";
}

TEST(DelayedDeposit, LedgerMeasuresTheDevicesShareFromJustBeforeItFired) {
  const Scene scene = parseScene(impactThenBurst("100 us", "50 us"), "impact.toml");
  // The device flies in behind the impactor: it is the explosive, not an impactor.
  const LedgerGroups g = ledgerGroups(scene);
  EXPECT_EQ(g.impactor, std::vector<int>{1});
  EXPECT_EQ(g.explosive, std::vector<int>{2});
  EXPECT_EQ(g.target, std::vector<int>{0});
  RunOptions options;
  options.outDir = tempDir("ledger");
  options.threads = 1;
  const RunOutcome out = runScene(scene, options);
  ASSERT_TRUE(out.ok) << out.error;
  // The device moved 0.18 m in 60 us: it fired 0.12 m above the surface, where it then was.
  EXPECT_NEAR(extra(out.summary, "deposit_yield_fired_time_s"), 60e-6, 1e-15);
  EXPECT_NEAR(extra(out.summary, "deposit_yield_point_y_m"), 0.36 - 0.18, 0.01);
  EXPECT_NEAR(extra(out.summary, "depth_of_burst_m"), -0.18, 0.01);
  // energy.csv: the target's energy at the last row before the deposit (the row of the step
  // that ended at 60 us) is the reference; the summary's share is measured from it.
  std::ifstream csv(fs::path(options.outDir) / "energy.csv");
  std::string line;
  std::getline(csv, line);
  auto cells = [](const std::string& row) {
    std::vector<double> v;
    std::stringstream in(row);
    for (std::string c; std::getline(in, c, ',');) v.push_back(std::stod(c));
    return v;
  };
  // Columns: step,time,dt,K,U,total,error,px,py,pz, then per material K,U, then target_share.
  std::vector<double> before, last;
  while (std::getline(csv, line)) {
    const std::vector<double> v = cells(line);
    if (v[1] <= 60e-6 * (1 + 1e-12)) before = v;
    last = v;
  }
  ASSERT_FALSE(before.empty());
  const double targetBefore = before[10] + before[11];
  const double targetAtStart = extra(out.summary, "energy_granite_kinetic_initial_J") +
                               extra(out.summary, "energy_granite_internal_initial_J");
  EXPECT_NEAR(extra(out.summary, "target_energy_before_source_J"), targetBefore, 1e-9 * targetBefore);
  // By then the impact has given the target a real part of the impactor's energy.
  EXPECT_GT(targetBefore - targetAtStart, 1e3);
  const double targetNow = last[10] + last[11];
  const double share = extra(out.summary, "target_share_of_yield");
  EXPECT_NEAR(share, (targetNow - targetBefore) / 1e9, 1e-9);
  EXPECT_NEAR(last.back(), share, 1e-9);  // the energy.csv column agrees
  // The column is 0 before the deposit (nothing to share yet).
  EXPECT_EQ(before.back(), 0.0);
  // The run's error counts the deposit as a source: a few 1e-4 at 5 particles across the device.
  EXPECT_LT(std::abs(out.summary.energy.relativeError), 5e-3);
  RecordProperty("target_share_of_yield", std::to_string(share));
  RecordProperty("energy_error", std::to_string(out.summary.energy.relativeError));
  fs::remove_all(options.outDir);
}

// Restarts: from a snapshot before the deposit's time the restarted run fires it; from one
// after, it does not fire it again. Either way it ends where the uninterrupted run ends.
TEST(DelayedDeposit, RestartBeforeTheDepositFiresItAfterDoesNotRepeatIt) {
  const std::string text = impactThenBurst("100 us", "40 us");  // snapshots at 0, 40, 80, 100 us
  const Scene scene = parseScene(text, "impact.toml");
  RunOptions options;
  options.outDir = tempDir("restart_full");
  options.threads = 1;
  options.sceneSource = text;
  const RunOutcome full = runScene(scene, options);
  ASSERT_TRUE(full.ok) << full.error;
  const double shareFull = extra(full.summary, "target_share_of_yield");
  for (const int keep : {1, 2}) {  // restart from snap 1 (40 us, before) or snap 2 (80 us, after)
    SCOPED_TRACE("restart from snapshot " + std::to_string(keep));
    const fs::path dir = tempDir("restart_" + std::to_string(keep));
    fs::copy(options.outDir, dir, fs::copy_options::recursive);
    for (int k = keep + 1; k <= 3; ++k) {
      char name[32];
      std::snprintf(name, sizeof name, "snap_%04d.h5", k);
      fs::remove(dir / "snapshots" / name);
    }
    RunOptions again;
    again.threads = 1;
    const RunOutcome resumed = restartRun(dir.string(), again);
    ASSERT_TRUE(resumed.ok) << resumed.error;
    EXPECT_NEAR(extra(resumed.summary, "deposit_yield_fired_time_s"), 60e-6, 1e-15);
    EXPECT_EQ(extra(resumed.summary, "deposit_yield_fired_step"),
              extra(full.summary, "deposit_yield_fired_step"));
    // Restarts are bit for bit: the same final energy (a second deposit would add 1e9 J).
    EXPECT_EQ(resumed.summary.energy.final, full.summary.energy.final);
    EXPECT_EQ(extra(resumed.summary, "target_share_of_yield"), shareFull);
    fs::remove_all(dir);
  }
  fs::remove_all(options.outDir);
}

TEST(DelayedDeposit, EmptyRegionAtItsTimeIsASceneError) {
  // A deposit centred outside the gas: nothing there at t0. The message names the file, the key,
  // the scene, the time and the region.
  std::string text = sedovScene(0.04, 0.03, "1 s", "[0.0, 0.7]");
  text.replace(text.find("profile = \"gaussian\""), 20, "radius = 0.1");
  text.replace(text.find("width = 0.03"), 12, "");
  const Scene empty = parseScene(text, "empty.toml");
  Simulation sim = makeSimulation(empty);
  try {
    while (sim.time() < 2 * kT0) sim.step(empty.time.tEnd);
    ADD_FAILURE() << "an empty region fired";
  } catch (const SceneError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("empty.toml"), std::string::npos) << m;
    EXPECT_NE(m.find("energy_deposits[0]"), std::string::npos) << m;
    EXPECT_NE(m.find("delayed_sedov"), std::string::npos) << m;
    EXPECT_NE(m.find("at time 0.05 s"), std::string::npos) << m;
    EXPECT_NE(m.find("radius 0.1 m around (0 m, 0.7 m)"), std::string::npos) << m;
    EXPECT_NE(m.find("empty"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace ejecta

namespace ejecta {
namespace {

// The follower scenes (docs/asteroid_studies.md, "The real crater against the void crater"):
// each variant of the header's sweep parses, builds without the yield (it fires at 3 ms), and
// puts the device, moving at its velocity, at the void study's station when it fires.
TEST(DelayedDeposit, FollowerScenesPutTheDeviceAtItsStationWhenItFires) {
  const std::filesystem::path dir = std::filesystem::path(EJECTA_SOURCE_DIR) / "scenes";
  struct Variant {
    std::string file, center, velocity;
    double stationX, stationY;
  };
  const std::vector<Variant> variants{
      {"case1_2d_follower.toml", "[0.0, \"61.99 m\"]", "", 0.0, 31.99},
      {"case1_2d_follower.toml", "[\"3.671 m\", \"65.226 m\"]", "", 3.671, 35.226},
      {"case2_rz_follower.toml", "[0.0, \"59.53 m\"]", "", 0.0, 29.53},
      {"case2_rz_follower.toml", "[0.0, \"68.53 m\"]", "", 0.0, 38.53},
      {"case2_rz_follower.toml", "[0.0, \"26.53 m\"]", "[0.0, 0.0]", 0.0, 26.53}};
  for (const Variant& v : variants) {
    SCOPED_TRACE(v.file + " " + v.center);
    std::vector<std::string> sets{"bodies[0].center=" + v.center};
    if (!v.velocity.empty()) sets.push_back("bodies[0].velocity=" + v.velocity);
    const Scene s = loadScene((dir / v.file).string(), sets);
    ASSERT_EQ(s.deposits.size(), 1u);
    const EnergyDepositSpec& dep = s.deposits[0];
    EXPECT_DOUBLE_EQ(dep.time, 3e-3);
    EXPECT_EQ(s.bodies.at(static_cast<std::size_t>(dep.body)).name, "device");
    const BodySpec& device = s.bodies[0];
    EXPECT_NEAR(device.shape.center[0] + device.velocity[0] * dep.time, v.stationX, 1e-9);
    EXPECT_NEAR(device.shape.center[1] + device.velocity[1] * dep.time, v.stationY, 1e-9);
    // The follower's kinetic energy is the explosive's, not the impactor's.
    const LedgerGroups g = ledgerGroups(s);
    ASSERT_EQ(g.impactor.size(), 1u);
    EXPECT_EQ(s.materials[static_cast<std::size_t>(g.impactor[0])].name, "aluminium");
    // No yield in the particles at t = 0: Tillotson granite at its reference density, e = 0.
    const MaterialTable materials = MaterialTable::fromScene(s);
    const ParticleSet p = buildParticles(s, materials);
    double internal = 0.0;
    for (std::size_t i = 0; i < p.numReal; ++i) internal += p.mass[i] * p.u[i];
    EXPECT_EQ(internal, 0.0);
  }
}

}  // namespace
}  // namespace ejecta
