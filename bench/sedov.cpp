// 3D Sedov benchmark on the standard problem of SPH-EXA: periodic cube [-0.5, 0.5]^3, n^3
// particles on a cell-centred cubic lattice, rho0 = 1, m = 1/N, gamma = 5/3, v = 0,
// u = E0 / (pi^1.5 w^3) exp(-r^2/w^2) + 1e-8 with E0 = 1, w = 0.1, run to t = 0.05
// (exact shock radius 0.3475, peak density 4).
// Prints N, steps, mean neighbours, wall time, particle-updates per second (the particle-steps
// over the wall time: N x steps with global steps, the active particles' updates with
// individual ones), the L1 density error (mean over particles of |rho - rho_exact(r)|), the
// binned peak density over the jump and the hot centre's median pressure over the exact.
//
//   ejecta_bench_sedov [--n 50] [--threads T] [--kernel cubic_spline|wendland_c2|wendland_c4]
//                      [--eta 1.2] [--t-end 0.05] [--conductivity A] [--balsara 0|1] [--json]
//                      [--stepping global|individual] [--limiter-factor F]
//                      [--alpha A] [--beta B] [--switch none|morris_monaghan]
//                      [--reconstruction none|monotone|van_leer]   (default none; monotone
//                      with --dissipation riemann, as in a scene)
//                      [--gradients kernel|iad]
//                      [--volume-exponent P]   (generalised volume elements X = (m/rho)^P)
//                      [--dissipation viscosity|riemann]   (riemann: Godunov SPH)
//   ejecta_bench_sedov --chart DIR [--threads T]
//
// --chart: the accuracy-for-cost chart of issue 19: the kernel gradient (the default), with
// Balsara's switch, with the monotone reconstructed viscosity, with integral-approach gradients,
// and Godunov SPH (the Riemann-solver dissipation) with global steps and on time bins (with its
// reconstruction and without), each at n = 30, 40 and 50, into DIR/sedov_3d_<variant>.csv (n, N, wall_s, particle_updates,
// L1_density, peak_density_ratio, peak_pressure_ratio, centre_pressure_ratio) and
// DIR/sedov_3d_error_vs_cost.png (L1 against wall time, one line per variant, the peers'
// published L1 at N = 125,000 as dashed lines). About 6 minutes on 2 cores.
#include <array>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <vector>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <numbers>
#include <string>

#include "bench/arguments.hpp"
#include "sim/exact/sedov.hpp"
#include "sim/run/run.hpp"
#include "sim/run/simulation.hpp"
#include "sim/verify/blast_metrics.hpp"
#include "render/charts.hpp"

using namespace ejecta;

namespace {

struct Config {
  double eta = 1.2, tEnd = 0.05, conductivity = 0.0, alpha = 1.0, beta = 2.0;
  bool balsara = false;
  std::string kernel = "cubic_spline", stepping = "global", viscositySwitch = "none",
              reconstruction = "", gradients = "kernel", dissipation = "viscosity";
  int limiterFactor = 2;
  double volumeExponent = std::nan("");  // unset: the standard (mass) volumes
};

struct Result {
  std::size_t N = 0;
  long steps = 0;
  double meanNeighbours = 0.0, wall = 0.0, l1 = 0.0, energyError = 0.0, shockRadius = 0.0;
  double peakDensityRatio = 0.0, peakPressureRatio = 0.0, centrePressureRatio = 0.0;  // blast_metrics.hpp
  double particleSteps = 0.0;
  int threads = 1;
  bool individual = false;
};

// The scene of the options, or a message naming the bad one.
std::string configure(const Config& c, Scene& scene) {
  scene.name = "bench_sedov_3d";
  scene.geometry = Geometry::Spatial;
  for (int d = 0; d < 3; ++d)
    scene.domain[d] = {-0.5, 0.5, BoundaryKind::Periodic, BoundaryKind::Periodic, true};
  scene.sph.kernel = c.kernel == "wendland_c2"   ? KernelKind::WendlandC2
                     : c.kernel == "wendland_c4" ? KernelKind::WendlandC4
                                                 : KernelKind::CubicSpline;
  scene.sph.eta = c.eta;
  scene.sph.conductivity = c.conductivity;
  scene.sph.balsara = c.balsara;
  scene.sph.alpha = c.alpha;
  scene.sph.beta = c.beta;
  if (c.viscositySwitch != "none" && c.viscositySwitch != "morris_monaghan")
    return "--switch must be none or morris_monaghan, not " + c.viscositySwitch;
  scene.sph.viscositySwitch =
      c.viscositySwitch == "morris_monaghan" ? ViscositySwitch::MorrisMonaghan : ViscositySwitch::None;
  // Unset: none, or monotone with the Riemann dissipation (the scene reader's default).
  const std::string reconstruction = !c.reconstruction.empty() ? c.reconstruction
                                     : c.dissipation == "riemann" ? "monotone"
                                                                  : "none";
  if (reconstruction == "monotone") scene.sph.viscosityReconstruction = ViscosityReconstruction::Monotone;
  else if (reconstruction == "van_leer") scene.sph.viscosityReconstruction = ViscosityReconstruction::VanLeer;
  else if (reconstruction != "none")
    return "--reconstruction must be none, monotone or van_leer, not " + reconstruction;
  if (c.gradients != "kernel" && c.gradients != "iad")
    return "--gradients must be kernel or iad, not " + c.gradients;
  scene.sph.gradients = c.gradients == "iad" ? GradientScheme::IntegralApproach : GradientScheme::Kernel;
  if (!std::isnan(c.volumeExponent)) {
    if (!(c.volumeExponent >= 0.0 && c.volumeExponent <= 1.0))
      return "--volume-exponent must lie in [0, 1]";
    scene.sph.volumeElements = VolumeElements::Generalised;
    scene.sph.volumeExponent = c.volumeExponent;
  }
  if (c.dissipation != "viscosity" && c.dissipation != "riemann")
    return "--dissipation must be viscosity or riemann, not " + c.dissipation;
  scene.sph.dissipation =
      c.dissipation == "riemann" ? Dissipation::Riemann : Dissipation::Viscosity;
  scene.time.tEnd = c.tEnd;
  if (c.stepping != "global" && c.stepping != "individual")
    return "--stepping must be global or individual, not " + c.stepping;
  scene.time.stepping = c.stepping == "individual" ? Stepping::Individual : Stepping::Global;
  scene.time.limiterFactor = c.limiterFactor;
  scene.output.snapshots = false;
  return "";
}

Result runSedov(const Scene& scene, int n, int threads) {
  const double gamma = 5.0 / 3.0;
  Scene withGas = scene;
  MaterialSpec gas;
  gas.name = "gas";
  gas.gamma = gamma;
  withGas.materials.push_back(gas);
  MaterialTable materials = MaterialTable::fromScene(withGas);

  const double E0 = 1.0, w = 0.1, dx = 1.0 / n;
  const std::size_t N = static_cast<std::size_t>(n) * n * n;
  const double m = 1.0 / static_cast<double>(N);
  const double uPeak = E0 / (std::pow(std::numbers::pi, 1.5) * w * w * w);
  ParticleSet p;
  p.resize(N);
  std::size_t i = 0;
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b)
      for (int c = 0; c < n; ++c, ++i) {
        const double x = -0.5 + (a + 0.5) * dx, y = -0.5 + (b + 0.5) * dx, z = -0.5 + (c + 0.5) * dx;
        p.x[0][i] = x; p.x[1][i] = y; p.x[2][i] = z;
        p.mass[i] = m;
        p.rho[i] = 1.0;
        p.u[i] = uPeak * std::exp(-(x * x + y * y + z * z) / (w * w)) + 1e-8;
        p.h[i] = withGas.sph.eta * dx;
        p.id[i] = static_cast<std::int64_t>(i);
      }
  p.numReal = N;

  Result r;
  r.threads = resolveThreads(threads);
  Simulation sim(withGas, std::move(p), std::move(materials), r.threads);
  RunOptions options;
  options.threads = r.threads;
  const auto start = std::chrono::steady_clock::now();
  const RunOutcome outcome = runSimulation(sim, options);
  r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!outcome.ok) {
    std::fprintf(stderr, "run failed: %s\n", outcome.error.c_str());
    std::exit(1);
  }
  const exact::SedovSolution sedov(3, gamma, E0, 1.0);
  const ParticleSet& q = sim.particles();
  const std::array<double, 3> origin{0.0, 0.0, 0.0};
  for (std::size_t k = 0; k < q.numReal; ++k)
    r.l1 += std::abs(q.rho[k] - sedov.at(verify::blastDistance(q, k, origin, 3), sim.time()).rho);
  r.l1 /= static_cast<double>(q.numReal);
  // The binned peak over the strong-shock jump (gamma + 1)/(gamma - 1) = 4, bins one spacing wide.
  const verify::BlastShock shock = verify::blastShock(q, origin, 3, dx, 0.5);
  r.peakDensityRatio = shock.density / sedov.postShockDensity();
  r.peakPressureRatio = shock.pressure / sedov.postShockPressure(sim.time());
  r.centrePressureRatio = verify::centrePressureRatio(q, origin, 3, sedov, sim.time());
  r.N = N;
  r.steps = sim.stepCount();
  r.meanNeighbours = sim.meanNeighbours();
  r.particleSteps = static_cast<double>(sim.particleUpdates());
  r.energyError = outcome.summary.energy.relativeError;
  r.shockRadius = sedov.shockRadius(sim.time());
  r.individual = sim.individualSteps();
  return r;
}

// The accuracy-for-cost chart (see the header).
int chart(const std::filesystem::path& dir, int threads) {
  struct Variant {
    std::string name, label;
    Config config;
  };
  std::vector<Variant> variants(7);
  variants[0] = {"kernel", "kernel gradient (default)", {}};
  variants[1] = {"balsara", "Balsara switch", {}};
  variants[1].config.balsara = true;
  variants[2] = {"monotone", "monotone reconstructed viscosity", {}};
  variants[2].config.reconstruction = "monotone";
  variants[3] = {"iad", "integral-approach gradients", {}};
  variants[3].config.gradients = "iad";
  variants[4] = {"riemann", "Godunov SPH, global steps", {}};
  variants[4].config.dissipation = "riemann";
  variants[5] = {"riemann_bins", "Godunov SPH, time bins", {}};
  variants[5].config.dissipation = "riemann";
  variants[5].config.stepping = "individual";
  variants[6] = {"riemann_bins_first_order", "Godunov SPH, time bins, not reconstructed", {}};
  variants[6].config = variants[5].config;
  variants[6].config.reconstruction = "none";
  std::filesystem::create_directories(dir);
  render::ChartSpec spec;
  spec.x = "wall_s";
  spec.xlog = spec.ylog = true;
  spec.xlabel = "wall time [s]";
  spec.ylabel = "L1(rho)";
  spec.title = "3D Sedov (SPH-EXA problem), n = 30, 40, 50";
  for (const Variant& v : variants) {
    Scene scene;
    const std::string bad = configure(v.config, scene);
    if (!bad.empty()) { std::fprintf(stderr, "%s\n", bad.c_str()); return 2; }
    const std::filesystem::path csv = dir / ("sedov_3d_" + v.name + ".csv");
    const std::filesystem::path partial = dir / ("sedov_3d_" + v.name + ".csv.part");
    {
      std::ofstream out(partial);
      out << "n,N,wall_s,particle_updates,L1_density,peak_density_ratio,peak_pressure_ratio,"
             "centre_pressure_ratio\n";
      for (int n : {30, 40, 50}) {
        const Result r = runSedov(scene, n, threads);
        std::printf("%-34s n %d: L1 %.4f, %.1f s (%d threads)\n", v.label.c_str(), n, r.l1, r.wall,
                    r.threads);
        std::fflush(stdout);
        out << n << "," << r.N << "," << r.wall << "," << r.particleSteps << "," << r.l1 << ","
            << r.peakDensityRatio << "," << r.peakPressureRatio << "," << r.centrePressureRatio
            << "\n";
      }
    }
    std::filesystem::rename(partial, csv);
    spec.series.push_back({.y = "L1_density", .label = v.label, .csv = csv, .markers = true});
  }
  spec.csv = spec.series.front().csv;
  // Published at N = 125,000 (README, "Speed": built and run on this machine's 2 cores).
  spec.hlines = {{0.090, "L1 0.090: SPH-EXA, IAD + volume elements, N = 125k"},
                 {0.107, "L1 0.107: SPH-EXA, standard SPH, N = 125k"},
                 {0.108, "L1 0.108: SWIFT, N = 125k"}};
  spec.out = dir / "sedov_3d_error_vs_cost.png";
  render::ChartRunner charts;
  if (!charts.chartsAvailable()) {
    std::printf("no chart (%s); the CSVs are in %s\n", charts.unavailableReason().c_str(), dir.c_str());
    return 0;
  }
  charts.writeChart(spec);
  std::printf("chart: %s\n", spec.out.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  int n = 50, threads = 0;
  bool json = false;
  Config c;
  std::string chartDir;
  bench::Arguments args(argc, argv);
  for (std::string arg; args.next(arg);) {
    auto next = [&args] { return args.value(); };
    if (arg == "--n") n = std::atoi(next());
    else if (arg == "--threads") threads = std::atoi(next());
    else if (arg == "--eta") c.eta = std::atof(next());
    else if (arg == "--t-end") c.tEnd = std::atof(next());
    else if (arg == "--kernel") c.kernel = next();
    else if (arg == "--conductivity") c.conductivity = std::atof(next());
    else if (arg == "--balsara") c.balsara = std::atoi(next()) != 0;
    else if (arg == "--json") json = true;
    else if (arg == "--stepping") c.stepping = next();
    else if (arg == "--limiter-factor") c.limiterFactor = std::atoi(next());
    else if (arg == "--alpha") c.alpha = std::atof(next());
    else if (arg == "--beta") c.beta = std::atof(next());
    else if (arg == "--switch") c.viscositySwitch = next();
    else if (arg == "--reconstruction") c.reconstruction = next();
    else if (arg == "--gradients") c.gradients = next();
    else if (arg == "--volume-exponent") c.volumeExponent = std::atof(next());
    else if (arg == "--dissipation") c.dissipation = next();
    else if (arg == "--chart") chartDir = next();
    else { std::fprintf(stderr, "unknown option %s\n", arg.c_str()); return 2; }
  }
  try {
    if (!chartDir.empty()) return chart(chartDir, threads);
  } catch (const std::exception& e) {  // a combination the simulation refuses
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }

  Scene scene;
  const std::string bad = configure(c, scene);
  if (!bad.empty()) { std::fprintf(stderr, "%s\n", bad.c_str()); return 2; }
  Result r;
  try {
    r = runSedov(scene, n, threads);
  } catch (const std::exception& e) {  // a combination the simulation refuses
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  const double updates = r.particleSteps / r.wall;
  if (json) {
    std::printf("{\"N\": %zu, \"steps\": %ld, \"mean_neighbours\": %.1f, \"wall_seconds\": %.3f, "
                "\"threads\": %d, \"particle_updates_per_second\": %.4g, "
                "\"updates_per_second_per_core\": %.4g, \"L1_density\": %.4f, "
                "\"energy_error\": %.3g, \"shock_radius_exact\": %.4f, \"stepping\": \"%s\", "
                "\"particle_steps\": %.6g, \"peak_density_ratio\": %.4f, "
                "\"peak_pressure_ratio\": %.4f, \"centre_pressure_ratio\": %.3f}\n",
                r.N, r.steps, r.meanNeighbours, r.wall, r.threads, updates, updates / r.threads, r.l1,
                r.energyError, r.shockRadius, c.stepping.c_str(), r.particleSteps,
                r.peakDensityRatio, r.peakPressureRatio, r.centrePressureRatio);
  } else {
    std::printf("3D Sedov (SPH-EXA standard problem), kernel %s, eta %.3g\n", c.kernel.c_str(), c.eta);
    std::printf("  N                          %zu\n", r.N);
    std::printf("  stepping                   %s\n", c.stepping.c_str());
    std::printf("  steps                      %ld%s\n", r.steps, r.individual ? " (sub-steps)" : "");
    std::printf("  particle-steps             %.6g (%.3g N)\n", r.particleSteps,
                r.particleSteps / static_cast<double>(r.N));
    std::printf("  mean neighbours            %.1f\n", r.meanNeighbours);
    std::printf("  threads                    %d\n", r.threads);
    std::printf("  wall time                  %.2f s\n", r.wall);
    std::printf("  particle-updates/s         %.4g  (%.4g per core)\n", updates, updates / r.threads);
    std::printf("  L1 density error           %.4f\n", r.l1);
    std::printf("  peak density / jump        %.3f\n", r.peakDensityRatio);
    std::printf("  peak pressure / jump       %.3f  (the shell's bins)\n", r.peakPressureRatio);
    std::printf("  centre pressure / exact    %.2f  (median of the 32 innermost)\n", r.centrePressureRatio);
    std::printf("  energy error               %.3g\n", r.energyError);
  }
  return 0;
}
