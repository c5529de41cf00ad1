// The thermal chain's ray casting (radiation/thermal_study.hpp, docs/thermal.md): the follower
// study (scenes/thermal/follower.toml: a 1 m box flying down the axis from 10 m to 1 m above a
// crater at 10 km/s, 10 flux samples, 6 faces) on synthetic emitters, with and without the
// asteroid's surface as an occluder.
//   emitters  the crater's hot lining: spheres on a cubic lattice filling a hemispherical shell
//             (inner radius 2.2 m, outer 2.5 m) below the crater point (0, 35, 0), each of its
//             lattice cell's volume (equalVolumeRadius, as voxel emitters are), 2000-4000 K;
//             --emitters sets the lattice spacing
//   occluder  a 35 m asteroid (an icosphere of 81,920 triangles) with the crater's cap removed,
//             and the crater's bowl 0.3 m behind the lining (an icosphere's lower half):
//             ~85,000 triangles, about what impact_rz's meshed level set gives (108,000)
//   phases    flux: runThermalStudy's ray-casting phase alone (walls and sizing removed), which
//             rebuilds the BVH at every sample: rays/s and rays/s per core at 1 and 2 threads;
//             build: one sample's ViewFactorSolver construction (the BVH), best of --repeats
// Prints rays, seconds, rays/s, rays/s per core, the occluder/no-occluder throughput ratio and
// the 2-thread / 1-thread speed-up, or --json.
//
//   ejecta_bench_thermal [--rays N] [--emitters N] [--repeats R] [--study FILE] [--json]
// --rays: rays per face and sample (default 65536); --emitters: about this many lining spheres
// (default 20000).
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "bench/arguments.hpp"
#include "radiation/emitters.hpp"
#include "radiation/geometry_file.hpp"
#include "radiation/spacecraft.hpp"
#include "radiation/thermal_study.hpp"
#include "radiation/view_factors.hpp"

using namespace ejecta;
using namespace ejecta::radiation;

namespace {

constexpr double kAsteroid = 35.0;                  // [m], impact_rz's asteroid
const Vec3 kCrater{0.0, kAsteroid, 0.0};            // the crater point
constexpr double kOuter = 2.5, kInner = 2.2;        // the hot lining's radii about it [m]
constexpr double kBowlGap = 0.3;                    // rock behind the lining [m]

struct Options {
  std::uint64_t rays = 1u << 16;
  std::size_t emitters = 20000;
  int repeats = 2;
  std::string study = std::string(EJECTA_SOURCE_DIR) + "/scenes/thermal/follower.toml";
  bool json = false;
};

Options parseOptions(int argc, char** argv) {
  Options o;
  bench::Arguments args(argc, argv);
  for (std::string arg; args.next(arg);) {
    if (arg == "--rays") o.rays = std::strtoull(args.value(), nullptr, 10);
    else if (arg == "--emitters") o.emitters = std::strtoull(args.value(), nullptr, 10);
    else if (arg == "--repeats") o.repeats = std::max(1, std::atoi(args.value()));
    else if (arg == "--study") o.study = args.value();
    else if (arg == "--json") o.json = true;
    else { std::fprintf(stderr, "unknown option %s\n", arg.c_str()); std::exit(2); }
  }
  if (o.rays < 4096 || o.emitters < 100) { std::fprintf(stderr, "need --rays >= 4096, --emitters >= 100\n"); std::exit(2); }
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

// The hot lining: lattice points in the shell kInner <= |p - crater| <= kOuter below the crater
// point, spacing chosen for about `count` of them.
Emitters hotLining(std::size_t count) {
  const double shell = 2.0 / 3.0 * std::numbers::pi * (std::pow(kOuter, 3) - std::pow(kInner, 3));
  const double s = std::cbrt(shell / static_cast<double>(count));
  const double r = equalVolumeRadius(s * s * s);
  const int n = static_cast<int>(std::ceil(kOuter / s));
  Emitters e;
  for (int i = -n; i <= n; ++i)
    for (int j = -n; j <= 0; ++j)
      for (int k = -n; k <= n; ++k) {
        const double x = i * s, y = (j - 0.5) * s, z = k * s;
        const double d = std::sqrt(x * x + y * y + z * z);
        if (d < kInner || d > kOuter) continue;
        const double t = 2000.0 + 2000.0 * (kOuter - d) / (kOuter - kInner);  // hotter inside
        e.add(kCrater[0] + x, kCrater[1] + y, kCrater[2] + z, r, t, kGraniteEmissivity, "lining");
      }
  return e;
}

// The triangles of `m` whose centroid passes `keep`, in patch `patch`.
TriangleMesh keepTriangles(const TriangleMesh& m, const std::function<bool(const Vec3&)>& keep,
                           TriangleMesh out, const std::string& patch) {
  const std::uint32_t p = out.patchIndex(patch);
  const auto base = static_cast<std::uint32_t>(out.vertices.size());
  out.vertices.insert(out.vertices.end(), m.vertices.begin(), m.vertices.end());
  for (const auto& t : m.triangles) {
    Vec3 c{};
    for (int k = 0; k < 3; ++k) c = vec3::add(c, vec3::scale(m.vertices[t[k]], 1.0 / 3.0));
    if (keep(c)) out.addTriangle(base + t[0], base + t[1], base + t[2], p);
  }
  return out;
}

// The asteroid without the crater's cap, and the crater's bowl behind the lining.
TriangleMesh asteroidWithCrater() {
  const double bowl = kOuter + kBowlGap;
  TriangleMesh out = keepTriangles(makeSphere("asteroid", {0, 0, 0}, kAsteroid, 6), [&](const Vec3& c) {
    return std::hypot(c[0], c[2]) > bowl || c[1] < 0.0;
  }, {}, "asteroid");
  return keepTriangles(makeSphere("bowl", kCrater, bowl, 5), [](const Vec3& c) { return c[1] < kCrater[1]; },
                       std::move(out), "asteroid");
}

struct FluxRun {
  bool occluded;
  int threads;
  std::uint64_t rays;
  double seconds;
  double rate() const { return static_cast<double>(rays) / seconds; }
};

struct BuildRun {
  bool occluded;
  int threads;
  double seconds;
};

}  // namespace

int main(int argc, char** argv) try {
  const Options o = parseOptions(argc, argv);
  ThermalStudy study = loadThermalStudy(o.study);
  study.walls.clear();  // the ray casting alone
  study.sizing.coatings.clear();
  study.sampling.rays = o.rays;
  const Emitters emitters = hotLining(o.emitters);
  const TriangleMesh occluder = asteroidWithCrater();
  const int saved = omp_get_max_threads();

  std::vector<FluxRun> flux;
  std::vector<BuildRun> builds;
  double side0Open = 0.0, side0Occluded = 0.0;
  std::size_t faces = 0;
  for (const int t : {1, 2}) {
    omp_set_num_threads(t);
    for (const bool occ : {false, true}) {
      ThermalResult r;
      double best = INFINITY;
      for (int k = 0; k < o.repeats; ++k) {
        r = runThermalStudy(study, emitters, occ ? &occluder : nullptr);
        best = std::min(best, r.raySeconds);
      }
      flux.push_back({occ, t, r.rays, best});
      (occ ? side0Occluded : side0Open) = r.patches.front().peakFlux;
      faces = r.patches.size();
      // One sample's scene: the spacecraft at t = 0, the emitters, the occluder; Embree builds
      // with as many threads.
      GeometryConfig craft;
      craft.spacecraft = study.spacecraft;
      RaySceneOptions ro;
      ro.buildThreads = t;
      const double s = bestOf(o.repeats, [&] {
        RadiationScene scene;
        scene.surfaces = buildRadiationScene(craft, 0.0).surfaces;
        scene.emitters = emitters;
        if (occ) scene.occluder.mesh = occluder;
        const ViewFactorSolver solver(std::move(scene), ro);
      });
      builds.push_back({occ, t, s});
    }
  }
  omp_set_num_threads(saved);

  auto find = [&](bool occ, int t) -> const FluxRun& {
    for (const FluxRun& f : flux)
      if (f.occluded == occ && f.threads == t) return f;
    return flux.front();
  };
  if (o.json) {
    std::printf("{\"study\": \"%s\", \"emitters\": %zu, \"occluder_triangles\": %zu, \"rays_per_face_sample\": %llu, "
                "\"side0_peak_flux_W_m2\": {\"open\": %.6g, \"occluded\": %.6g}, \"flux\": [",
                study.name.c_str(), emitters.size(), occluder.triangleCount(),
                static_cast<unsigned long long>(o.rays), side0Open, side0Occluded);
    for (std::size_t i = 0; i < flux.size(); ++i)
      std::printf("%s{\"occluder\": %s, \"threads\": %d, \"rays\": %llu, \"seconds\": %.5g, \"rays_per_second\": %.4g, "
                  "\"rays_per_second_per_core\": %.4g}",
                  i ? ", " : "", flux[i].occluded ? "true" : "false", flux[i].threads,
                  static_cast<unsigned long long>(flux[i].rays), flux[i].seconds, flux[i].rate(),
                  flux[i].rate() / flux[i].threads);
    std::printf("], \"build\": [");
    for (std::size_t i = 0; i < builds.size(); ++i)
      std::printf("%s{\"occluder\": %s, \"threads\": %d, \"seconds\": %.5g}", i ? ", " : "",
                  builds[i].occluded ? "true" : "false", builds[i].threads, builds[i].seconds);
    std::printf("]}\n");
    return 0;
  }
  std::printf("Thermal study '%s' (%zu samples, %zu faces, %llu rays per face and sample) on %zu hot lining "
              "spheres; occluder: %zu triangles\n",
              study.name.c_str(), study.approach.times().size(), faces,
              static_cast<unsigned long long>(o.rays), emitters.size(), occluder.triangleCount());
  std::printf("  side0 peak flux %.4g W/m^2 open, %.4g W/m^2 with the occluder\n", side0Open, side0Occluded);
  std::printf("  %-9s %8s %12s %10s %14s %16s\n", "occluder", "threads", "rays", "wall [s]", "rays/s", "rays/s/core");
  for (const FluxRun& f : flux)
    std::printf("  %-9s %8d %12llu %10.4f %14.4g %16.4g\n", f.occluded ? "yes" : "no", f.threads,
                static_cast<unsigned long long>(f.rays), f.seconds, f.rate(), f.rate() / f.threads);
  std::printf("  occluder / none (rays/s): %.2f at 1 thread, %.2f at 2; 2 threads / 1 thread: %.2f open, %.2f occluded\n",
              find(true, 1).rate() / find(false, 1).rate(), find(true, 2).rate() / find(false, 2).rate(),
              find(false, 2).rate() / find(false, 1).rate(), find(true, 2).rate() / find(true, 1).rate());
  const double samples = static_cast<double>(study.approach.times().size());
  std::printf("BVH build of one sample's scene (best of %d), and the flux phase without the %g builds\n"
              "  %-9s %8s %10s %12s %16s\n", o.repeats, samples, "occluder", "threads", "build [s]",
              "builds share", "rays/s/core else");
  for (const BuildRun& b : builds) {
    const FluxRun& f = find(b.occluded, b.threads);
    const double rest = f.seconds - samples * b.seconds;
    std::printf("  %-9s %8d %10.4f %11.0f%% %16.4g\n", b.occluded ? "yes" : "no", b.threads, b.seconds,
                100.0 * samples * b.seconds / f.seconds, static_cast<double>(f.rays) / rest / b.threads);
  }
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "ejecta_bench_thermal: %s\n", e.what());
  return 1;
}
