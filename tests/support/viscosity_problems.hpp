#pragma once
// Two viscosity test problems shared by the viscosity switch and reconstruction tests: Sod's tube
// (the verification scene sod_1d) against the exact Riemann solution, and a periodic standing
// sound wave whose amplitude after one period measures the damping of smooth flow.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "sim/setup/bodies.hpp"
#include "sim/exact/riemann.hpp"
#include "sim/run/run.hpp"
#include "sim/verify/runner.hpp"

namespace ejecta::test {

struct SodResult {
  double l1Rho = 0, l1V = 0, l1P = 0;
  double energyError = 0;
  double plateauRipple = 0;     // max |v - u*| / u* between contact and shock (margins: 4 h)
  double shockAlphaPeak = 0;    // largest alpha seen within 2 h of the exact shock, t >= 0.05
  double leftStateAlphaMax = 0; // largest alpha in the undisturbed left gas at the end
  double rarefactionAlphaMax = 0;  // the fan and the left star region (never shocked)
  double plateauAlphaMax = 0;   // shocked gas, from the contact to half-way to the shock
  long steps = 0;
};

inline SodResult runSod(const std::vector<std::string>& overrides) {
  verify::Options options;
  options.threads = 1;
  options.overrides = overrides;
  const Scene scene = verify::detail::problemScene("sod_1d", options);
  const auto& left = scene.bodies[0];
  const auto& right = scene.bodies[1];
  const exact::RiemannProblem riemann({left.density, 0.0, *left.pressure},
                                      {right.density, 0.0, *right.pressure},
                                      scene.materials[0].gamma);
  const double x0 = left.shape.max[0];
  SodResult out;
  const auto observer = [&](const Simulation& sim) {
    const ParticleSet& p = sim.particles();
    if (!p.hasViscositySwitch() || sim.time() < 0.05) return;
    const double xShock = x0 + riemann.rightHeadSpeed() * sim.time();
    for (std::size_t i = 0; i < p.numReal; ++i)
      if (std::abs(p.x[0][i] - xShock) < 2.0 * p.h[i])
        out.shockAlphaPeak = std::max(out.shockAlphaPeak, p.alpha[i]);
  };
  const verify::detail::Finished f = verify::detail::runAt(scene, 1.0, options, observer);
  const ParticleSet& p = f.particles;
  const double t = f.time;
  const double uStar = riemann.starVelocity();
  const double xContact = x0 + uStar * t, xShock = x0 + riemann.rightHeadSpeed() * t;
  const double xHead = x0 + riemann.leftHeadSpeed() * t;
  double volume = 0;
  for (std::size_t i = 0; i < p.numReal; ++i) {
    const double x = p.x[0][i];
    const exact::GasState s = riemann.sample((x - x0) / t);
    const double w = p.mass[i] / p.rho[i];
    volume += w;
    out.l1Rho += w * std::abs(p.rho[i] - s.rho);
    out.l1V += w * std::abs(p.v[0][i] - s.u);
    out.l1P += w * std::abs(p.P[i] - s.p);
    if (x > xContact + 4.0 * p.h[i] && x < xShock - 4.0 * p.h[i])
      out.plateauRipple = std::max(out.plateauRipple, std::abs(p.v[0][i] - uStar) / uStar);
    if (p.hasViscositySwitch()) {
      if (x < xHead - 4.0 * p.h[i])
        out.leftStateAlphaMax = std::max(out.leftStateAlphaMax, p.alpha[i]);
      if (x > xHead && x < xContact - 4.0 * p.h[i])
        out.rarefactionAlphaMax = std::max(out.rarefactionAlphaMax, p.alpha[i]);
      if (x > xContact + 4.0 * p.h[i] && x < 0.5 * (xContact + xShock))
        out.plateauAlphaMax = std::max(out.plateauAlphaMax, p.alpha[i]);
    }
  }
  out.l1Rho /= volume;
  out.l1V /= volume;
  out.l1P /= volume;
  out.energyError = f.run.energyError;
  out.steps = f.run.steps;
  return out;
}

// Periodic 1D gas, c = 1 (rho = 1, P = 1/gamma), 100 particles on one wavelength.
inline constexpr const char* kWaveScene = R"(
[scene]
name = "sound_wave"
dimension = "1d"
[domain]
x = { min = 0.0, max = 1.0, boundary = "periodic" }
[time]
t_end = 1.0
[output]
snapshots = false
[[materials]]
name = "gas"
eos = "ideal_gas"
gamma = 1.4
[[bodies]]
name = "tube"
material = "gas"
shape = "box"
min = [0.0]
max = [1.0]
spacing = 0.01
density = 1.0
pressure = 0.7142857142857143
)";

struct WaveResult {
  double amplitudeRatio = 0;  // standing-wave amplitude after one period over the initial one
  double alphaMax = 0;        // largest alpha over the run
  double energyError = 0;
};

inline WaveResult runWave(const std::vector<std::string>& overrides, double amplitude) {
  const Scene scene = parseScene(kWaveScene, "sound_wave.toml", overrides);
  MaterialTable materials = MaterialTable::fromScene(scene);
  ParticleSet p = buildParticles(scene, materials);
  const double k = 2.0 * std::numbers::pi;
  // v = A sin(kx): two counter-running waves, a standing wave of period 1 (c = 1, lambda = 1).
  for (std::size_t i = 0; i < p.numReal; ++i) p.v[0][i] = amplitude * std::sin(k * p.x[0][i]);
  auto project = [&](const ParticleSet& q) {
    double s = 0;
    for (std::size_t i = 0; i < q.numReal; ++i)
      s += 2.0 * q.v[0][i] * std::sin(k * q.x[0][i]) * q.mass[i] / q.rho[i];
    return s;
  };
  const double a0 = project(p);
  Simulation sim(scene, std::move(p), std::move(materials), 1);
  WaveResult out;
  RunOptions options;
  options.threads = 1;
  options.observer = [&](const Simulation& s) {
    const ParticleSet& q = s.particles();
    if (!q.hasViscositySwitch()) return;
    for (std::size_t i = 0; i < q.numReal; ++i) out.alphaMax = std::max(out.alphaMax, q.alpha[i]);
  };
  const RunOutcome r = runSimulation(sim, options);
  EXPECT_TRUE(r.ok) << r.error;
  out.amplitudeRatio = project(sim.particles()) / a0;
  out.energyError = r.summary.energy.relativeError;
  return out;
}

}  // namespace ejecta::test
