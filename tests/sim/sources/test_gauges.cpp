// Gauges (sim/gauges): the Shepard-normalised SPH value at a fixed point, written every step to
// gauges.csv, with each gauge's peak pressure in the summary.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <variant>

#include "sim/setup/bodies.hpp"
#include "sim/sources/gauges.hpp"
#include "sim/solid/materials.hpp"
#include "sim/run/run.hpp"
#include "sim/run/simulation.hpp"

namespace fs = std::filesystem;

namespace ejecta {
namespace {

std::string gasScene(const std::string& dimension, const std::string& extra) {
  const bool rz = dimension == "rz";
  return std::string(R"(
[scene]
name = "gauge_gas"
dimension = ")") + dimension + R"("
[time]
t_end = "1 ms"
[[materials]]
name = "gas"
eos = "ideal_gas"
gamma = 1.4
[[bodies]]
name = "gas"
material = "gas"
shape = "box"
min = [)" + (rz ? "0.0, -1.0" : "-1.0, -1.0") + R"(]
max = [1.0, 1.0]
spacing = 0.05
density = 1.2
pressure = 1e5
)" + extra;
}

// A uniform gas: every gauge inside it reads the state exactly, whatever the kernel weights (the
// Shepard normalisation); in RZ also near the axis, where the ring volumes vary with r.
TEST(Gauges, UniformStateIsReadExactlyInPlanarAndRZ) {
  for (const std::string dim : {"2d", "rz"}) {
    SCOPED_TRACE(dim);
    const Scene scene = parseScene(gasScene(dim, R"(
[[gauges]]
name = "inside"
position = [0.31, 0.27]
[[gauges]]
name = "near_axis"
position = [0.02, -0.4]
[[gauges]]
name = "outside"
position = [5.0, 5.0]
)"), "g.toml");
    MaterialTable materials = MaterialTable::fromScene(scene);
    ParticleSet p = buildParticles(scene, materials);
    Simulation sim(scene, std::move(p), std::move(materials), 1);
    sim.initialise();
    // The state as the particles hold it (summation density at the lattice's h differs from 1.2
    // by 2e-4, and more at the free edges): make it exactly uniform, so only the gauge is tested.
    ParticleSet& q = sim.particles();
    std::fill(q.P.begin(), q.P.end(), 1e5);
    std::fill(q.rho.begin(), q.rho.end(), 1.2);
    const std::vector<GaugeReading> r = readGauges(gaugeLayout(scene), q);
    ASSERT_EQ(r.size(), 3u);
    for (int g = 0; g < 2; ++g) {
      EXPECT_NEAR(r[g].pressure, 1e5, 1e-9 * 1e5);
      EXPECT_NEAR(r[g].density, 1.2, 1e-12);
      EXPECT_NEAR(r[g].velocity[0], 0.0, 1e-12);
    }
    // A gauge no particle reaches reads NaN (an empty cell in the CSV), not zero.
    EXPECT_TRUE(std::isnan(r[2].pressure));
  }
}

// A linear velocity field v_x = a x on a symmetric lattice: the interpolant is exact at a point
// of the lattice's symmetry (the first moment of the weights vanishes there).
TEST(Gauges, LinearFieldAtASymmetryPoint) {
  const Scene scene = parseScene(gasScene("2d", "[[gauges]]\nname = \"c\"\nposition = [0.0, 0.0]\n"), "g.toml");
  MaterialTable materials = MaterialTable::fromScene(scene);
  ParticleSet p = buildParticles(scene, materials);
  for (std::size_t i = 0; i < p.numReal; ++i) p.v[0][i] = 3.0 * p.x[0][i] + 2.0;
  Simulation sim(scene, std::move(p), std::move(materials), 1);
  sim.initialise();
  EXPECT_NEAR(readGauges(gaugeLayout(scene), sim.particles())[0].velocity[0], 2.0, 1e-12);
}

TEST(Gauges, RunWritesTheCsvAndPeaksAndRejectsBadNames) {
  const fs::path dir = fs::temp_directory_path() / ("ejecta_gauges_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  // A pressure pulse in the middle of the gas: the gauge beside it sees it pass.
  const Scene scene = parseScene(gasScene("2d", R"(
[[energy_deposits]]
name = "pulse"
energy = "2e4 J"
center = [0.0, 0.0]
radius = 0.12
[[gauges]]
name = "g1"
position = [0.25, 0.0]
)"), "g.toml");
  RunOptions options;
  options.outDir = dir.string();
  const RunOutcome out = runScene(scene, options);
  ASSERT_TRUE(out.ok) << out.error;
  std::ifstream csv(dir / "gauges.csv");
  std::string header, line;
  std::getline(csv, header);
  EXPECT_EQ(header, "step,time_s,g1_pressure_Pa,g1_density_kg_m3,g1_velocity_x_m_s,g1_velocity_y_m_s");
  long rows = 0;
  double peak = 0.0;
  while (std::getline(csv, line)) {
    ++rows;
    const std::size_t a = line.find(',', line.find(',') + 1);
    peak = std::max(peak, std::stod(line.substr(a + 1)));
  }
  EXPECT_EQ(rows, out.summary.steps + 1);  // t = 0 and every step
  double summaryPeak = 0.0, when = 0.0, arrival = -1.0, decay = -1.0;
  for (const auto& [k, v] : out.summary.extras) {
    if (k == "gauge_g1_peak_pressure_Pa") summaryPeak = std::get<double>(v);
    if (k == "gauge_g1_peak_time_s") when = std::get<double>(v);
    if (k == "gauge_g1_arrival_s") arrival = std::get<double>(v);
    if (k == "gauge_g1_decay_time_s") decay = std::get<double>(v);
  }
  EXPECT_NEAR(summaryPeak, peak, 1e-9 * peak);
  EXPECT_GT(peak, 1.2e5) << "the blast should have passed the gauge";
  EXPECT_GT(when, 0.0);
  // The pulse (sim/sources/gauge_decay.hpp, tested on exact pulses in test_gauge_decay): it arrives
  // (half its overpressure) before its peak, and falls to 1/e of it within the run.
  EXPECT_GT(arrival, 0.0);
  EXPECT_LE(arrival, when);
  EXPECT_GT(decay, 0.0) << "no decay constant in the summary";
  EXPECT_LT(when + decay, out.summary.tEnd);
  fs::remove_all(dir);
  EXPECT_THROW(parseScene(gasScene("2d", "[[gauges]]\nname = \"a,b\"\nposition = [0.0, 0.0]\n"), "g.toml"),
               SceneError);
}

}  // namespace
}  // namespace ejecta
