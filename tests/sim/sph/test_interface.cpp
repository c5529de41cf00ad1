// Material interfaces (issue 3): a contact between very different materials must carry neither
// spurious pressure spikes nor mixing. Two cases with exact answers:
//  - a shocked interface, Al-2024 striking copper: the contact pressure and particle velocity of
//    the impedance match (both Hugoniots linear Us-up), with no overshoot at the interface;
//  - a granite/aluminium contact at rest: with continuity density nothing moves, while summation
//    density smooths the density jump and puts the contact particles out of equilibrium.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "sim/setup/bodies.hpp"
#include "sim/eos/mie_gruneisen.hpp"
#include "sim/run/run.hpp"

namespace ejecta {
namespace {

std::string flyerOnCopper(const std::string& form) {
  return R"(
[scene]
name = "al_on_cu"
dimension = "1d"
[sph]
eta = 2.0
density = "continuity"
form = ")" + form + R"("
[time]
t_end = "3 us"
[[materials]]
name = "al"
eos = "mie_gruneisen"
library = "Al-2024"
[[materials]]
name = "cu"
eos = "mie_gruneisen"
library = "copper"
[[bodies]]
name = "flyer"
material = "al"
shape = "box"
min = ["-20 mm"]
max = [0.0]
spacing = "0.1 mm"
density = "2785 kg/m^3"
pressure = 0.0
velocity = ["1 km/s"]
[[bodies]]
name = "target"
material = "cu"
shape = "box"
min = [0.0]
max = ["30 mm"]
spacing = "0.1 mm"
density = "8930 kg/m^3"
pressure = 0.0
)";
}

// Particle velocity of the contact from the impedance match of two linear Hugoniots:
// rho2 (c2 + s2 u) u = rho1 (c1 + s1 (V - u)) (V - u), by bisection.
double impedanceMatch(const ShockMaterial& flyer, const ShockMaterial& target, double V) {
  auto mismatch = [&](double u) {
    return target.rho0 * (target.c0 + target.s1 * u) * u -
           flyer.rho0 * (flyer.c0 + flyer.s1 * (V - u)) * (V - u);
  };
  double lo = 0.0, hi = V;
  for (int it = 0; it < 100; ++it) {
    const double mid = 0.5 * (lo + hi);
    (mismatch(mid) > 0.0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

struct ContactResult {
  // Plateau pressures and velocity over their exact values; the largest pressure between the
  // shock fronts over the exact one, away from and at the two particles that met at t = 0.
  double pressureTarget, pressureFlyer, velocity, peakPressure, contactPressure, overlap;
};

ContactResult runContact(const std::string& form) {
  const Scene scene = parseScene(flyerOnCopper(form), "al_on_cu.toml");
  MaterialTable materials = MaterialTable::fromScene(scene);
  Simulation sim(scene, buildParticles(scene, materials), materials, 2);
  const RunOutcome r = runSimulation(sim, RunOptions{});
  EXPECT_TRUE(r.ok) << r.error;
  const ParticleSet& p = sim.particles();
  const double t = sim.time();
  const ShockMaterial& al = shockMaterial("Al-2024");
  const ShockMaterial& cu = shockMaterial("copper");
  const double up = impedanceMatch(al, cu, 1000.0);
  const double contact = up * t;
  const double frontCu = contact + (cu.c0 + cu.s1 * up) * t;
  const double frontAl = contact - (al.c0 + al.s1 * (1000.0 - up)) * t;
  ContactResult c{0, 0, 0, 0, 0, 0};
  int nCu = 0, nAl = 0;
  double maxAl = -1e9, minCu = 1e9;
  std::size_t lastAl = 0, firstCu = 0;
  for (std::size_t i = 0; i < p.numReal; ++i) {
    const double x = p.x[0][i];
    if (p.material[i] == 0 && x > maxAl) { maxAl = x; lastAl = i; }
    if (p.material[i] == 1 && x < minCu) { minCu = x; firstCu = i; }
  }
  for (std::size_t i = 0; i < p.numReal; ++i) {
    const double x = p.x[0][i];
    // Plateaus: the middle half between the contact and each shock front.
    if (p.material[i] == 1 && x > contact + 0.25 * (frontCu - contact) &&
        x < contact + 0.75 * (frontCu - contact)) {
      c.pressureTarget += p.P[i];
      c.velocity += p.v[0][i];
      ++nCu;
    }
    if (p.material[i] == 0 && x < contact - 0.25 * (contact - frontAl) &&
        x > contact - 0.75 * (contact - frontAl)) {
      c.pressureFlyer += p.P[i];
      ++nAl;
    }
    if (i == lastAl || i == firstCu) {
      c.contactPressure = std::max(c.contactPressure, p.P[i]);
    } else if (x > frontAl + 0.1 * (contact - frontAl) && x < frontCu - 0.1 * (frontCu - contact)) {
      c.peakPressure = std::max(c.peakPressure, p.P[i]);
    }
  }
  c.pressureTarget /= nCu;
  c.pressureFlyer /= nAl;
  c.velocity /= nCu;
  c.overlap = maxAl - minCu;
  const double pExact = cu.rho0 * (cu.c0 + cu.s1 * up) * up;
  c.pressureTarget /= pExact;
  c.pressureFlyer /= pExact;
  c.peakPressure /= pExact;
  c.contactPressure /= pExact;
  c.velocity /= up;
  return c;
}

TEST(MaterialInterface, AluminiumOnCopperMatchesTheImpedanceMatchWithoutSpikes) {
  double contactSpike[2] = {0.0, 0.0}, peak[2] = {0.0, 0.0};
  int k = 0;
  for (const std::string form : {"interface", "lagrangian"}) {
    SCOPED_TRACE("form = " + form);
    const ContactResult c = runContact(form);
    // Both sides of the contact at the exact contact pressure (12.1 GPa) and velocity: 1%
    // covers the plateaus' residual ringing after 3 us (measured < 0.1%).
    EXPECT_NEAR(c.pressureTarget, 1.0, 0.01);
    EXPECT_NEAR(c.pressureFlyer, 1.0, 0.01);
    EXPECT_NEAR(c.velocity, 1.0, 0.01);
    // No interpenetration: every aluminium particle stays behind every copper particle.
    EXPECT_LT(c.overlap, 0.0);
    contactSpike[k] = c.contactPressure;
    peak[k++] = c.peakPressure;
  }
  // The interface form: no pressure spike along the interface region; nothing between the shock
  // fronts, save the two particles that met at t = 0, exceeds the contact pressure by more than
  // the 5% of a shock's own overshoot (measured 0.8%).
  EXPECT_LT(peak[0], 1.05);
  // The Lagrangian form's P/rho^2 weights spread a spike over the neighbours of the contact
  // (measured +25%): the reason scenes with interfaces use sph.form = "interface".
  EXPECT_GT(peak[1], peak[0]);
  // The two particles that collided at t = 0 keep the start-up error of every impact ("wall
  // heating", Noh 1987, J. Comput. Phys. 72, 78): excess entropy and a pressure excess on the
  // denser side, +17% with the interface form against +28% with the Lagrangian one.
  EXPECT_LT(contactSpike[0], 1.2);
  EXPECT_LT(contactSpike[0], contactSpike[1]);
}

// Granite (Tillotson) against aluminium (Mie-Grueneisen) at rest and zero pressure, between two
// walls. The exact answer is that nothing happens.
std::string contactAtRest(const std::string& density) {
  return R"(
[scene]
name = "granite_al_rest"
dimension = "2d"
[domain]
x = { min = "-10 mm", max = "10 mm", boundary = "wall" }
y = { min = "-5 mm", max = "5 mm", boundary = "periodic" }
[sph]
density = ")" + density + R"("
form = "interface"
[time]
t_end = "5 us"
[[materials]]
name = "granite"
eos = "tillotson"
library = "granite"
[materials.strength]
model = "von_mises"
shear_modulus = "25 GPa"
yield_stress = "3.5 GPa"
[[materials]]
name = "al"
eos = "mie_gruneisen"
library = "Al-2024"
[materials.strength]
library = "Al-2024-T351"
model = "johnson_cook"
[[bodies]]
name = "rock"
material = "granite"
shape = "box"
min = ["-10 mm", "-5 mm"]
max = [0.0, "5 mm"]
spacing = "0.5 mm"
density = "2680 kg/m^3"
pressure = 0.0
[[bodies]]
name = "plate"
material = "al"
shape = "box"
min = [0.0, "-5 mm"]
max = ["10 mm", "5 mm"]
spacing = "0.5 mm"
density = "2785 kg/m^3"
pressure = 0.0
)";
}

double maxSpeedAtRest(const std::string& density, double& maxPressure) {
  const Scene scene = parseScene(contactAtRest(density), "granite_al_rest.toml");
  MaterialTable materials = MaterialTable::fromScene(scene);
  Simulation sim(scene, buildParticles(scene, materials), materials, 2);
  const RunOutcome r = runSimulation(sim, RunOptions{});
  EXPECT_TRUE(r.ok) << r.error;
  const ParticleSet& p = sim.particles();
  double vMax = 0.0;
  maxPressure = 0.0;
  for (std::size_t i = 0; i < p.numReal; ++i) {
    vMax = std::max(vMax, std::hypot(p.v[0][i], p.v[1][i]));
    maxPressure = std::max(maxPressure, std::abs(p.P[i]));
  }
  return vMax;
}

TEST(MaterialInterface, GraniteAluminiumContactAtRestStaysAtRestWithContinuityDensity) {
  double pContinuity = 0.0, pSummation = 0.0;
  const double vContinuity = maxSpeedAtRest("continuity", pContinuity);
  const double vSummation = maxSpeedAtRest("summation", pSummation);
  // Continuity density keeps each particle's own density: the state is an exact equilibrium
  // and stays one to round-off.
  EXPECT_LT(vContinuity, 1e-6);
  EXPECT_LT(pContinuity, 1.0);
  // Summation density smears the 4% density jump over 2h: the contact particles start out of
  // equilibrium by tens of MPa and move at m/s (the failure this treatment avoids). Asserting it
  // keeps the comparison honest.
  EXPECT_GT(pSummation, 1e7);
  EXPECT_GT(vSummation, 1.0);
}

}  // namespace
}  // namespace ejecta
