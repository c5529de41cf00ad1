// Particles to grids throughput (fields/, issue 5). A 35 m asteroid of particles on a cubic
// lattice (3D), or its half-disc of rings (RZ), with an iron core, radial temperature, pressure
// and damage profiles and a hemispherical crater of radius R/3 at the top. Each phase is
// timed (steady_clock, best of --repeats):
//   grid set   buildGridSet of the default grids {density, temperature, pressure, damage,
//              fractions} at voxel = h (--voxel: in units of h); RZ includes the revolve
//   revolve    RZ only: revolveAboutAxis alone, on the 2D lattice of the same splat
//   vdb write  writeGridFile of that grid set (with its surface level set) to a temporary file
//   vdb fogs   the same without the level set
//   crater     measureCrater at its default resolution (h/2; its own splat and ray marching)
// Prints particles, active voxels (channel 0 > 0), wall seconds, particles/s, voxels/s and per-
// core particles/s. --threads-sweep runs at 1 and 2 threads and prints the 2-thread / 1-thread
// throughput ratio of each phase. OpenVDB's own TBB threads are capped to the same count.
//
//   ejecta_bench_fields [--n 72] [--geometry 3d|rz] [--voxel 1.0] [--threads T] [--repeats 3]
//                       [--threads-sweep] [--json]
// --n: particles per diameter (default 72 in 3D: 192,000 particles, 132,000 voxels; 200 in RZ:
// 14,900 rings revolved into 2.6 million voxels).
#include <omp.h>
#include <tbb/global_control.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "fields/grid_set.hpp"
#include "fields/measure_crater.hpp"
#include "fields/revolve.hpp"
#include "fields/vdb_grids.hpp"
#include "bench/arguments.hpp"
#include "sim/run/run.hpp"

using namespace ejecta;
using namespace ejecta::fields;
namespace fs = std::filesystem;

namespace {

constexpr double kRadius = 35.0;       // [m], the asteroid of scenes/impact_rz.toml
constexpr double kEta = 1.2;           // h / spacing
constexpr double kCraterRadius = kRadius / 3.0;
constexpr double kRock = 2700.0, kIron = 7800.0;  // [kg/m^3]
const std::vector<std::string> kMaterials = {"basalt", "iron"};

struct Options {
  bool rz = false;
  int n = 0;                 // 0: the geometry's default
  double voxel = 1.0;        // in units of h
  int threads = 0;
  int repeats = 3;
  bool sweep = false;
  bool json = false;
};

Options parseOptions(int argc, char** argv) {
  Options o;
  bench::Arguments args(argc, argv);
  for (std::string arg; args.next(arg);) {
    auto next = [&args] { return args.value(); };
    if (arg == "--n") o.n = std::atoi(next());
    else if (arg == "--geometry") {
      const std::string g = next();
      if (g != "3d" && g != "rz") { std::fprintf(stderr, "--geometry: 3d or rz\n"); std::exit(2); }
      o.rz = g == "rz";
    }
    else if (arg == "--voxel") o.voxel = std::atof(next());
    else if (arg == "--threads") o.threads = std::atoi(next());
    else if (arg == "--repeats") o.repeats = std::max(1, std::atoi(next()));
    else if (arg == "--threads-sweep") o.sweep = true;
    else if (arg == "--json") o.json = true;
    else { std::fprintf(stderr, "unknown option %s\n", arg.c_str()); std::exit(2); }
  }
  if (o.n == 0) o.n = o.rz ? 200 : 72;
  if (o.n < 8 || !(o.voxel > 0.0)) { std::fprintf(stderr, "need --n >= 8 and --voxel > 0\n"); std::exit(2); }
  return o;
}

// The asteroid at n particles per diameter: cell centres inside the sphere (RZ: r > 0 only, the
// ring mass 2 pi r rho dx^2) and outside the crater bowl centred on the top pole (0, R, 0).
ParticleSet makeAsteroid(bool rz, int n) {
  const double dx = 2.0 * kRadius / n;
  const int ni = rz ? n / 2 : n, nk = rz ? 1 : n;
  ParticleSet p;
  for (int i = 0; i < ni; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < nk; ++k) {
        const double x = (rz ? 0.0 : -kRadius) + (i + 0.5) * dx;
        const double y = -kRadius + (j + 0.5) * dx;
        const double z = rz ? 0.0 : -kRadius + (k + 0.5) * dx;
        const double r = std::sqrt(x * x + y * y + z * z);
        const double yc = y - kRadius;
        if (r >= kRadius || x * x + yc * yc + z * z < kCraterRadius * kCraterRadius) continue;
        const int mat = r < 0.5 * kRadius ? 1 : 0;
        const double rho = mat == 1 ? kIron : kRock;
        const double m = rz ? rho * 2.0 * std::numbers::pi * x * dx * dx : rho * dx * dx * dx;
        p.append({x, y, z}, {0, 0, 0}, m, rho, 1e5, kEta * dx, mat);
      }
  p.numReal = p.size();
  // Profiles so every grid carries data: hot dense centre, a damaged outer shell.
  p.enableFracture();
  for (std::size_t i = 0; i < p.numReal; ++i) {
    const double s = std::hypot(p.x[0][i], p.x[1][i], p.x[2][i]) / kRadius;
    p.temperature[i] = 300.0 + 1200.0 * (1.0 - s * s);
    p.P[i] = 1e8 * (1.0 - s * s);
    p.crack[i] = std::cbrt(std::clamp((s - 0.8) / 0.2, 0.0, 1.0));
  }
  return p;
}

ParticleContext contextFor(bool rz) {
  ParticleContext c;
  c.geometry = rz ? Geometry::Axisymmetric : Geometry::Spatial;
  c.materialNames = kMaterials;
  return c;
}

// The sphere as the crater's reference surface, struck at the top pole (grid coordinates: the
// RZ axis is y, so the same setup serves both geometries).
CraterSetup craterSetup() {
  CraterSetup s;
  s.surface.kind = ReferenceSurface::Kind::Sphere;
  s.surface.center = {0, 0, 0};
  s.surface.radius = kRadius;
  s.impactPoint = {0, kRadius, 0};
  s.alongTrack = {0, -1, 0};
  s.targetDensity = kRock;
  s.targetMaterials = {0, 1};
  s.targetNames = kMaterials;
  return s;
}

std::size_t activeVoxels(const SparseLattice& lat) {
  std::size_t n = 0;
  for (std::size_t b = 0; b < lat.blockCount(); ++b) {
    const float* filled = lat.data(b, 0);
    for (int v = 0; v < lat.blockVolume(); ++v) n += filled[v] > 0.0f ? 1 : 0;
  }
  return n;
}

// Best wall time of `repeats` calls: the first call also pays page faults and OpenVDB's set-up.
double bestOf(int repeats, const std::function<void()>& f) {
  double best = INFINITY;
  for (int r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    f();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return best;
}

struct Phase {
  std::string name;
  double seconds = 0.0;
  std::size_t particles = 0;  // particles consumed (0: not a particle phase)
  std::size_t voxels = 0;     // voxels produced or written (0: not counted)
};

struct Run {
  int threads = 0;
  std::vector<Phase> phases;
  std::size_t fileBytes = 0;
  CraterMetrics crater;
};

struct Workload {
  ParticleSet particles;
  ParticleContext ctx;
  GridRequest request;
  std::size_t voxels = 0;     // active voxels of the grid set
  int channels = 0;
};

Run runAt(int threads, const Workload& w, const Options& o) {
  omp_set_num_threads(threads);
  // levelSetRebuild in writeGridFile runs on TBB, which ignores OpenMP's count.
  tbb::global_control cap(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
  Run run;
  run.threads = threads;
  const std::size_t n = w.particles.numReal;

  GridSet set;
  run.phases.push_back({"grid set", bestOf(o.repeats, [&] { set = buildGridSet(w.particles, w.ctx, w.request); }),
                        n, w.voxels});
  if (o.rz) {
    // The 2D splat buildGridSet revolves, with as many value channels.
    const std::vector<std::vector<double>> values(set.grids.size(), w.particles.temperature);
    const SparseLattice plane = splatParticles(w.particles, w.ctx, values, w.request.voxel);
    run.phases.push_back({"revolve", bestOf(o.repeats, [&] { (void)revolveAboutAxis(plane, std::nullopt); }),
                          0, w.voxels});
  }

  const fs::path file = fs::temp_directory_path() /
                        ("ejecta_bench_fields_" + std::to_string(getpid()) + ".vdb");
  GridFileMeta meta;
  meta.scene = "bench_fields";
  run.phases.push_back({"vdb write", bestOf(o.repeats, [&] { writeGridFile(file.string(), set, meta); }),
                        n, w.voxels});
  run.fileBytes = fs::file_size(file);
  // The same without the surface level set (OpenVDB's levelSetRebuild): what the fogs cost.
  meta.levelSet = false;
  run.phases.push_back({"vdb fogs", bestOf(o.repeats, [&] { writeGridFile(file.string(), set, meta); }),
                        n, w.voxels});
  fs::remove(file);

  const CraterSetup setup = craterSetup();
  run.phases.push_back({"crater", bestOf(o.repeats, [&] { run.crater = measureCrater(w.particles, w.ctx, setup); }),
                        n, 0});
  return run;
}

double perSecond(std::size_t count, double seconds) {
  return count > 0 ? static_cast<double>(count) / seconds : 0.0;
}

void printHuman(const Options& o, const Workload& w, const std::vector<Run>& runs) {
  std::printf("Particles to grids, %s asteroid (R = %.0f m, %d particles per diameter), voxel = %.3g h\n",
              o.rz ? "RZ" : "3D", kRadius, o.n, o.voxel);
  std::printf("  particles                  %zu\n", w.particles.numReal);
  std::printf("  active voxels              %zu (%d channels)\n", w.voxels, w.channels);
  for (const Run& r : runs) {
    std::printf("  threads %d (best of %d)\n", r.threads, o.repeats);
    std::printf("    %-10s %9s %14s %14s %16s\n", "phase", "wall [s]", "particles/s", "voxels/s",
                "particles/s/core");
    for (const Phase& p : r.phases) {
      const double ps = perSecond(p.particles, p.seconds), vs = perSecond(p.voxels, p.seconds);
      auto cell = [](double v) {
        char buf[32];
        std::snprintf(buf, sizeof buf, v > 0 ? "%.4g" : "-", v);
        return std::string(buf);
      };
      std::printf("    %-10s %9.4f %14s %14s %16s\n", p.name.c_str(), p.seconds, cell(ps).c_str(),
                  cell(vs).c_str(), cell(ps / r.threads).c_str());
    }
    std::printf("    vdb file %.1f MB; crater depth %.2f m (bowl %.2f m), apparent diameter %.2f m\n",
                static_cast<double>(r.fileBytes) / 1e6, r.crater.depth, kCraterRadius,
                r.crater.apparentDiameter);
  }
  if (runs.size() == 2) {
    std::printf("  throughput %d threads / %d thread:", runs[1].threads, runs[0].threads);
    for (std::size_t k = 0; k < runs[0].phases.size(); ++k)
      std::printf("  %s %.2f", runs[0].phases[k].name.c_str(),
                  runs[0].phases[k].seconds / runs[1].phases[k].seconds);
    std::printf("\n");
  }
}

void printJson(const Options& o, const Workload& w, const std::vector<Run>& runs) {
  std::printf("{\"geometry\": \"%s\", \"n\": %d, \"particles\": %zu, \"voxel_h\": %.4g, "
              "\"voxel_m\": %.4g, \"active_voxels\": %zu, \"channels\": %d, \"repeats\": %d, \"runs\": [",
              o.rz ? "rz" : "3d", o.n, w.particles.numReal, o.voxel, w.request.voxel, w.voxels,
              w.channels, o.repeats);
  for (std::size_t r = 0; r < runs.size(); ++r) {
    std::printf("%s{\"threads\": %d, \"vdb_bytes\": %zu, \"crater_depth_m\": %.4g, \"phases\": {",
                r ? ", " : "", runs[r].threads, runs[r].fileBytes, runs[r].crater.depth);
    for (std::size_t k = 0; k < runs[r].phases.size(); ++k) {
      const Phase& p = runs[r].phases[k];
      const double ps = perSecond(p.particles, p.seconds);
      std::printf("%s\"%s\": {\"wall_seconds\": %.5g, \"particles_per_second\": %.4g, "
                  "\"voxels_per_second\": %.4g, \"particles_per_second_per_core\": %.4g}",
                  k ? ", " : "", p.name.c_str(), p.seconds, ps, perSecond(p.voxels, p.seconds),
                  ps / runs[r].threads);
    }
    std::printf("}}");
  }
  std::printf("]");
  if (runs.size() == 2) {
    std::printf(", \"speedup_2_over_1\": {");
    for (std::size_t k = 0; k < runs[0].phases.size(); ++k)
      std::printf("%s\"%s\": %.3f", k ? ", " : "", runs[0].phases[k].name.c_str(),
                  runs[0].phases[k].seconds / runs[1].phases[k].seconds);
    std::printf("}");
  }
  std::printf("}\n");
}

}  // namespace

int main(int argc, char** argv) try {
  const Options o = parseOptions(argc, argv);
  Workload w;
  w.particles = makeAsteroid(o.rz, o.n);
  w.ctx = contextFor(o.rz);
  w.request.voxel = o.voxel * kEta * 2.0 * kRadius / o.n;
  // The active voxels, counted once: they do not depend on the thread count.
  const GridSet set = buildGridSet(w.particles, w.ctx, w.request);
  w.voxels = activeVoxels(set.lattice);
  w.channels = set.lattice.channels();

  std::vector<Run> runs;
  if (o.sweep) {
    for (int t : {1, 2}) runs.push_back(runAt(t, w, o));
  } else {
    runs.push_back(runAt(resolveThreads(o.threads), w, o));
  }
  if (o.json) printJson(o, w, runs);
  else printHuman(o, w, runs);
  return 0;
} catch (const std::exception& e) {  // e.g. the temporary VDB file cannot be written
  std::fprintf(stderr, "ejecta_bench_fields: %s\n", e.what());
  return 1;
}
