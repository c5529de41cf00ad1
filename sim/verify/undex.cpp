// Verification problems of underwater explosions (docs/undex.md), both against the exact C-J /
// water impedance match (sim/exact/impedance_match.hpp):
//   undex_1d          the TNT slab lit at its far end, its gauges' water shock against p* and the
//                     water Hugoniot;
//   undex_riemann_1d  the same slab already at the C-J state and moving at u_CJ (a supported
//                     detonation), the whole profile against the exact self-similar solution.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/exact/impedance_match.hpp"
#include "sim/sources/gauges.hpp"
#include "sim/eos/jwl.hpp"
#include "sim/sph/kernel.hpp"
#include "sim/eos/mie_gruneisen.hpp"
#include "sim/verify/runner.hpp"

namespace ejecta::verify::detail {

namespace {

// What one gauge saw of the water shock.
struct GaugePeak {
  double position = 0.0;  // distance into the water from the initial interface [m]
  double pressure = 0.0;  // peak pressure [Pa]
  double velocity = 0.0;  // particle velocity at the peak [m/s]
  double arrival = 0.0;   // when the pressure first rose through half its peak [s]
};

// Pressure and velocity of every gauge after every step, and whether the products were out of
// its reach: once the contact comes within a kernel support, the gauge averages products and
// water, and SPH's pressure blip at the contact is not the water shock.
struct GaugeHistory {
  std::vector<double> time;
  std::vector<std::vector<GaugeReading>> readings;  // [step][gauge]
  std::vector<std::vector<char>> waterOnly;         // [step][gauge]

  void record(const Scene& scene, const ParticleSet& p, int explosive, double t) {
    time.push_back(t);
    readings.push_back(readGauges(gaugeLayout(scene), p));
    std::vector<char> clean(scene.gauges.size(), 1);
    for (std::size_t g = 0; g < scene.gauges.size(); ++g)
      for (std::size_t i = 0; i < p.numReal; ++i)
        if (p.material[i] == explosive &&
            std::abs(p.x[0][i] - scene.gauges[g].position[0]) < kKernelSupport * p.h[i]) {
          clean[g] = 0;
          break;
        }
    waterOnly.push_back(std::move(clean));
  }
};

// Least-squares line y = a + b x.
struct Line {
  double a = 0.0, b = 0.0;
};
Line fitLine(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    sx += x[k];
    sy += y[k];
    sxx += x[k] * x[k];
    sxy += x[k] * y[k];
  }
  const double b = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  return {(sy - b * sx) / n, b};
}

// Each gauge's water-shock peak. A gauge counts only if its pressure rose to the peak and fell
// again while the products were out of its reach; on a coarse lattice the contact can enter a
// gauge's kernel before the shock has passed it.
std::vector<GaugePeak> gaugePeaks(const Scene& scene, const GaugeHistory& h, double interface) {
  std::vector<GaugePeak> peaks;
  for (std::size_t g = 0; g < scene.gauges.size(); ++g) {
    GaugePeak peak;
    peak.position = scene.gauges[g].position[0] - interface;
    std::size_t at = 0;
    bool passed = false;
    for (std::size_t s = 0; s < h.time.size() && h.waterOnly[s][g]; ++s) {
      const double pressure = h.readings[s][g].pressure;
      if (pressure > peak.pressure) {
        peak.pressure = pressure;
        at = s;
        passed = false;
      } else if (pressure < peak.pressure) {
        passed = true;
      }
    }
    if (!passed || !(peak.pressure > 0.0)) continue;
    peak.velocity = h.readings[at][g].velocity[0];
    // The first rise through half the peak, interpolated between the two steps that bracket it.
    for (std::size_t s = 1; s <= at; ++s) {
      const double p0 = h.readings[s - 1][g].pressure, p1 = h.readings[s][g].pressure;
      if (p0 < 0.5 * peak.pressure && p1 >= 0.5 * peak.pressure) {
        const double f = (0.5 * peak.pressure - p0) / (p1 - p0);
        peak.arrival = h.time[s - 1] + f * (h.time[s] - h.time[s - 1]);
        break;
      }
    }
    peaks.push_back(peak);
  }
  if (peaks.size() < 3)
    throw std::runtime_error("undex_1d: fewer than 3 gauges saw the water shock pass before the "
                             "products reached them");
  return peaks;
}

// --- TNT slab against water, 1D (the seed's Sec. 3.2.2) ----------------------------------------

Report undex1d(const Options& options) {
  const std::string name = "undex_1d";
  const Scene scene = problemScene(name, options);
  const JwlParams& tnt = jwlExplosive(scene.materials.at(0).library);
  const ShockMaterial& water = shockMaterial(scene.materials.at(1).library);
  const exact::ImpedanceMatch match = exact::detonationImpedanceMatch(tnt, water);
  const double interface = scene.bodies.at(0).shape.max[0];
  const double lit = scene.detonations.at(0).point[0];
  const double reachesWater = scene.detonations.at(0).time + (interface - lit) / tnt.dCJ;

  Report report;
  report.problem = name;
  report.description = scene.description;
  report.reference = "exact impedance match of the C-J products (JWL, " + tnt.name +
                     ") against water at rest (Mie-Grueneisen Hugoniot): p* = " +
                     std::to_string(match.pressure() / 1e9) + " GPa";
  const int levels = options.resolutions > 0 ? options.resolutions : 3;
  for (int k = levels - 1; k >= 0; --k) {
    GaugeHistory history;
    Finished f = runAt(scene, std::pow(2.0, k), options, [&](const Simulation& sim) {
      history.record(scene, sim.particles(), scene.bodies[0].material, sim.time());
    });
    const std::vector<GaugePeak> peaks = gaugePeaks(scene, history, interface);
    std::vector<double> d, p, t, usHugoniot;
    std::vector<std::vector<double>> rows;
    for (const GaugePeak& g : peaks) {
      d.push_back(g.position);
      p.push_back(g.pressure);
      t.push_back(g.arrival);
      usHugoniot.push_back(hugoniotShockVelocity(water, g.velocity));
      rows.push_back({g.position, g.pressure, g.velocity, g.arrival, usHugoniot.back(),
                      water.rho0 * usHugoniot.back() * g.velocity});
    }
    // The Taylor wave behind the C-J front weakens the water shock as it runs: the peaks fall
    // almost linearly over the gauges' 16 mm, so a straight line through them, taken back to the
    // interface, estimates the peak the interface launched.
    const Line peakLine = fitLine(d, p);
    // The shock's mean speed over the gauges, and the Hugoniot's at the particle velocities
    // the gauges measured: the same average over the same decaying shock.
    const Line trajectory = fitLine(t, d);
    double usMean = 0.0;
    for (double u : usHugoniot) usMean += u / static_cast<double>(usHugoniot.size());
    // Where the shock line meets the interface: when the detonation reached the water.
    const double launch = fitLine(d, t).a;
    f.run.metrics = {
        {"peak_pressure_extrapolated", peakLine.a, "Pa"},
        {"peak_pressure_exact", match.pressure(), "Pa"},
        {"peak_pressure_error", (peakLine.a - match.pressure()) / match.pressure(), "1"},
        {"gauges_used", static_cast<double>(peaks.size()), "1"},
        {"peak_pressure_first_gauge", peaks.front().pressure, "Pa"},
        {"peak_pressure_last_gauge", peaks.back().pressure, "Pa"},
        {"shock_speed", trajectory.b, "m/s"},
        {"shock_speed_hugoniot", usMean, "m/s"},
        {"shock_speed_error", (trajectory.b - usMean) / usMean, "1"},
        {"shock_speed_exact_at_interface", match.target.us, "m/s"},
        {"shock_launch_time", launch, "s"},
        {"shock_launch_time_exact", reachesWater, "s"},
        {"shock_launch_time_error", (launch - reachesWater) / reachesWater, "1"},
    };
    writeProfile(options, name, f.run, "d,peak_P,u_at_peak,arrival,Us_hugoniot,P_hugoniot", rows);
    report.runs.push_back(std::move(f.run));
  }
  // Observed orders of the peak and shock-speed errors between successive resolutions.
  for (std::size_t r = 1; r < report.runs.size(); ++r)
    for (const char* m : {"peak_pressure_error", "shock_speed_error"}) {
      const double coarse = std::abs(report.runs[r - 1].metric(m));
      const double fine = std::abs(report.runs[r].metric(m));
      const double ratio = report.runs[r - 1].spacing / report.runs[r].spacing;
      report.orders.push_back({std::string("order_") + m + "_" + std::to_string(r),
                               std::log(coarse / fine) / std::log(ratio), "1"});
    }
  return report;
}

// --- The same slab at the C-J state against water: the exact Riemann problem -------------------

// undex_1d's scene with the slab replaced by detonation products at the C-J state moving toward
// the water at u_CJ, as if the detonation had just arrived and a piston kept it supported: the
// interface is then the Riemann problem of sim/exact/impedance_match.hpp for all time, with no
// programmed burn and no Taylor wave. It runs for 8 us: the water shock is then 47 mm in and the
// reflected fan's head 26 mm back, while the release from the slab's far end (the products move
// away from the wall) has come only to 45 mm from the interface.
Scene supportedDetonationScene(const Scene& slab, const JwlParams& tnt) {
  Scene scene = slab;
  const ChapmanJouguetState cj = chapmanJouguetState(tnt);
  BodySpec& products = scene.bodies.at(0);
  products.density = cj.rho;
  products.pressure.reset();
  products.internalEnergy = cj.u;
  products.velocity = {cj.up, 0.0, 0.0};
  scene.detonations.clear();
  scene.name = "undex_riemann_1d";
  scene.description = "TNT products at the C-J state (moving at u_CJ) against water, 1D: the whole "
                      "profile against the exact impedance-match Riemann solution";
  scene.time.tEnd = 8e-6;
  return scene;
}

Report undexRiemann1d(const Options& options) {
  const Scene slab = problemScene("undex_1d", options);
  const JwlParams& tnt = jwlExplosive(slab.materials.at(0).library);
  const ShockMaterial& water = shockMaterial(slab.materials.at(1).library);
  const Scene scene = supportedDetonationScene(slab, tnt);
  const exact::InterfaceRiemannSolution solution(tnt, water);
  const exact::ImpedanceMatch& star = solution.match();
  const double x0 = slab.bodies.at(0).shape.max[0];

  Report report;
  report.problem = scene.name;
  report.description = scene.description;
  report.reference = "exact Riemann solution of C-J products (JWL) against water at rest";
  const int levels = options.resolutions > 0 ? options.resolutions : 3;
  for (int k = levels - 1; k >= 0; --k) {
    Finished f = runAt(scene, std::pow(2.0, k), options);
    const ParticleSet& p = f.particles;
    const double t = f.time;
    // Errors over every wave and a margin of undisturbed state on both sides, in units of the
    // star state so that the three fields read alike.
    const double left = x0 + 1.2 * solution.reflectedHeadSpeed() * t;
    const double right = x0 + 1.2 * star.target.us * t;
    double length = 0, l1P = 0, l1v = 0, l1rho = 0;
    double contactProducts = -1e300, contactWater = 1e300;
    std::vector<std::vector<double>> rows;
    for (std::size_t i = 0; i < p.numReal; ++i) {
      const double x = p.x[0][i];
      if (p.material[i] == scene.bodies[0].material)
        contactProducts = std::max(contactProducts, x);
      else
        contactWater = std::min(contactWater, x);
      if (x < left || x > right) continue;
      const exact::InterfaceSample s = solution.sample((x - x0) / t);
      const double w = p.mass[i] / p.rho[i];
      length += w;
      l1P += w * std::abs(p.P[i] - s.p);
      l1v += w * std::abs(p.v[0][i] - s.u);
      l1rho += w * std::abs(p.rho[i] - s.rho);
      rows.push_back({x, p.rho[i], p.v[0][i], p.P[i], s.rho, s.u, s.p});
    }
    std::sort(rows.begin(), rows.end());
    // The shocked water between the contact and the shock, away from both by a quarter of the
    // layer, against (p*, u*); the shock where the velocity falls through u*/2.
    const double contact = 0.5 * (contactProducts + contactWater);
    const double shock = waveFront(p, 0.5 * star.velocity());
    double plateauP = 0, plateauV = 0;
    int n = 0;
    for (std::size_t i = 0; i < p.numReal; ++i) {
      const double x = p.x[0][i];
      if (x > contact + 0.25 * (shock - contact) && x < contact + 0.75 * (shock - contact)) {
        plateauP += p.P[i];
        plateauV += p.v[0][i];
        ++n;
      }
    }
    if (n == 0) throw std::runtime_error("undex_riemann_1d: no particle in the shocked water");
    plateauP /= n;
    plateauV /= n;
    const double shockExact = x0 + star.target.us * t, contactExact = x0 + star.velocity() * t;
    f.run.metrics = {
        {"L1_pressure", l1P / (length * star.pressure()), "1"},
        {"L1_velocity", l1v / (length * star.velocity()), "1"},
        {"L1_density", l1rho / (length * star.target.rho), "1"},
        {"interface_pressure", plateauP, "Pa"},
        {"interface_pressure_exact", star.pressure(), "Pa"},
        {"interface_pressure_error", (plateauP - star.pressure()) / star.pressure(), "1"},
        {"interface_velocity", plateauV, "m/s"},
        {"interface_velocity_exact", star.velocity(), "m/s"},
        {"interface_velocity_error", (plateauV - star.velocity()) / star.velocity(), "1"},
        {"shock_position", shock, "m"},
        {"shock_position_error", (shock - shockExact) / (shockExact - x0), "1"},
        {"contact_position_error", (contact - contactExact) / (contactExact - x0), "1"},
    };
    writeProfile(options, scene.name, f.run, "x,rho,v,P,rho_exact,v_exact,P_exact", rows);
    report.runs.push_back(std::move(f.run));
  }
  for (std::size_t r = 1; r < report.runs.size(); ++r)
    for (const char* m : {"L1_pressure", "L1_velocity", "L1_density"}) {
      const double ratio = report.runs[r - 1].spacing / report.runs[r].spacing;
      report.orders.push_back(
          {std::string("order_") + m + "_" + std::to_string(r),
           std::log(report.runs[r - 1].metric(m) / report.runs[r].metric(m)) / std::log(ratio),
           "1"});
    }
  return report;
}

}  // namespace

std::vector<Problem> undexProblems() {
  return {
      {"undex_1d", "TNT slab lit at its far end against water, 1D: water shock against the exact C-J/water impedance match and the water Hugoniot", 3, undex1d},
      {"undex_riemann_1d", "TNT products at the C-J state against water, 1D: the whole profile against the exact impedance-match Riemann solution", 3, undexRiemann1d},
  };
}

}  // namespace ejecta::verify::detail
