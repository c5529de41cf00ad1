// Wall heat solvers (radiation/, issue 6): throughput, accuracy against wall time, and shield
// sizing on the seed's example. Each phase is timed with steady_clock, best of --repeats.
//   throughput  node updates per second (steps x nodes / s) of the explicit and Crank-Nicolson
//               solvers in 1D and 2D at two sizes each, on an aluminium wall with a radiating,
//               irradiated hot face; per core with --threads 1 (the default). The explicit
//               solver is asked for steps 20x its stability limit and sub-steps them; CN takes
//               steps 50x the explicit limit.
//   accuracy    the seed's sine-decay problem (eq. 4.12; 2D analogue) at several resolutions:
//               max error relative to the amplitude, against wall seconds, for both schemes
//               (explicit at K = 0.4 and at its limit K = 1/2, CN with dt = t/n).
//   sizing      minimum coating on 3 mm aluminium for every material of the table, (a) the seed's
//               method: hot face held at the seed's side-0 temperature (Table 4.2, 9100.2 K) for
//               1 ms (its survival time); (b) the same 1 ms with the face as a radiative
//               boundary under the incident flux that gives 9100.2 K at equilibrium with the
//               seed's aluminium optics (9.73e7 W/m^2), absorbed with the outer material's optics.
//
//   ejecta_bench_wall_heat [--threads T] [--repeats 3] [--threads-sweep] [--quick] [--json]
// --threads-sweep: also runs the throughput at 2 threads and prints the 2/1 ratio.
// --quick: smaller sizes and fewer resolutions (a smoke run).
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "bench/arguments.hpp"
#include "radiation/radiative_balance.hpp"
#include "radiation/shield_sizing.hpp"
#include "radiation/wall_explicit.hpp"
#include "radiation/wall_implicit.hpp"

using namespace ejecta;
using namespace ejecta::radiation;

namespace {

constexpr double kPi = std::numbers::pi;

struct Options {
  int threads = 1;
  int repeats = 3;
  bool sweep = false;
  bool quick = false;
  bool json = false;
};

Options parseOptions(int argc, char** argv) {
  Options o;
  bench::Arguments args(argc, argv);
  for (std::string arg; args.next(arg);) {
    if (arg == "--threads")
      o.threads = std::max(1, std::atoi(args.value()));
    else if (arg == "--repeats")
      o.repeats = std::max(1, std::atoi(args.value()));
    else if (arg == "--threads-sweep")
      o.sweep = true;
    else if (arg == "--quick")
      o.quick = true;
    else if (arg == "--json")
      o.json = true;
    else {
      std::fprintf(stderr, "unknown option %s\n", arg.c_str());
      std::exit(2);
    }
  }
  return o;
}

double seconds(const std::function<void()>& f) {
  const auto start = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double bestOf(int repeats, const std::function<void()>& f) {
  double best = 1e300;
  for (int r = 0; r < repeats; ++r) best = std::min(best, seconds(f));
  return best;
}

// ---------------------------------------------------------------------------------------------
// Throughput

struct Throughput {
  std::string scheme;
  int nx = 0, ny = 0;
  int threads = 1;
  long steps = 0;  // solver steps (explicit: sub-steps)
  double seconds = 0.0;
  double updatesPerSecond = 0.0;
  std::string extra;  // CN: factorisations and solves per step
};

// 1 mm of aluminium, hot face irradiated at 1e7 W/m^2 with the table's optics, cold face
// radiating; in 2D a 1 cm strip with insulated ends and the flux varying along it.
WallBoundaries benchBoundaries() {
  const WallMaterial& al = wallMaterial("aluminium");
  WallBoundaries bc;
  bc.hot = FaceCondition::irradiated(
      [](double t, double y) { return 1e7 * (1.0 + 1e3 * t) * (1.0 + 50.0 * y); }, al);
  bc.cold = FaceCondition::radiating(al.emissivity);
  return bc;
}

Throughput measureThroughput(bool implicit, int cellsX, int nodesY, int threads, int repeats) {
  omp_set_num_threads(threads);
  const WallGrid grid(LayeredWall({wallLayer("aluminium", 1e-3, cellsX)}), 0.01, nodesY);
  const WallBoundaries bc = benchBoundaries();
  Throughput r;
  r.scheme = implicit ? "Crank-Nicolson" : "explicit";
  r.nx = grid.nx();
  r.ny = grid.ny();
  r.threads = threads;
  // Node updates per timed run: CN's steps cost several passes and solves.
  const double target = implicit ? 3e6 : 3e7;
  const double explicitLimit = ExplicitWallSolver(grid, bc, 300.0).stableTimeStep();
  if (implicit) {
    const long steps = std::max(20L, static_cast<long>(target / grid.size()));
    long factorizations = 0, solves = 0;
    r.seconds = bestOf(repeats, [&] {
      CrankNicolsonWallSolver s(grid, bc, 300.0);
      for (long k = 0; k < steps; ++k) s.advance(50.0 * explicitLimit);
      factorizations = s.factorizations();
      solves = s.solves();
    });
    r.steps = steps;
    char buf[96];
    std::snprintf(buf, sizeof buf, "%.2f factorisations, %.2f solves per step",
                  static_cast<double>(factorizations) / steps, static_cast<double>(solves) / steps);
    r.extra = buf;
  } else {
    const long userSteps = std::max(1L, static_cast<long>(target / grid.size() / 20));
    long taken = 0;
    r.seconds = bestOf(repeats, [&] {
      ExplicitWallSolver s(grid, bc, 300.0);
      for (long k = 0; k < userSteps; ++k) s.advance(20.0 * explicitLimit);
      taken = s.stepsTaken();
    });
    r.steps = taken;
    r.extra = std::to_string(taken / userSteps) + " sub-steps per requested step";
  }
  r.updatesPerSecond = static_cast<double>(r.steps) * grid.size() / r.seconds;
  return r;
}

// ---------------------------------------------------------------------------------------------
// Accuracy against wall time: sine decay

struct AccuracyPoint {
  std::string scheme;
  int dimension = 1;
  int cells = 0;
  long steps = 0;
  double error = 0.0;
  double seconds = 0.0;
};

AccuracyPoint sineDecay(int dimension, const std::string& scheme, int n, int repeats) {
  const double lx = 1.0, ly = 2.0, endTime = dimension == 1 ? 0.1 : 0.05;
  WallMaterial unit;
  unit.name = "unit";
  unit.conductivity = unit.density = unit.specificHeat = 1.0;
  unit.meltingPoint = unit.boilingPoint = 1e9;
  const WallGrid grid = dimension == 1 ? WallGrid(LayeredWall({{unit, lx, n}}))
                                       : WallGrid(LayeredWall({{unit, lx, n}}), ly, n + 1);
  WallBoundaries bc;
  bc.hot = bc.cold = FaceCondition::fixed(0.0);
  bc.ends = {EndCondition::Kind::FixedTemperature, 0.0};
  std::vector<double> field(grid.size());
  for (int j = 0; j < grid.ny(); ++j)
    for (int i = 0; i < grid.nx(); ++i)
      field[grid.index(i, j)] = std::sin(kPi * grid.wall().position()[i] / lx) *
                                (dimension == 1 ? 1.0 : std::sin(kPi * grid.facePosition(j) / ly));
  const double rate = kPi * kPi * (1.0 / (lx * lx) + (dimension == 1 ? 0.0 : 1.0 / (ly * ly)));
  const double dx = lx / n, dy = ly / n;
  const double inverseSquares = 1.0 / (dx * dx) + (dimension == 1 ? 0.0 : 1.0 / (dy * dy));
  double dt = endTime / n;
  if (scheme == "explicit K=0.4") dt = 0.4 / inverseSquares;
  if (scheme == "explicit K=0.5") dt = 0.5 / inverseSquares;
  AccuracyPoint p;
  p.scheme = scheme;
  p.dimension = dimension;
  p.cells = n;
  std::vector<double> result;
  p.seconds = bestOf(repeats, [&] {
    std::unique_ptr<WallSolver> s;
    if (scheme == "Crank-Nicolson")
      s = std::make_unique<CrankNicolsonWallSolver>(grid, bc, field);
    else
      s = std::make_unique<ExplicitWallSolver>(grid, bc, field);
    s->run(endTime, dt);
    result.assign(s->temperature().begin(), s->temperature().end());
  });
  p.steps = static_cast<long>(std::ceil(endTime / dt * (1.0 - 1e-12)));
  const double amplitude = std::exp(-rate * endTime);
  for (std::size_t k = 0; k < grid.size(); ++k)
    p.error = std::max(p.error, std::abs(result[k] - field[k] * amplitude));
  p.error /= amplitude;
  return p;
}

// ---------------------------------------------------------------------------------------------
// Sizing

struct SizingCase {
  std::string name;
  std::vector<ShieldSizing> results;
  double seconds = 0.0;
};

SizingCase sizeSeedExample(bool radiative, int threads) {
  omp_set_num_threads(threads);
  ShieldSizingProblem p;
  p.structure = wallLayer("aluminium", 3e-3, 30);
  p.initialTemperature = 293.15;
  p.patchArea = 1.0;
  p.maxThickness = 5e-3;
  p.coatingCells = 20;
  const double sideZero = 9100.2;  // seed Table 4.2
  SizingCase c;
  if (!radiative) {
    c.name = "seed method: hot face held at 9100.2 K for 1 ms";
    p.hotFace = FaceCondition::fixed(sideZero);
    p.duration = 1e-3;
    p.timeStep = 1e-6;
  } else {
    const double incident =
        incidentFluxForTemperature(sideZero, kSeedAluminiumAbsorptivity, kSeedAluminiumEmissivity);
    char name[160];
    std::snprintf(name, sizeof name,
                  "radiative face: incident %.3g W/m^2 for 1 ms, the outer "
                  "material's optics",
                  incident);
    c.name = name;
    p.hotFace =
        FaceCondition::irradiated([incident](double, double) { return incident; }, 1.0, 0.0);
    p.useCoatingOptics = true;
    p.duration = 1e-3;
    p.timeStep = 1e-6;
  }
  const std::vector<WallMaterial>& candidates = wallMaterials();
  c.seconds = seconds([&] { c.results = sizeShield(p, candidates); });
  return c;
}

// ---------------------------------------------------------------------------------------------

void printHuman(const Options& o, const std::vector<Throughput>& tp,
                const std::vector<AccuracyPoint>& acc, const std::vector<SizingCase>& sizing) {
  std::printf("Wall heat solvers (aluminium wall, irradiated radiating hot face)\n");
  std::printf("  throughput, best of %d\n", o.repeats);
  std::printf("    %-15s %10s %8s %10s %9s %14s  %s\n", "scheme", "nodes", "threads", "steps",
              "wall [s]", "node updates/s", "");
  for (const auto& r : tp) {
    char nodes[32];
    std::snprintf(nodes, sizeof nodes, r.ny > 1 ? "%dx%d" : "%d", r.nx, r.ny);
    std::printf("    %-15s %10s %8d %10ld %9.4f %14.4g  %s\n", r.scheme.c_str(), nodes, r.threads,
                r.steps, r.seconds, r.updatesPerSecond, r.extra.c_str());
  }
  if (o.sweep) {
    std::printf("  throughput 2 threads / 1 thread:");
    for (const auto& a : tp)
      for (const auto& b : tp)
        if (a.threads == 1 && b.threads == 2 && a.scheme == b.scheme && a.nx == b.nx &&
            a.ny == b.ny)
          std::printf("  %s %dx%d %.2f", a.scheme.c_str(), a.nx, a.ny,
                      b.updatesPerSecond / a.updatesPerSecond);
    std::printf("\n");
  }
  std::printf("  accuracy against wall time, sine decay (error relative to the amplitude)\n");
  std::printf("    %-3s %-15s %6s %8s %11s %10s\n", "dim", "scheme", "cells", "steps", "error",
              "wall [s]");
  for (const auto& p : acc)
    std::printf("    %-3d %-15s %6d %8ld %11.3e %10.5f\n", p.dimension, p.scheme.c_str(), p.cells,
                p.steps, p.error, p.seconds);
  for (const auto& c : sizing) {
    std::printf("  sizing on 3 mm aluminium (limit 933.47 K), %s: %.2f s for %zu candidates\n",
                c.name.c_str(), c.seconds, c.results.size());
    std::printf("    %-17s %8s %12s %14s %12s %12s  %s\n", "coating", "runs", "thickness", "kg/m^2",
                "Al peak [K]", "coat peak", "note");
    for (const auto& r : c.results) {
      if (r.feasible)
        std::printf("    %-17s %8d %9.4f mm %14.4f %12.1f %12.1f  %s\n", r.material.c_str(), r.runs,
                    r.thickness * 1e3, r.addedMass, r.structurePeak, r.coatingPeak, r.note.c_str());
      else
        std::printf("    %-17s %8d %12s %14s %12.1f %12.1f  %s\n", r.material.c_str(), r.runs,
                    "none", "-", r.structurePeak, r.coatingPeak, r.note.c_str());
    }
  }
}

void printJson(const std::vector<Throughput>& tp, const std::vector<AccuracyPoint>& acc,
               const std::vector<SizingCase>& sizing) {
  std::printf("{\"throughput\": [");
  for (std::size_t k = 0; k < tp.size(); ++k)
    std::printf(
        "%s{\"scheme\": \"%s\", \"nx\": %d, \"ny\": %d, \"threads\": %d, \"steps\": %ld, "
        "\"wall_seconds\": %.5g, \"node_updates_per_second\": %.5g}",
        k ? ", " : "", tp[k].scheme.c_str(), tp[k].nx, tp[k].ny, tp[k].threads, tp[k].steps,
        tp[k].seconds, tp[k].updatesPerSecond);
  std::printf("], \"accuracy\": [");
  for (std::size_t k = 0; k < acc.size(); ++k)
    std::printf(
        "%s{\"dimension\": %d, \"scheme\": \"%s\", \"cells\": %d, \"steps\": %ld, "
        "\"error\": %.5g, \"wall_seconds\": %.5g}",
        k ? ", " : "", acc[k].dimension, acc[k].scheme.c_str(), acc[k].cells, acc[k].steps,
        acc[k].error, acc[k].seconds);
  std::printf("], \"sizing\": [");
  for (std::size_t c = 0; c < sizing.size(); ++c) {
    std::printf("%s{\"case\": \"%s\", \"wall_seconds\": %.4g, \"candidates\": [", c ? ", " : "",
                sizing[c].name.c_str(), sizing[c].seconds);
    for (std::size_t k = 0; k < sizing[c].results.size(); ++k) {
      const auto& r = sizing[c].results[k];
      std::printf(
          "%s{\"material\": \"%s\", \"feasible\": %s, \"thickness_m\": %.6g, "
          "\"kg_per_m2\": %.6g, \"structure_peak_K\": %.6g, \"coating_peak_K\": %.6g, "
          "\"runs\": %d}",
          k ? ", " : "", r.material.c_str(), r.feasible ? "true" : "false", r.thickness,
          r.addedMass, r.structurePeak, r.coatingPeak, r.runs);
    }
    std::printf("]}");
  }
  std::printf("]}\n");
}

}  // namespace

int main(int argc, char** argv) try {
  const Options o = parseOptions(argc, argv);
  std::vector<Throughput> tp;
  std::vector<int> threadCounts = {o.threads};
  if (o.sweep && o.threads != 2) threadCounts = {1, 2};
  struct Size {
    bool implicit;
    int cells;
    int nodesY;
  };
  const std::vector<Size> sizes =
      o.quick
          ? std::vector<Size>{{false, 100, 1}, {true, 100, 1}, {false, 100, 101}, {true, 100, 101}}
          : std::vector<Size>{{false, 100, 1},  {false, 1000, 1},  {true, 100, 1},
                              {true, 1000, 1},  {false, 100, 101}, {false, 400, 401},
                              {true, 100, 101}, {true, 300, 301}};
  for (const int t : threadCounts)
    for (const Size& s : sizes)
      tp.push_back(measureThroughput(s.implicit, s.cells, s.nodesY, t, o.repeats));

  omp_set_num_threads(o.threads);
  std::vector<AccuracyPoint> acc;
  const std::vector<int> cells1 =
      o.quick ? std::vector<int>{16, 64} : std::vector<int>{16, 32, 64, 128, 256, 512};
  const std::vector<int> cells2 =
      o.quick ? std::vector<int>{16, 32} : std::vector<int>{16, 32, 64, 128};
  for (const char* scheme : {"explicit K=0.4", "explicit K=0.5", "Crank-Nicolson"}) {
    for (const int n : cells1) acc.push_back(sineDecay(1, scheme, n, o.repeats));
    for (const int n : cells2) acc.push_back(sineDecay(2, scheme, n, o.repeats));
  }

  std::vector<SizingCase> sizing = {sizeSeedExample(false, o.threads),
                                    sizeSeedExample(true, o.threads)};
  if (o.json)
    printJson(tp, acc, sizing);
  else
    printHuman(o, tp, acc, sizing);
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "ejecta_bench_wall_heat: %s\n", e.what());
  return 1;
}
