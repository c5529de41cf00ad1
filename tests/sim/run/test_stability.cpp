// Where the seed's codes failed (issue 4, label `stability`): its in-house SPH lost symmetry in
// high-energy subsurface bursts, AUTODYN's SPH could not run air blasts, and its Euler solver
// accumulated large energy errors from a 1e12 Pa source. Each case here runs at a reduced size and
// asserts the property the seed's code lost, with a bound from the measured value.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <map>
#include <utility>

#include "sim/setup/bodies.hpp"
#include "sim/solid/materials.hpp"
#include "sim/run/run.hpp"
#include "sim/setup/scene.hpp"
#include "sim/run/simulation.hpp"
#include "support/mirror_symmetry.hpp"

namespace ejecta {
namespace {

using test::mirrorAsymmetry;
using test::Ran;
constexpr auto run = test::runMirrorScene;

// The 250 kt burst of tests/support/mirror_symmetry.hpp.
TEST(Stability, SubsurfaceBurstOf250ktStaysSymmetricWithBoundedEnergyError) {
  const Ran r = run(test::burst250ktScene());
  ASSERT_TRUE(r.outcome.ok) << r.outcome.error;
  // The shock has travelled well into the rock: the fastest target particle moves.
  double moved = 0.0;
  for (std::size_t i = 0; i < r.final.numReal; ++i)
    if (r.final.material[i] == 0) moved = std::max(moved, std::hypot(r.final.v[0][i], r.final.v[1][i]));
  EXPECT_GT(moved, 1e3);
  // Mirror symmetry in x and y: every pair of mirror particles stays mirrored. The gather sums
  // run in a fixed order, so the only asymmetry is round-off in sums over mirrored neighbour
  // lists: measured 7e-13 m at 0.5 ms. 1e-9 m fails on any real asymmetry, such as a
  // direction-dependent loop or a one-sided ghost.
  const double ax = mirrorAsymmetry(r, 0), ay = mirrorAsymmetry(r, 1);
  std::printf("  mirror asymmetry: %.3g m (x), %.3g m (y)\n", ax, ay);
  EXPECT_LT(ax, 1e-9);
  EXPECT_LT(ay, 1e-9);
  // Energy: measured dE/E = -3.4e-4 with a 3e10 J/kg source; 2e-3 bounds it.
  EXPECT_LT(std::abs(r.outcome.summary.energy.relativeError), 2e-3);
}

// An air blast: 1 kg of TNT (4.184 MJ) in sea-level air (1.225 kg/m^3, 101325 Pa; U.S. Standard
// Atmosphere 1976), RZ. At 0.3 ms the shock stands ~0.8 m out, where its overpressure is still
// ~25 times ambient, so the Sedov-Taylor radius R = (E t^2 / (alpha rho))^(1/5), alpha = 0.851
// (gamma 1.4, spherical), is a fair reference; the ambient pressure slows the shock by a few %.
TEST(Stability, AirBlastInAnIdealGasRunsAndFollowsTheBlastWave) {
  const Ran r = run(R"(
[scene]
name = "air_blast"
dimension = "rz"
[domain]
x = { min = 0.0, max = 1.5, boundary = "wall" }
y = { min = -1.5, max = 1.5, boundary = "wall" }
[time]
t_end = "0.3 ms"
[[materials]]
name = "air"
eos = "ideal_gas"
gamma = 1.4
[[bodies]]
name = "air"
material = "air"
shape = "box"
min = [0.0, -1.5]
max = [1.5, 1.5]
spacing = "3 cm"
density = 1.225
pressure = 101325.0
[[energy_deposits]]
name = "charge"
energy = "4.184 MJ"          # 1 kg of TNT
center = [0.0, 0.0]
radius = "6 cm"
)");
  ASSERT_TRUE(r.outcome.ok) << r.outcome.error;
  // Shock radius: the density peak.
  double rPeak = 0.0, rhoPeak = 0.0;
  for (std::size_t i = 0; i < r.final.numReal; ++i)
    if (r.final.rho[i] > rhoPeak) {
      rhoPeak = r.final.rho[i];
      rPeak = std::hypot(r.final.x[0][i], r.final.x[1][i]);
    }
  const double t = 0.3e-3, E = 4.184e6;
  const double sedov = std::pow(E * t * t / (0.851 * 1.225), 0.2);
  // Measured 0.850 m against 0.816 m (+4%); the counter-pressure and the 3 cm resolution (the
  // peak lags by ~1 h) allow 10%.
  std::printf("  shock at %.4g m, Sedov-Taylor %.4g m\n", rPeak, sedov);
  EXPECT_NEAR(rPeak / sedov, 1.0, 0.10) << "shock at " << rPeak << " m, Sedov " << sedov << " m";
  EXPECT_GT(rhoPeak, 2.5 * 1.225);  // a real shock, compressed toward (gamma+1)/(gamma-1) = 6
  EXPECT_LT(std::abs(r.outcome.summary.energy.relativeError), 1e-3);
}

// A 1e12 Pa source in granite (the jump that broke AUTODYN's Euler energy balance): a 0.3 m
// region set to 1e12 Pa in a 4 m granite block, 2D planar.
TEST(Stability, TerapascalSourceKeepsItsEnergyErrorSmall) {
  const Ran r = run(R"(
[scene]
name = "terapascal"
dimension = "2d"
[sph]
density = "continuity"
form = "interface"
[time]
t_end = "0.1 ms"
[[materials]]
name = "granite"
eos = "tillotson"
library = "granite"
parameters = { minimum_pressure = 0.0 }
[[bodies]]
name = "source"
material = "granite"
shape = "sphere"
center = [0.0, 0.0]
radius = "0.3 m"
spacing = "0.05 m"
density = 2680.0
pressure = "1e12 Pa"
[[bodies]]
name = "rock"
material = "granite"
shape = "box"
min = [-2.0, -2.0]
max = [2.0, 2.0]
spacing = "0.05 m"
density = 2680.0
pressure = 0.0
)");
  ASSERT_TRUE(r.outcome.ok) << r.outcome.error;
  double moved = 0.0;
  for (std::size_t i = 0; i < r.final.numReal; ++i)
    if (std::hypot(r.initial.x[0][i], r.initial.x[1][i]) > 1.0)
      moved = std::max(moved, std::hypot(r.final.v[0][i], r.final.v[1][i]));
  EXPECT_GT(moved, 100.0) << "the shock should have passed 1 m by 0.1 ms";
  // Measured dE/E = 2e-4; 1e-3 bounds it.
  EXPECT_LT(std::abs(r.outcome.summary.energy.relativeError), 1e-3);
}

}  // namespace
}  // namespace ejecta
