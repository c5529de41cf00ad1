// 3D Sedov benchmark on the standard problem of SPH-EXA: periodic cube [-0.5, 0.5]^3, n^3
// particles on a cell-centred cubic lattice, rho0 = 1, m = 1/N, gamma = 5/3, v = 0,
// u = E0 / (pi^1.5 w^3) exp(-r^2/w^2) + 1e-8 with E0 = 1, w = 0.1, run to t = 0.05
// (exact shock radius 0.3475, peak density 4).
// Prints N, steps, mean neighbours, wall time, particle-updates per second (the particle-steps
// over the wall time: N x steps with global steps, the active particles' updates with
// individual ones) and the L1 density error (mean over particles of |rho - rho_exact(r)|).
//
//   ejecta_bench_sedov [--n 50] [--threads T] [--kernel cubic_spline|wendland_c2|wendland_c4]
//                      [--eta 1.2] [--t-end 0.05] [--conductivity A] [--balsara 0|1] [--json]
//                      [--stepping global|individual] [--limiter-factor F]
//                      [--alpha A] [--beta B] [--switch none|morris_monaghan]
//                      [--reconstruction none|monotone|van_leer] [--gradients kernel|iad]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <numbers>
#include <string>

#include "bench/arguments.hpp"
#include "sim/exact/sedov.hpp"
#include "sim/run/run.hpp"
#include "sim/run/simulation.hpp"

using namespace ejecta;

int main(int argc, char** argv) {
  int n = 50, threads = 0;
  double eta = 1.2, tEnd = 0.05, conductivity = 0.0;
  bool balsara = false, json = false;
  std::string kernel = "cubic_spline", stepping = "global";
  int limiterFactor = 2;
  double alpha = 1.0, beta = 2.0;
  std::string viscositySwitch = "none", reconstruction = "none", gradients = "kernel";
  bench::Arguments args(argc, argv);
  for (std::string arg; args.next(arg);) {
    auto next = [&args] { return args.value(); };
    if (arg == "--n") n = std::atoi(next());
    else if (arg == "--threads") threads = std::atoi(next());
    else if (arg == "--eta") eta = std::atof(next());
    else if (arg == "--t-end") tEnd = std::atof(next());
    else if (arg == "--kernel") kernel = next();
    else if (arg == "--conductivity") conductivity = std::atof(next());
    else if (arg == "--balsara") balsara = std::atoi(next()) != 0;
    else if (arg == "--json") json = true;
    else if (arg == "--stepping") stepping = next();
    else if (arg == "--limiter-factor") limiterFactor = std::atoi(next());
    else if (arg == "--alpha") alpha = std::atof(next());
    else if (arg == "--beta") beta = std::atof(next());
    else if (arg == "--switch") viscositySwitch = next();
    else if (arg == "--reconstruction") reconstruction = next();
    else if (arg == "--gradients") gradients = next();
    else { std::fprintf(stderr, "unknown option %s\n", arg.c_str()); return 2; }
  }

  Scene scene;
  scene.name = "bench_sedov_3d";
  scene.geometry = Geometry::Spatial;
  for (int d = 0; d < 3; ++d)
    scene.domain[d] = {-0.5, 0.5, BoundaryKind::Periodic, BoundaryKind::Periodic, true};
  scene.sph.kernel = kernel == "wendland_c2"   ? KernelKind::WendlandC2
                     : kernel == "wendland_c4" ? KernelKind::WendlandC4
                                               : KernelKind::CubicSpline;
  scene.sph.eta = eta;
  scene.sph.conductivity = conductivity;
  scene.sph.balsara = balsara;
  scene.sph.alpha = alpha;
  scene.sph.beta = beta;
  if (viscositySwitch != "none" && viscositySwitch != "morris_monaghan") {
    std::fprintf(stderr, "--switch must be none or morris_monaghan, not %s\n", viscositySwitch.c_str());
    return 2;
  }
  scene.sph.viscositySwitch =
      viscositySwitch == "morris_monaghan" ? ViscositySwitch::MorrisMonaghan : ViscositySwitch::None;
  if (reconstruction == "monotone") scene.sph.viscosityReconstruction = ViscosityReconstruction::Monotone;
  else if (reconstruction == "van_leer") scene.sph.viscosityReconstruction = ViscosityReconstruction::VanLeer;
  else if (reconstruction != "none") {
    std::fprintf(stderr, "--reconstruction must be none, monotone or van_leer, not %s\n",
                 reconstruction.c_str());
    return 2;
  }
  if (gradients != "kernel" && gradients != "iad") {
    std::fprintf(stderr, "--gradients must be kernel or iad, not %s\n", gradients.c_str());
    return 2;
  }
  scene.sph.gradients = gradients == "iad" ? GradientScheme::IntegralApproach : GradientScheme::Kernel;
  scene.time.tEnd = tEnd;
  if (stepping != "global" && stepping != "individual") {
    std::fprintf(stderr, "--stepping must be global or individual, not %s\n", stepping.c_str());
    return 2;
  }
  scene.time.stepping = stepping == "individual" ? Stepping::Individual : Stepping::Global;
  scene.time.limiterFactor = limiterFactor;
  scene.output.snapshots = false;
  const double gamma = 5.0 / 3.0;
  MaterialSpec gas;
  gas.name = "gas";
  gas.gamma = gamma;
  scene.materials.push_back(gas);
  MaterialTable materials = MaterialTable::fromScene(scene);

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
        p.h[i] = eta * dx;
        p.id[i] = static_cast<std::int64_t>(i);
      }
  p.numReal = N;

  const int nThreads = resolveThreads(threads);
  Simulation sim(scene, std::move(p), std::move(materials), nThreads);
  RunOptions options;
  options.threads = nThreads;
  const auto start = std::chrono::steady_clock::now();
  const RunOutcome outcome = runSimulation(sim, options);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!outcome.ok) { std::fprintf(stderr, "run failed: %s\n", outcome.error.c_str()); return 1; }

  const exact::SedovSolution sedov(3, gamma, E0, 1.0);
  const ParticleSet& q = sim.particles();
  double l1 = 0.0;
  for (std::size_t k = 0; k < q.numReal; ++k) {
    const double r = std::sqrt(q.x[0][k] * q.x[0][k] + q.x[1][k] * q.x[1][k] + q.x[2][k] * q.x[2][k]);
    l1 += std::abs(q.rho[k] - sedov.at(r, sim.time()).rho);
  }
  l1 /= static_cast<double>(q.numReal);
  const double particleSteps = static_cast<double>(sim.particleUpdates());
  const double updates = particleSteps / wall;
  if (json) {
    std::printf("{\"N\": %zu, \"steps\": %ld, \"mean_neighbours\": %.1f, \"wall_seconds\": %.3f, "
                "\"threads\": %d, \"particle_updates_per_second\": %.4g, "
                "\"updates_per_second_per_core\": %.4g, \"L1_density\": %.4f, "
                "\"energy_error\": %.3g, \"shock_radius_exact\": %.4f, \"stepping\": \"%s\", "
                "\"particle_steps\": %.6g}\n",
                N, sim.stepCount(), sim.meanNeighbours(), wall, nThreads, updates,
                updates / nThreads, l1, outcome.summary.energy.relativeError,
                sedov.shockRadius(sim.time()), stepping.c_str(), particleSteps);
  } else {
    std::printf("3D Sedov (SPH-EXA standard problem), kernel %s, eta %.3g\n", kernel.c_str(), eta);
    std::printf("  N                          %zu\n", N);
    std::printf("  stepping                   %s\n", stepping.c_str());
    std::printf("  steps                      %ld%s\n", sim.stepCount(),
                sim.individualSteps() ? " (sub-steps)" : "");
    std::printf("  particle-steps             %.6g (%.3g N)\n", particleSteps,
                particleSteps / static_cast<double>(N));
    std::printf("  mean neighbours            %.1f\n", sim.meanNeighbours());
    std::printf("  threads                    %d\n", nThreads);
    std::printf("  wall time                  %.2f s\n", wall);
    std::printf("  particle-updates/s         %.4g  (%.4g per core)\n", updates, updates / nThreads);
    std::printf("  L1 density error           %.4f\n", l1);
    std::printf("  energy error               %.3g\n", outcome.summary.energy.relativeError);
  }
  return 0;
}
