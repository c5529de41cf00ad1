#include "sim/verify/verification.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "core/atomic_file.hpp"
#include "core/join.hpp"
#include "sim/eos/mie_gruneisen.hpp"
#include "sim/exact/radial_euler.hpp"
#include "sim/exact/riemann.hpp"
#include "sim/exact/sedov.hpp"
#include "sim/run/run.hpp"
#include "sim/setup/bodies.hpp"
#include "sim/setup/embedded_scenes.hpp"
#include "sim/solid/materials.hpp"
#include "sim/verify/blast_metrics.hpp"
#include "sim/verify/runner.hpp"

namespace ejecta::verify {

double ResolutionRun::metric(const std::string& name) const {
  for (const Metric& m : metrics)
    if (m.name == name) return m.value;
  throw std::out_of_range("no metric '" + name + "'");
}

namespace detail {

std::vector<Problem> undexProblems();  // sim/verify/undex.cpp

Scene problemScene(const std::string& name, const Options& options) {
  const std::string key = "verification/" + name;
  const std::string_view text = findEmbeddedScene(key);
  if (text.empty()) throw std::logic_error("verification scene '" + key + "' is not embedded");
  return parseScene(std::string(text), "scenes/" + key + ".toml", options.overrides);
}

// Runs the scene with every body's spacing multiplied by `coarsen`; `observer` (optional) sees
// the simulation after every step.
Finished runAt(Scene scene, double coarsen, const Options& options,
               std::function<void(const Simulation&)> observer, Coarsen what) {
  for (BodySpec& b : scene.bodies) b.spacing *= coarsen;
  if (what == Coarsen::BodiesAndDeposits)
    for (EnergyDepositSpec& d : scene.deposits)
      if (d.profile == DepositProfile::Gaussian) d.width *= coarsen;
  scene.output.snapshots = false;
  const int threads = resolveThreads(options.threads);
  MaterialTable materials = MaterialTable::fromScene(scene);
  ParticleSet particles = buildParticles(scene, materials);
  Simulation sim(scene, std::move(particles), std::move(materials), threads);
  RunOptions runOptions;
  runOptions.threads = threads;
  runOptions.progress = options.progress;
  runOptions.observer = std::move(observer);
  const RunOutcome outcome = runSimulation(sim, runOptions);
  if (!outcome.ok)
    throw std::runtime_error("verification run '" + scene.name + "' failed: " + outcome.error);
  Finished f;
  f.particles = sim.particles();
  f.time = sim.time();
  f.run.spacing = scene.bodies.front().spacing;
  f.run.particles = outcome.summary.particles;
  f.run.steps = outcome.summary.steps;
  f.run.particleUpdates = sim.particleUpdates();
  f.run.wallSeconds = outcome.summary.wallSeconds;
  f.run.energyError = outcome.summary.energy.relativeError;
  // RZ conserves only axial momentum (component 1); the radial one is not a conserved quantity.
  const bool rz = scene.geometry == Geometry::Axisymmetric;
  double dp2 = 0.0, scale = 0.0;
  for (int d = rz ? 1 : 0; d < (rz ? 2 : 3); ++d) {
    const double dp = outcome.summary.momentum.final[d] - outcome.summary.momentum.initial[d];
    dp2 += dp * dp;
  }
  const ParticleSet& p = f.particles;
  for (std::size_t i = 0; i < p.numReal; ++i)
    scale += p.mass[i] * std::sqrt(p.v[0][i] * p.v[0][i] + p.v[1][i] * p.v[1][i] +
                                   p.v[2][i] * p.v[2][i]);
  f.run.momentumError = scale > 0 ? std::sqrt(dp2) / scale : 0.0;
  return f;
}

Report convergenceStudy(const std::string& name, const Options& options, int defaultLevels,
                        const std::function<void(const Scene&, Finished&)>& measure,
                        const std::function<void(const Simulation&)>& observer, Coarsen what) {
  const Scene scene = problemScene(name, options);
  Report report;
  report.problem = name;
  report.description = scene.description;
  std::vector<double> factors = options.factors;
  if (factors.empty()) {
    const int levels = options.resolutions > 0 ? options.resolutions : defaultLevels;
    for (int k = levels - 1; k >= 0; --k) factors.push_back(std::pow(2.0, k));
  }
  std::sort(factors.begin(), factors.end(), std::greater<>());  // coarsest first
  for (const double factor : factors) {
    Finished f = runAt(scene, factor, options, observer, what);
    measure(scene, f);
    report.runs.push_back(std::move(f.run));
  }
  // Observed order between successive runs for every L1 metric: log2(e_coarse / e_fine).
  for (std::size_t r = 1; r < report.runs.size(); ++r)
    for (const Metric& m : report.runs[r].metrics) {
      if (m.name.rfind("L1_", 0) != 0) continue;
      const double coarse = report.runs[r - 1].metric(m.name);
      const double ratio = report.runs[r - 1].spacing / report.runs[r].spacing;
      report.orders.push_back({"order_" + m.name + "_" + std::to_string(r),
                               std::log(coarse / m.value) / std::log(ratio), "1"});
    }
  return report;
}

void writeProfile(const Options& options, const std::string& name, const ResolutionRun& run,
                  const std::string& header, const std::vector<std::vector<double>>& rows) {
  if (options.outDir.empty()) return;
  std::filesystem::create_directories(options.outDir);
  char file[64];
  std::snprintf(file, sizeof file, "%s_n%zu.csv", name.c_str(), run.particles);
  std::ostringstream out;
  out << header << "\n";
  out.precision(10);
  for (const auto& row : rows) {
    for (std::size_t c = 0; c < row.size(); ++c) out << (c ? "," : "") << row[c];
    out << "\n";
  }
  writeFileAtomically(std::filesystem::path(options.outDir) / file, out.str());
}

// The rightmost position where the x-velocity profile first falls below `level` (the front of a
// wave running in +x into material at rest), interpolated between the bracketing particles.
double waveFront(const ParticleSet& p, double level) {
  std::vector<std::pair<double, double>> xv;
  for (std::size_t i = 0; i < p.numReal; ++i) xv.emplace_back(p.x[0][i], p.v[0][i]);
  std::sort(xv.begin(), xv.end());
  for (std::size_t k = xv.size() - 1; k > 0; --k)
    if (xv[k - 1].second >= level && xv[k].second < level) {
      const double f = (level - xv[k].second) / (xv[k - 1].second - xv[k].second);
      return xv[k].first + f * (xv[k - 1].first - xv[k].first);
    }
  throw std::runtime_error("no wave front found at velocity level " + std::to_string(level));
}

Report singleRunReport(const std::string& name, const Scene& scene, std::string reference,
                       ResolutionRun run) {
  Report report;
  report.problem = name;
  report.description = scene.description;
  report.reference = std::move(reference);
  report.runs.push_back(std::move(run));
  return report;
}

}  // namespace detail

namespace {

using namespace detail;

// Volume-weighted L1 errors of density, velocity and pressure against a reference state.
struct L1Accumulator {
  double volume = 0, rho = 0, v = 0, P = 0;
  void add(double weight, double rhoNum, double vNum, double PNum, const exact::GasState& ref) {
    volume += weight;
    rho += weight * std::abs(rhoNum - ref.rho);
    v += weight * std::abs(vNum - ref.u);
    P += weight * std::abs(PNum - ref.p);
  }
  std::vector<Metric> metrics() const {
    return {{"L1_density", rho / volume, "kg/m^3"},
            {"L1_velocity", v / volume, "m/s"},
            {"L1_pressure", P / volume, "Pa"}};
  }
};

// --- Sod shock tube, 1D -------------------------------------------------------------------------

Report sod1d(const Options& options) {
  return convergenceStudy("sod_1d", options, 3, [&](const Scene& scene, Finished& f) {
    const auto& left = scene.bodies[0];
    const auto& right = scene.bodies[1];
    const double gamma = scene.materials[0].gamma;
    const exact::GasState L{left.density, 0.0, left.pressure.value_or(0.0)};
    const exact::GasState R{right.density, 0.0, right.pressure.value_or(0.0)};
    const exact::RiemannProblem riemann(L, R, gamma);
    const double x0 = left.shape.max[0];  // the interface
    const ParticleSet& p = f.particles;
    L1Accumulator l1;
    std::vector<std::vector<double>> rows;
    for (std::size_t i = 0; i < p.numReal; ++i) {
      const exact::GasState s = riemann.sample((p.x[0][i] - x0) / f.time);
      l1.add(p.mass[i] / p.rho[i], p.rho[i], p.v[0][i], p.P[i], s);
      rows.push_back({p.x[0][i], p.rho[i], p.v[0][i], p.P[i], s.rho, s.u, s.p});
    }
    std::sort(rows.begin(), rows.end());
    f.run.metrics = l1.metrics();
    writeProfile(options, "sod_1d", f.run, "x,rho,v,P,rho_exact,v_exact,P_exact", rows);
  });
}

// --- Sod, 2D circular (the seed's case) -------------------------------------------------------

// The reference is the 1D radial (cylindrical) Euler solution converged on 4000 cells
// (sim/exact/radial_euler.hpp; its own tests show 2000- and 4000-cell solutions agree to
// L1(rho) = 1.6e-4, far below the SPH errors measured here).
Report sod2d(const Options& options) {
  return convergenceStudy("sod_2d", options, 3, [&](const Scene& scene, Finished& f) {
    const auto& inner = scene.bodies[0];
    const auto& outer = scene.bodies[1];
    const double gamma = scene.materials[0].gamma;
    const double rMax = 1.5;  // beyond the box corners' distance is irrelevant: r < 1 is compared
    exact::RadialRiemannSolution reference(
        2, {inner.density, 0.0, inner.pressure.value_or(0.0)},
        {outer.density, 0.0, outer.pressure.value_or(0.0)}, inner.shape.radius, gamma, rMax, 6000);
    reference.advanceTo(f.time);
    const ParticleSet& p = f.particles;
    L1Accumulator l1;
    std::vector<std::vector<double>> rows;
    for (std::size_t i = 0; i < p.numReal; ++i) {
      const double dx = p.x[0][i] - inner.shape.center[0], dy = p.x[1][i] - inner.shape.center[1];
      const double r = std::hypot(dx, dy);
      if (r >= 1.0) continue;  // the walls' corners: outside the circle the reference describes
      const double vr = r > 0 ? (p.v[0][i] * dx + p.v[1][i] * dy) / r : 0.0;
      const exact::GasState s = reference.at(r);
      l1.add(p.mass[i] / p.rho[i], p.rho[i], vr, p.P[i], s);
      rows.push_back({r, p.rho[i], vr, p.P[i], s.rho, s.u, s.p});
    }
    std::sort(rows.begin(), rows.end());
    f.run.metrics = l1.metrics();
    writeProfile(options, "sod_2d", f.run, "r,rho,v_r,P,rho_ref,v_ref,P_ref", rows);
  });
}

// --- Plate impact: shock speed against the Hugoniot -------------------------------------------

Report plateImpact(const Options& options) {
  const std::string name = "plate_impact_al";
  const Scene scene = problemScene(name, options);
  const double V = scene.bodies[0].velocity[0];
  const double up = 0.5 * V;  // symmetric impact
  const double tFirst = 0.6 * scene.time.tEnd;
  double xFirst = 0.0, tAtFirst = 0.0;
  Finished f = runAt(scene, 1.0, options, [&](const Simulation& sim) {
    if (tAtFirst == 0.0 && sim.time() >= tFirst) {
      tAtFirst = sim.time();
      xFirst = waveFront(sim.particles(), 0.5 * up);
    }
  });
  const double us = (waveFront(f.particles, 0.5 * up) - xFirst) / (f.time - tAtFirst);
  // Shocked state behind the front, away from the contact and the front's smearing.
  const ParticleSet& p = f.particles;
  const double xContact = up * f.time, xFront = waveFront(p, 0.5 * up);
  double vSum = 0, PSum = 0;
  int n = 0;
  for (std::size_t i = 0; i < p.numReal; ++i) {
    const double x = p.x[0][i];
    if (x > xContact + 0.25 * (xFront - xContact) && x < xContact + 0.75 * (xFront - xContact)) {
      vSum += p.v[0][i];
      PSum += p.P[i];
      ++n;
    }
  }
  const double upMeasured = vSum / n, pressure = PSum / n;
  const auto& material = shockMaterial(scene.materials[0].library);
  const double usHugoniot = material.c0 + material.s1 * upMeasured;
  const double pHugoniot = material.rho0 * usHugoniot * upMeasured;
  f.run.metrics = {
      {"particle_velocity", upMeasured, "m/s"},
      {"shock_speed", us, "m/s"},
      {"shock_speed_hugoniot", usHugoniot, "m/s"},
      {"shock_speed_error", (us - usHugoniot) / usHugoniot, "1"},
      {"shock_pressure", pressure, "Pa"},
      {"shock_pressure_error", (pressure - pHugoniot) / pHugoniot, "1"},
  };
  return singleRunReport(name, scene,
                         "Al-2024 Hugoniot Us = C0 + s up (Steinberg 1996, from Marsh 1980)",
                         std::move(f.run));
}

// --- Sedov-Taylor blast -------------------------------------------------------------------------

// Geometry j of the similarity solution.
int sedovSymmetry(Geometry g) { return g == Geometry::Planar ? 2 : (g == Geometry::Line ? 1 : 3); }

// Samples the shock radius of every run at kHistorySamples times spread over the run (the first
// step at or after each), for the radius-against-time record of `ejecta verify --out`.
constexpr int kHistorySamples = 24;

Report sedov(const std::string& name, const Options& options, int defaultLevels,
             Coarsen what = Coarsen::Bodies) {
  std::vector<std::array<double, 2>> history;  // (t, shock radius) of the run in progress
  double nextSample = -1.0;  // < 0: the run has not started
  auto observer = [&](const Simulation& sim) {
    if (options.outDir.empty()) return;  // only written out, never measured against
    const Scene& scene = sim.scene();
    const double interval = scene.time.tEnd / kHistorySamples;
    if (nextSample < 0.0) nextSample = interval;
    if (sim.time() < nextSample) return;
    while (nextSample <= sim.time()) nextSample += interval;
    const auto& deposit = scene.deposits.at(0);
    const double spacing = scene.bodies[0].spacing;
    const double extent = scene.domain[0].max - scene.domain[0].min;
    history.push_back({sim.time(), blastShock(sim.particles(), deposit.center,
                                              spatialDimension(scene.geometry), spacing,
                                              extent).radius});
  };
  return convergenceStudy(name, options, defaultLevels, [&](const Scene& scene, Finished& f) {
    const ParticleSet& p = f.particles;
    const int dim = spatialDimension(scene.geometry);
    const double gamma = scene.materials[0].gamma;
    const double rho0 = scene.bodies[0].density;
    const auto& deposit = scene.deposits.at(0);
    const exact::SedovSolution sedovExact(sedovSymmetry(scene.geometry), gamma, deposit.energy,
                                          rho0);
    const double Rs = sedovExact.shockRadius(f.time);
    // Mean absolute density error over particles (the SPH-EXA benchmark's L1) and a binned
    // radial profile for the shock position and peak.
    double l1 = 0.0;
    std::vector<std::vector<double>> rows;
    for (std::size_t i = 0; i < p.numReal; ++i) {
      const double r = blastDistance(p, i, deposit.center, dim);
      const exact::SedovState s = sedovExact.at(r, f.time);
      l1 += std::abs(p.rho[i] - s.rho);
      rows.push_back({r, p.rho[i], p.P[i], s.rho, s.p});
    }
    l1 /= static_cast<double>(p.numReal);
    const BlastShock shock = blastShock(p, deposit.center, dim, f.run.spacing, 1.5 * Rs);
    std::sort(rows.begin(), rows.end());
    f.run.metrics = {
        {"L1_density", l1, "kg/m^3"},
        {"shock_radius", shock.radius, "m"},
        {"shock_radius_exact", Rs, "m"},
        {"shock_radius_error", (shock.radius - Rs) / Rs, "1"},
        {"peak_density_ratio", shock.density / sedovExact.postShockDensity(), "1"},
        {"peak_pressure_ratio", shock.pressure / sedovExact.postShockPressure(f.time), "1"},
        {"centre_pressure_ratio",
         centrePressureRatio(p, deposit.center, dim, sedovExact, f.time), "1"},
    };
    if (scene.geometry == Geometry::Axisymmetric) {
      // The axis of RZ: the largest particle pressure in the shell behind the shock (0.5 to 1.05
      // shock radii), among the rings within two spacings of the axis and among those more than
      // four spacings from it, each over the exact jump (docs/rz.md, "The axis behind a shock").
      const double spacing = f.run.spacing;
      double nearAxis = 0.0, offAxis = 0.0;
      for (std::size_t i = 0; i < p.numReal; ++i) {
        const double r = blastDistance(p, i, deposit.center, dim);
        if (r < 0.5 * Rs || r > 1.05 * Rs) continue;
        const double axisDistance = std::abs(p.x[0][i]);
        if (axisDistance < 2.0 * spacing) nearAxis = std::max(nearAxis, p.P[i]);
        if (axisDistance > 4.0 * spacing) offAxis = std::max(offAxis, p.P[i]);
      }
      const double jump = sedovExact.postShockPressure(f.time);
      f.run.metrics.push_back({"near_axis_peak_pressure_ratio", nearAxis / jump, "1"});
      f.run.metrics.push_back({"off_axis_peak_pressure_ratio", offAxis / jump, "1"});
    }
    writeProfile(options, name, f.run, "r,rho,P,rho_exact,P_exact", rows);
    std::vector<std::vector<double>> radii;
    for (const auto& [t, r] : history) radii.push_back({t, r, sedovExact.shockRadius(t)});
    writeProfile(options, name + "_shock_radius", f.run, "t_s,shock_radius_m,shock_radius_m_exact",
                 radii);
    history.clear();
    nextSample = -1.0;
  }, observer, what);
}

}  // namespace

const std::vector<Problem>& problems() {
  static const std::vector<Problem> list = {
      {"sod_1d", "Sod shock tube, 1D, t = 0.2 s, against the exact Riemann solution", 3, sod1d},
      {"sod_2d", "Sod, 2D circular (the seed's case: r = 0.4 m, t = 0.25 s), against the converged radial solution", 3, sod2d},
      {"plate_impact_al", "Al-2024 plate impact at 2 km/s, 1D: shock speed and pressure against the Hugoniot", 1, plateImpact},
      {"sedov_1d", "Sedov-Taylor blast, 1D (plane blast), the deposit two spacings wide at every level", 3,
       [](const Options& o) { return sedov("sedov_1d", o, 3, Coarsen::BodiesAndDeposits); }},
      {"sedov_2d", "Sedov-Taylor blast, 2D planar (cylindrical blast), against the similarity solution", 2,
       [](const Options& o) { return sedov("sedov_2d", o, 2); }},
      {"sedov_rz", "Sedov-Taylor blast, RZ (spherical blast), the seed's case", 2,
       [](const Options& o) { return sedov("sedov_rz", o, 2); }},
      {"sedov_3d", "Sedov-Taylor blast, 3D (spherical blast)", 1,
       [](const Options& o) { return sedov("sedov_3d", o, 1); }},
  };
  static const std::vector<Problem> all = [] {
    std::vector<Problem> out = list;
    for (const Problem& p : detail::strengthProblems()) out.push_back(p);
    for (const Problem& p : detail::sourceProblems()) out.push_back(p);
    for (const Problem& p : detail::porosityProblems()) out.push_back(p);
    for (const Problem& p : detail::undexProblems()) out.push_back(p);
    return out;
  }();
  return all;
}

Report runProblem(const std::string& name, const Options& options) {
  for (const Problem& p : problems())
    if (p.name == name) return p.run(options);
  throw std::invalid_argument("unknown verification problem '" + name + "' (known: " +
                              joinList(problems(), &Problem::name) + ")");
}

std::string reportJson(const Report& r) {
  std::ostringstream s;
  s.precision(8);
  s << "{\n  \"problem\": \"" << r.problem << "\",\n  \"description\": \"" << r.description
    << "\",\n  \"runs\": [\n";
  for (std::size_t k = 0; k < r.runs.size(); ++k) {
    const ResolutionRun& run = r.runs[k];
    s << "    {\"spacing\": " << run.spacing << ", \"particles\": " << run.particles
      << ", \"steps\": " << run.steps << ", \"particle_updates\": " << run.particleUpdates
      << ", \"wall_seconds\": " << run.wallSeconds
      << ", \"energy_error\": " << run.energyError << ", \"momentum_error\": " << run.momentumError;
    for (const Metric& m : run.metrics) s << ", \"" << m.name << "\": " << m.value;
    s << "}" << (k + 1 < r.runs.size() ? "," : "") << "\n";
  }
  s << "  ],\n  \"orders\": {";
  for (std::size_t k = 0; k < r.orders.size(); ++k)
    s << (k ? ", " : "") << "\"" << r.orders[k].name << "\": " << r.orders[k].value;
  s << "}\n}\n";
  return s.str();
}

std::string convergenceCsv(const Report& r) {
  std::ostringstream s;
  s.precision(10);
  if (r.runs.empty()) return s.str();
  const ResolutionRun& coarsest = r.runs.front();
  s << "spacing_m,particles,steps,wall_s,energy_error,momentum_error";
  for (const Metric& m : coarsest.metrics) s << "," << m.name;
  for (const Metric& m : coarsest.metrics)
    if (m.name.rfind("L1_", 0) == 0) s << "," << m.name << "_relative";
  s << ",first_order\n";
  for (const ResolutionRun& run : r.runs) {
    s << run.spacing << "," << run.particles << "," << run.steps << "," << run.wallSeconds << ","
      << run.energyError << "," << run.momentumError;
    for (const Metric& m : coarsest.metrics) s << "," << run.metric(m.name);
    for (const Metric& m : coarsest.metrics)
      if (m.name.rfind("L1_", 0) == 0) s << "," << run.metric(m.name) / m.value;
    s << "," << run.spacing / coarsest.spacing << "\n";
  }
  return s.str();
}

std::string reportTable(const Report& r) {
  std::ostringstream s;
  s << r.problem << ": " << r.description << "\n";
  char line[512];
  for (const ResolutionRun& run : r.runs) {
    std::snprintf(line, sizeof line, "  N = %8zu  spacing = %-10.4g steps = %-6ld wall = %7.2f s  dE/E = %+.2e  dP = %.1e\n",
                  run.particles, run.spacing, run.steps, run.wallSeconds, run.energyError,
                  run.momentumError);
    s << line;
    for (const Metric& m : run.metrics) {
      std::snprintf(line, sizeof line, "      %-22s %14.6g %s\n", m.name.c_str(), m.value, m.unit.c_str());
      s << line;
    }
  }
  for (const Metric& m : r.orders) {
    std::snprintf(line, sizeof line, "  %-30s %8.3f\n", m.name.c_str(), m.value);
    s << line;
  }
  return s.str();
}

std::string markdownHeader() {
  return "| problem | N | wall [s] | L1(rho) | L1(v) | L1(P) | order L1(rho) | shock radius error | "
         "peak rho / exact | energy error |\n"
         "|---|---|---|---|---|---|---|---|---|---|\n";
}

std::string markdownRow(const Report& r) {
  const ResolutionRun& run = r.runs.back();
  auto value = [&](const std::string& name, const char* format) -> std::string {
    for (const Metric& m : run.metrics)
      if (m.name == name) {
        char buf[64];
        std::snprintf(buf, sizeof buf, format, m.value);
        return buf;
      }
    return "-";
  };
  std::string order = "-";
  const std::string finest = "order_L1_density_" + std::to_string(r.runs.size() - 1);
  for (const Metric& m : r.orders)
    if (m.name == finest) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.2f", m.value);
      order = buf;
    }
  char head[160];
  std::snprintf(head, sizeof head, "| %s | %zu | %.1f | ", r.problem.c_str(), run.particles,
                run.wallSeconds);
  char tail[64];
  std::snprintf(tail, sizeof tail, " | %.1e |\n", run.energyError);
  return head + value("L1_density", "%.4f") + " | " + value("L1_velocity", "%.4f") + " | " +
         value("L1_pressure", "%.4f") + " | " + order + " | " +
         value("shock_radius_error", "%+.3f") + " | " + value("peak_density_ratio", "%.2f") + tail;
}

}  // namespace ejecta::verify
