// The kinetic-impact scene with strength and fracture, next to the same scene hydro-only: what
// the solid mechanics costs per step. The scene (default scenes/impact_rz.toml) is run twice for
// --steps steps: as it is, and with every material's [strength] and [fracture] tables and every
// body's initial damage removed (pure hydrodynamics with the same equations of state). Only the
// stepping is timed (steady_clock), not building the particles or the first derivatives.
// Prints particles, steps, wall, particle-updates per second (particles x steps / wall) and per
// core for each, and the overhead ratio (hydro / solid throughput). --threads-sweep runs both at
// 1 and 2 threads and prints the 2-thread / 1-thread throughput ratio.
//
//   ejecta_bench_impact [--geometry rz|2d|3d] [--scene PATH] [--set key=value ...]
//                       [--steps 40] [--threads T] [--threads-sweep] [--json]
// --geometry picks scenes/impact_rz.toml, impact_2d.toml or impact_3d_oblique.toml (3D: about
// 0.7 s per step on 2 cores, so --steps defaults to 5 there).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "bench/arguments.hpp"
#include "sim/setup/bodies.hpp"
#include "sim/run/run.hpp"
#include "sim/run/simulation.hpp"

using namespace ejecta;

namespace {

struct Options {
  std::string geometry = "rz";
  std::string scene;                    // empty: the geometry's scene
  std::vector<std::string> overrides;   // --set
  int steps = 0;                        // 0: 40, 3D 5
  int threads = 0;
  bool sweep = false;
  bool json = false;
};

Options parseOptions(int argc, char** argv) {
  Options o;
  bench::Arguments args(argc, argv);
  for (std::string arg; args.next(arg);) {
    auto next = [&args] { return args.value(); };
    if (arg == "--geometry") o.geometry = next();
    else if (arg == "--scene") o.scene = next();
    else if (arg == "--set") o.overrides.push_back(next());
    else if (arg == "--steps") o.steps = std::atoi(next());
    else if (arg == "--threads") o.threads = std::atoi(next());
    else if (arg == "--threads-sweep") o.sweep = true;
    else if (arg == "--json") o.json = true;
    else { std::fprintf(stderr, "unknown option %s\n", arg.c_str()); std::exit(2); }
  }
  if (o.geometry != "rz" && o.geometry != "2d" && o.geometry != "3d") {
    std::fprintf(stderr, "--geometry: rz, 2d or 3d\n");
    std::exit(2);
  }
  if (o.scene.empty())
    o.scene = std::string(EJECTA_SOURCE_DIR "/scenes/") +
              (o.geometry == "3d" ? "impact_3d_oblique" : "impact_" + o.geometry) + ".toml";
  if (o.steps <= 0) o.steps = o.geometry == "3d" ? 5 : 40;
  return o;
}

// The scene with an end time no step of the bench reaches, so the steps are never shortened to
// land on it; the dt_min health check keeps the value the scene's own t_end gave it.
Scene benchScene(const Options& o) {
  Scene scene = loadScene(o.scene, o.overrides);
  if (scene.time.dtMin <= 0.0) scene.time.dtMin = 1e-12 * scene.time.tEnd;
  scene.time.tEnd = 1e6 * scene.time.tEnd;
  scene.output.snapshots = false;
  return scene;
}

// The same scene without solid mechanics (sim/solid/materials.cpp: an absent table is no model). The
// rubble crust's initial damage goes too: without it no fracture arrays are allocated at all.
Scene hydroOnly(Scene scene) {
  for (MaterialSpec& m : scene.materials) {
    m.strength = ModelSpec{};
    m.fracture = ModelSpec{};
  }
  for (BodySpec& b : scene.bodies) b.damage = 0.0;
  return scene;
}

struct Result {
  std::string variant;
  int threads = 0;
  std::size_t particles = 0;
  long steps = 0;
  double wall = 0.0;        // [s], stepping only
  double simulated = 0.0;   // [s] of physical time covered
  double meanNeighbours = 0.0;
  std::string error;        // a SimulationError, if the run failed

  double updatesPerSecond() const {
    return wall > 0.0 ? static_cast<double>(particles) * static_cast<double>(steps) / wall : 0.0;
  }
};

// Builds the simulation as runScene does (not timed), then times `steps` steps.
Result stepScene(const Scene& scene, const std::string& variant, int steps, int threads) {
  Result r;
  r.variant = variant;
  r.threads = threads;
  MaterialTable materials = MaterialTable::fromScene(scene);
  ParticleSet particles = buildParticles(scene, materials);
  Simulation sim(scene, std::move(particles), std::move(materials), threads);
  r.particles = sim.particles().numReal;
  try {
    sim.initialise();
    const double t0 = sim.time();
    const auto start = std::chrono::steady_clock::now();
    for (int s = 0; s < steps; ++s) sim.step(scene.time.tEnd);
    r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.simulated = sim.time() - t0;
  } catch (const SimulationError& e) {
    r.error = e.what();
  }
  r.steps = sim.stepCount();
  r.meanNeighbours = sim.meanNeighbours();
  return r;
}

void printHuman(const Options& o, const Scene& scene, const std::vector<Result>& results) {
  std::printf("Kinetic impact %s (%s), %d steps: strength + fracture vs hydro-only\n",
              scene.name.c_str(), o.scene.c_str(), o.steps);
  std::printf("  %-8s %7s %9s %6s %9s %10s %12s %16s %12s\n", "variant", "threads", "particles",
              "steps", "wall [s]", "sim [us]", "updates/s", "updates/s/core", "neighbours");
  for (const Result& r : results) {
    if (!r.error.empty()) {
      std::printf("  %-8s %7d failed: %s\n", r.variant.c_str(), r.threads, r.error.c_str());
      continue;
    }
    std::printf("  %-8s %7d %9zu %6ld %9.3f %10.1f %12.4g %16.4g %12.1f\n", r.variant.c_str(),
                r.threads, r.particles, r.steps, r.wall, r.simulated * 1e6, r.updatesPerSecond(),
                r.updatesPerSecond() / r.threads, r.meanNeighbours);
  }
  // Results come in (solid, hydro) pairs per thread count.
  for (std::size_t k = 0; k + 1 < results.size(); k += 2)
    std::printf("  overhead of strength + fracture at %d thread(s): hydro / solid throughput = %.2f\n",
                results[k].threads, results[k + 1].updatesPerSecond() / results[k].updatesPerSecond());
  if (results.size() == 4)
    std::printf("  throughput 2 threads / 1 thread: solid %.2f, hydro %.2f\n",
                results[2].updatesPerSecond() / results[0].updatesPerSecond(),
                results[3].updatesPerSecond() / results[1].updatesPerSecond());
  std::printf("  for the hydro-only reference problem: ejecta_bench_sedov --n 40\n");
}

void printJson(const Options& o, const Scene& scene, const std::vector<Result>& results) {
  std::printf("{\"scene\": \"%s\", \"path\": \"%s\", \"steps\": %d, \"runs\": [", scene.name.c_str(),
              o.scene.c_str(), o.steps);
  for (std::size_t k = 0; k < results.size(); ++k) {
    const Result& r = results[k];
    std::printf("%s{\"variant\": \"%s\", \"threads\": %d, \"particles\": %zu, \"steps\": %ld, "
                "\"wall_seconds\": %.4g, \"simulated_seconds\": %.4g, "
                "\"particle_updates_per_second\": %.4g, \"updates_per_second_per_core\": %.4g, "
                "\"mean_neighbours\": %.1f, \"ok\": %s}",
                k ? ", " : "", r.variant.c_str(), r.threads, r.particles, r.steps, r.wall,
                r.simulated, r.updatesPerSecond(), r.updatesPerSecond() / r.threads,
                r.meanNeighbours, r.error.empty() ? "true" : "false");
  }
  std::printf("], \"overhead_hydro_over_solid\": {");
  for (std::size_t k = 0; k + 1 < results.size(); k += 2)
    std::printf("%s\"%d\": %.3f", k ? ", " : "", results[k].threads,
                results[k + 1].updatesPerSecond() / results[k].updatesPerSecond());
  std::printf("}}\n");
}

}  // namespace

int main(int argc, char** argv) try {
  const Options o = parseOptions(argc, argv);
  const Scene solid = benchScene(o);
  const Scene hydro = hydroOnly(solid);

  std::vector<int> threadCounts{resolveThreads(o.threads)};
  if (o.sweep) threadCounts = {1, 2};
  std::vector<Result> results;
  for (int t : threadCounts) {
    results.push_back(stepScene(solid, "solid", o.steps, t));
    results.push_back(stepScene(hydro, "hydro", o.steps, t));
  }
  if (o.json) printJson(o, solid, results);
  else printHuman(o, solid, results);
  for (const Result& r : results)
    if (!r.error.empty()) return 1;
  return 0;
} catch (const std::exception& e) {  // a bad scene (SceneError) or model table
  std::fprintf(stderr, "ejecta_bench_impact: %s\n", e.what());
  return 1;
}
