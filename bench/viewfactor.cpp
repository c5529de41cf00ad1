// Ray casting and view factors (radiation/, docs/view_factors.md). Three measurements:
//   throughput  the seed-like scene: a 1 m box spacecraft 10 m from a ball of --emitters hot
//               spheres on a 35 m asteroid (a 20,480-triangle occluder). Rays from the box's
//               side0 facing the melt, cosine-weighted.
//                 trace: RayScene::trace alone on pre-generated rays;
//                 full:  ViewFactorSolver::fromPatch (sampling + tracing + tallies);
//               single rays (rtcIntersect1), 16-ray packets (rtcIntersect16) and streams
//               (rtcIntersectNp), at 1 and 2 threads; rays/s, rays/s per core, ratios.
//   build       BVH build time of N random spheres (1e4, 1e5, 1e6), Embree at 1 and 2 threads.
//   accuracy    Howell C-41 (coaxial discs r1 = 0.5, r2 = 1, h = 1): error and standard error
//               against rays and wall time, scrambled Sobol' and random points.
//
//   ejecta_bench_viewfactor [--rays N] [--emitters N] [--max-build N] [--repeats R] [--json]
// --rays: rays per throughput measurement (default 2^20); --emitters: spheres in the melt
// (default 100000); --max-build: largest BVH build (default 1000000).
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
#include "radiation/ray_scene.hpp"
#include "radiation/sampling.hpp"
#include "radiation/spacecraft.hpp"
#include "radiation/view_factors.hpp"

using namespace ejecta;
using namespace ejecta::radiation;

namespace {

struct Options {
  std::uint64_t rays = 1u << 20;
  std::size_t emitters = 100000;
  std::size_t maxBuild = 1000000;
  int repeats = 3;
  bool json = false;
};

Options parseOptions(int argc, char** argv) {
  Options o;
  bench::Arguments args(argc, argv);
  for (std::string arg; args.next(arg);) {
    if (arg == "--rays") o.rays = std::strtoull(args.value(), nullptr, 10);
    else if (arg == "--emitters") o.emitters = std::strtoull(args.value(), nullptr, 10);
    else if (arg == "--max-build") o.maxBuild = std::strtoull(args.value(), nullptr, 10);
    else if (arg == "--repeats") o.repeats = std::max(1, std::atoi(args.value()));
    else if (arg == "--json") o.json = true;
    else { std::fprintf(stderr, "unknown option %s\n", arg.c_str()); std::exit(2); }
  }
  if (o.rays < 4096 || o.emitters < 1) { std::fprintf(stderr, "need --rays >= 4096, --emitters >= 1\n"); std::exit(2); }
  return o;
}

double bestOf(int repeats, const std::function<void()>& f) {
  double best = INFINITY;
  for (int r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    f();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return best;
}

double uniform(std::uint64_t key, std::uint64_t i) {
  return sampling::toUnit(static_cast<std::uint32_t>(sampling::combine(key, i)));
}

// The seed-like scene: box at x = -10 facing +x, a ball of melt spheres of radius 3 m at the
// origin (random centres, radius chosen so they overlap into an opaque lump), the asteroid.
RadiationScene seedScene(std::size_t emitters) {
  RadiationScene s;
  Pose pose;
  pose.position = {-10, 0, 0};
  s.surfaces = placeMesh(makeBox(1, 1, 1), pose);
  const double ball = 3.0, r = ball * std::cbrt(4.0 / static_cast<double>(emitters));
  for (std::size_t i = 0; s.emitters.size() < emitters; ++i) {
    const Vec3 p{ball * (2 * uniform(1, 3 * i) - 1), ball * (2 * uniform(1, 3 * i + 1) - 1),
                 ball * (2 * uniform(1, 3 * i + 2) - 1)};
    if (vec3::norm(p) <= ball) s.emitters.add(p[0], p[1], p[2], r, 2500.0, 0.45, "melt");
  }
  s.occluder.mesh = makeSphere("asteroid", {35, 0, 0}, 35.0, 5);
  return s;
}

const char* modeName(TraceMode m) {
  return m == TraceMode::Single ? "single" : m == TraceMode::Packet16 ? "packet16" : "stream";
}

struct Throughput {
  std::string what;
  TraceMode mode;
  int threads;
  double seconds;
  std::uint64_t rays;
  double raysPerSecond() const { return static_cast<double>(rays) / seconds; }
};

struct BuildTime {
  std::size_t spheres;
  int threads;
  double seconds;
};

struct AccuracyRow {
  const char* sampler;
  std::uint64_t rays;
  double error, standardError, seconds;
};

// Rays of side0 (x = -9.5, y and z in [-0.5, 0.5], normal +x), cosine-weighted, in blocks.
std::vector<RayBlock> side0Rays(std::uint64_t rays) {
  std::vector<RayBlock> blocks(static_cast<std::size_t>((rays + RayBlock::kCapacity - 1) / RayBlock::kCapacity));
  const sampling::PointSet set(sampling::Sampler::Sobol, 99);
  std::uint64_t k = 0;
  for (RayBlock& b : blocks) {
    b.count = 0;
    for (; b.count < RayBlock::kCapacity && k < rays; ++b.count, ++k) {
      double u[4];
      set.point(static_cast<std::uint32_t>(k), u);
      const auto d = sampling::squareToCosineHemisphere(u[2], u[3]);
      const int i = b.count;
      b.ox[i] = -9.5f + 1e-4f;
      b.oy[i] = static_cast<float>(u[0] - 0.5);
      b.oz[i] = static_cast<float>(u[1] - 0.5);
      b.dx[i] = static_cast<float>(d[2]);  // local z = the normal +x
      b.dy[i] = static_cast<float>(d[0]);
      b.dz[i] = static_cast<float>(d[1]);
    }
  }
  return blocks;
}

double coaxialDiscs(double r1, double r2, double h) {
  const double R1 = r1 / h, R2 = r2 / h;
  const double X = 1.0 + (1.0 + R2 * R2) / (R1 * R1);
  return 0.5 * (X - std::sqrt(X * X - 4.0 * (R2 / R1) * (R2 / R1)));
}

}  // namespace

int main(int argc, char** argv) try {
  const Options o = parseOptions(argc, argv);
  const int saved = omp_get_max_threads();
  const std::vector<int> threadCounts = {1, 2};
  const TraceMode modes[] = {TraceMode::Single, TraceMode::Packet16, TraceMode::Stream};

  // ---- throughput
  const ViewFactorSolver solver(seedScene(o.emitters));
  // The trace-only scene: the same geometry in its own RayScene.
  RayScene scene;
  scene.addTriangles(solver.scene().surfaces);
  scene.addTriangles(solver.scene().occluder.mesh);
  const Emitters& em = solver.scene().emitters;
  scene.addSpheres(em.x, em.y, em.z, em.radius);
  scene.commit();
  std::vector<RayBlock> blocks = side0Rays(o.rays);
  std::vector<Throughput> through;
  double hitFraction = 0.0;
  for (const int t : threadCounts) {
    omp_set_num_threads(t);
    for (const TraceMode m : modes) {
      const double s = bestOf(o.repeats, [&] {
#pragma omp parallel for schedule(dynamic, 16)
        for (std::size_t b = 0; b < blocks.size(); ++b) scene.trace(blocks[b], m);
      });
      through.push_back({"trace", m, t, s, o.rays});
    }
    for (const TraceMode m : modes) {
      SamplingOptions so;
      so.rays = o.rays;
      so.trace = m;
      ReceiverResult r;
      const double s = bestOf(o.repeats, [&] { r = solver.fromPatch("side0", so); });
      through.push_back({"full", m, t, s, r.rays});
      hitFraction = r.toEmitters.value;
    }
  }
  omp_set_num_threads(saved);

  // ---- BVH build
  std::vector<BuildTime> builds;
  for (std::size_t n = 10000; n <= o.maxBuild; n *= 10) {
    std::vector<double> x(n), y(n), z(n), r(n, 0.01);
    for (std::size_t i = 0; i < n; ++i) {
      x[i] = 10 * uniform(7, 3 * i);
      y[i] = 10 * uniform(7, 3 * i + 1);
      z[i] = 10 * uniform(7, 3 * i + 2);
    }
    for (const int t : threadCounts) {
      const double s = bestOf(o.repeats, [&] {
        RaySceneOptions ro;
        ro.buildThreads = t;
        RayScene bvh(ro);
        bvh.addSpheres(x, y, z, r);
        bvh.commit();
      });
      builds.push_back({n, t, s});
    }
  }

  // ---- accuracy against rays and time (default thread count)
  TriangleMesh discs = makeDisc("disc1", {0, 0, 0}, {0, 0, 1}, 0.5, 512);
  discs.append(makeDisc("disc2", {0, 0, 1}, {0, 0, -1}, 1.0, 512));
  const ViewFactorSolver discSolver(RadiationScene{discs, {}, {}});
  const double exact = coaxialDiscs(0.5, 1.0, 1.0);
  std::vector<AccuracyRow> accuracy;
  for (const auto sampler : {sampling::Sampler::Sobol, sampling::Sampler::Random})
    for (std::uint64_t rays = 1u << 12; rays <= (1u << 22); rays <<= 2) {
      SamplingOptions so;
      so.rays = rays;
      so.sampler = sampler;
      ReceiverResult r;
      const double s = bestOf(1, [&] { r = discSolver.fromPatch("disc1", so); });
      accuracy.push_back({sampler == sampling::Sampler::Sobol ? "sobol" : "random", r.rays,
                          r.toPatch[1].value - exact, r.toPatch[1].standardError, s});
    }

  auto find = [&](const char* what, TraceMode m, int t) -> const Throughput& {
    for (const Throughput& x : through)
      if (x.what == what && x.mode == m && x.threads == t) return x;
    return through.front();
  };
  if (o.json) {
    std::printf("{\"rays\": %llu, \"emitters\": %zu, \"occluder_triangles\": %zu, \"hit_emitters\": %.4f, \"throughput\": [",
                static_cast<unsigned long long>(o.rays), em.size(), solver.scene().occluder.mesh.triangleCount(),
                hitFraction);
    for (std::size_t i = 0; i < through.size(); ++i) {
      const Throughput& x = through[i];
      std::printf("%s{\"what\": \"%s\", \"mode\": \"%s\", \"threads\": %d, \"seconds\": %.5g, \"rays_per_second\": %.4g, "
                  "\"rays_per_second_per_core\": %.4g}",
                  i ? ", " : "", x.what.c_str(), modeName(x.mode), x.threads, x.seconds, x.raysPerSecond(),
                  x.raysPerSecond() / x.threads);
    }
    std::printf("], \"build\": [");
    for (std::size_t i = 0; i < builds.size(); ++i)
      std::printf("%s{\"spheres\": %zu, \"threads\": %d, \"seconds\": %.5g}", i ? ", " : "", builds[i].spheres,
                  builds[i].threads, builds[i].seconds);
    std::printf("], \"accuracy\": {\"case\": \"Howell C-41, r1=0.5 r2=1 h=1\", \"exact\": %.8f, \"rows\": [", exact);
    for (std::size_t i = 0; i < accuracy.size(); ++i)
      std::printf("%s{\"sampler\": \"%s\", \"rays\": %llu, \"error\": %.4g, \"std_error\": %.4g, \"seconds\": %.4g}",
                  i ? ", " : "", accuracy[i].sampler, static_cast<unsigned long long>(accuracy[i].rays),
                  accuracy[i].error, accuracy[i].standardError, accuracy[i].seconds);
    std::printf("]}}\n");
    return 0;
  }
  std::printf("Ray casting: 1 m box 10 m from %zu melt spheres (%.0f%% of side0's rays hit them) on a "
              "%zu-triangle asteroid; %llu rays from side0\n",
              em.size(), 100.0 * hitFraction, solver.scene().occluder.mesh.triangleCount(),
              static_cast<unsigned long long>(o.rays));
  std::printf("  %-6s %-9s %8s %10s %14s %16s\n", "what", "mode", "threads", "wall [s]", "rays/s", "rays/s/core");
  for (const Throughput& x : through)
    std::printf("  %-6s %-9s %8d %10.4f %14.4g %16.4g\n", x.what.c_str(), modeName(x.mode), x.threads, x.seconds,
                x.raysPerSecond(), x.raysPerSecond() / x.threads);
  for (const char* what : {"trace", "full"}) {
    std::printf("  %s: packet16/single %.2f, stream/single %.2f (1 thread); 2 threads / 1 thread:", what,
                find(what, TraceMode::Single, 1).seconds / find(what, TraceMode::Packet16, 1).seconds,
                find(what, TraceMode::Single, 1).seconds / find(what, TraceMode::Stream, 1).seconds);
    for (const TraceMode m : modes)
      std::printf(" %s %.2f", modeName(m), find(what, m, 1).seconds / find(what, m, 2).seconds);
    std::printf("\n");
  }
  std::printf("BVH build of random spheres (best of %d)\n  %10s %8s %10s %14s\n", o.repeats, "spheres", "threads",
              "wall [s]", "spheres/s");
  for (const BuildTime& b : builds)
    std::printf("  %10zu %8d %10.4f %14.4g\n", b.spheres, b.threads, b.seconds, static_cast<double>(b.spheres) / b.seconds);
  std::printf("Accuracy, Howell C-41 coaxial discs (exact F12 = %.6f), %d threads\n  %-7s %10s %11s %11s %9s\n",
              exact, saved, "sampler", "rays", "error", "std error", "wall [s]");
  for (const AccuracyRow& a : accuracy)
    std::printf("  %-7s %10llu %+11.2e %11.2e %9.4f\n", a.sampler, static_cast<unsigned long long>(a.rays), a.error,
                a.standardError, a.seconds);
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "ejecta_bench_viewfactor: %s\n", e.what());
  return 1;
}
