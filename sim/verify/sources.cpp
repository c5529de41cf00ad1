// Verification problems of energy sources (docs/sources.md): the programmed burn of a JWL
// explosive against the exact C-J detonation and Taylor wave.
#include <algorithm>
#include <cmath>

#include "sim/eos/eos_catalog.hpp"
#include "sim/exact/taylor_wave.hpp"
#include "sim/eos/jwl.hpp"
#include "sim/verify/runner.hpp"

namespace ejecta::verify::detail {

namespace {

// --- TNT bar lit at its middle (the seed's Sec. 3.2.1) -----------------------------------------

Report tntBar(const Options& options) {
  return convergenceStudy("tnt_bar_1d", options, 3, [&](const Scene& scene, Finished& f) {
    const JwlParams& tnt = jwlExplosive(scene.materials[0].library);
    const exact::TaylorWave wave(tnt);
    const exact::DetonationState& cj = wave.chapmanJouguet();
    const ParticleSet& p = f.particles;
    const double t = f.time - scene.detonations[0].time;
    const double x0 = scene.detonations[0].point[0];
    // Errors over the products and the unreacted bar, normalised by the C-J state so the three
    // fields read alike; the symmetric halves are folded onto x >= 0.
    double length = 0, l1P = 0, l1v = 0, l1rho = 0, peak = 0, front = 0;
    double plateauP = 0, plateauLength = 0;
    const double xWall = wave.wallSoundSpeed() * t;  // the resting products: |x| < c_wall t
    std::vector<std::vector<double>> rows;
    for (std::size_t i = 0; i < p.numReal; ++i) {
      const double x = std::abs(p.x[0][i] - x0);
      const double v = (p.x[0][i] >= x0 ? 1.0 : -1.0) * p.v[0][i];
      const exact::DetonationState s = wave.sample(x / t);
      const double w = p.mass[i] / p.rho[i];
      length += w;
      l1P += w * std::abs(p.P[i] - s.p);
      l1v += w * std::abs(v - s.u);
      l1rho += w * std::abs(p.rho[i] - s.rho);
      peak = std::max(peak, p.P[i]);
      if (p.P[i] > 0.5 * cj.p) front = std::max(front, x);
      if (x < 0.5 * xWall) {
        plateauP += w * p.P[i];
        plateauLength += w;
      }
      rows.push_back({p.x[0][i], p.rho[i], p.v[0][i], p.P[i], p.u[i], s.rho,
                      (p.x[0][i] >= x0 ? 1.0 : -1.0) * s.u, s.p, s.e});
    }
    std::sort(rows.begin(), rows.end());
    plateauP /= plateauLength;
    const double frontExact = wave.detonationVelocity() * t;
    f.run.metrics = {
        {"L1_pressure", l1P / (length * cj.p), "1"},
        {"L1_velocity", l1v / (length * cj.u), "1"},
        {"L1_density", l1rho / (length * cj.rho), "1"},
        {"front_position", front, "m"},
        {"front_position_exact", frontExact, "m"},
        {"front_position_error", (front - frontExact) / frontExact, "1"},
        {"peak_pressure", peak, "Pa"},
        {"peak_pressure_over_cj", peak / cj.p, "1"},
        {"rest_pressure", plateauP, "Pa"},
        {"rest_pressure_exact", wave.wall().p, "Pa"},
        {"rest_pressure_error", (plateauP - wave.wall().p) / wave.wall().p, "1"},
    };
    writeProfile(options, "tnt_bar_1d", f.run,
                 "x,rho,v,P,u,rho_exact,v_exact,P_exact,u_exact", rows);
  });
}

}  // namespace

std::vector<Problem> sourceProblems() {
  return {
      {"tnt_bar_1d", "TNT bar lit at its middle, 1D, t = 14 us: programmed burn against the exact C-J detonation and Taylor wave", 3, tntBar},
  };
}

}  // namespace ejecta::verify::detail
