// Off-screen rendering throughput (render/, issue 7): particles drawn by OSMesa's llvmpipe.
// A 35 m asteroid of N particles, uniformly random in a ball (3D: a perspective view cut in
// half by the plane z = 0, shaded discs; RZ: a half disc mirrored about the axis), coloured by a
// radial temperature on a log scale, with the annotation strip (time, scale bar, colour bar).
// For each particle count and image size it times, with steady_clock and the process's CPU
// clock (all threads):
//   context   creating the Renderer: the OSMesa context and the shader programs
//   first     the first frame (llvmpipe compiles its pipeline variants on first use)
//   frame     a later frame: colours on the CPU, upload, draw, glFinish, copy, strip (best of
//             --repeats)
//   png       encoding that frame as PNG, libpng's fast mode and default compression
// llvmpipe reads LP_NUM_THREADS once per process, so --threads-sweep runs this command again
// for 1 and 2 threads (LP_NUM_THREADS = OMP_NUM_THREADS = T) and prints the 2/1 ratio.
//
//   ejecta_bench_render [--particles 100000,1000000] [--sizes 1024,2048] [--view 3d|rz]
//                       [--flat] [--no-cut] [--threads T] [--threads-sweep] [--repeats 3] [--out
//                       DIR]
//                       [--json]
// --no-cut: the whole ball, no clipping plane. --out writes each configuration's frame as
// DIR/<view>_<N>_<size>.png, to look at.
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "bench/arguments.hpp"
#include "render/png_io.hpp"
#include "render/process.hpp"
#include "render/renderer.hpp"

using namespace ejecta;
using namespace ejecta::render;
namespace fs = std::filesystem;

namespace {

constexpr double kRadius = 35.0;  // [m]

struct Options {
  std::vector<long> particles{100000, 1000000};
  std::vector<int> sizes{1024, 2048};
  bool rz = false;
  bool flat = false;
  bool cut = true;
  int threads = 0;  // 0: as the environment says
  bool sweep = false;
  int repeats = 3;
  std::string out;
  bool json = false;
};

template <typename T>
std::vector<T> parseList(const char* text) {
  std::vector<T> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');)
    out.push_back(static_cast<T>(std::atol(item.c_str())));
  return out;
}

Options parseOptions(int argc, char** argv) {
  Options o;
  bench::Arguments args(argc, argv);
  for (std::string arg; args.next(arg);) {
    if (arg == "--particles")
      o.particles = parseList<long>(args.value());
    else if (arg == "--sizes")
      o.sizes = parseList<int>(args.value());
    else if (arg == "--view") {
      const std::string v = args.value();
      if (v != "3d" && v != "rz") {
        std::fprintf(stderr, "--view: 3d or rz\n");
        std::exit(2);
      }
      o.rz = v == "rz";
    } else if (arg == "--flat")
      o.flat = true;
    else if (arg == "--no-cut")
      o.cut = false;
    else if (arg == "--threads")
      o.threads = std::atoi(args.value());
    else if (arg == "--threads-sweep")
      o.sweep = true;
    else if (arg == "--repeats")
      o.repeats = std::max(1, std::atoi(args.value()));
    else if (arg == "--out")
      o.out = args.value();
    else if (arg == "--json")
      o.json = true;
    else {
      std::fprintf(stderr, "unknown option %s\n", arg.c_str());
      std::exit(2);
    }
  }
  return o;
}

double cpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

struct Clock {
  std::chrono::steady_clock::time_point wall = std::chrono::steady_clock::now();
  double cpu = cpuSeconds();
  std::pair<double, double> elapsed() const {
    return {std::chrono::duration<double>(std::chrono::steady_clock::now() - wall).count(),
            cpuSeconds() - cpu};
  }
};

// Particles uniformly in a ball (3D) or a half disc r >= 0 (RZ), deterministic.
struct Body {
  std::vector<double> x, y, z, h, temperature;
};

Body makeBody(long n, bool rz) {
  Body b;
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double volume = rz ? std::numbers::pi * kRadius * kRadius / 2.0
                           : 4.0 / 3.0 * std::numbers::pi * std::pow(kRadius, 3);
  const double spacing = std::pow(volume / static_cast<double>(n), rz ? 0.5 : 1.0 / 3.0);
  const auto count = static_cast<std::size_t>(n);
  b.x.reserve(count);
  while (b.x.size() < count) {
    double p[3] = {u(rng), u(rng), rz ? 0.0 : u(rng)};
    if (rz) p[0] = std::abs(p[0]);
    const double r2 = p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
    if (r2 > 1.0) continue;
    b.x.push_back(kRadius * p[0]);
    b.y.push_back(kRadius * p[1]);
    if (!rz) b.z.push_back(kRadius * p[2]);
    b.h.push_back(1.2 * spacing);
    // A hot core: 300 K at the surface to 3000 K at the centre.
    b.temperature.push_back(300.0 + 2700.0 * (1.0 - r2));
  }
  return b;
}

struct Record {
  long particles = 0;
  int size = 0;
  int threads = 0;
  double contextWall = 0, firstWall = 0, frameWall = 0, frameCpu = 0, pngFast = 0, pngDefault = 0;
  long pngBytes = 0, pngFastBytes = 0;
};

void printJson(const Record& r, const Options& o, const std::string& renderer) {
  std::printf(
      "{\"bench\": \"render\", \"renderer\": \"%s\", \"view\": \"%s\", \"style\": \"%s\", "
      "\"particles\": %ld, \"size\": %d, \"threads\": %d, \"context_s\": %.4f, "
      "\"first_frame_s\": %.4f, \"frame_s\": %.4f, \"frame_cpu_s\": %.4f, \"png_fast_s\": %.4f, "
      "\"png_default_s\": %.4f, \"png_bytes\": %ld, \"png_fast_bytes\": %ld, "
      "\"particles_per_s\": %.4g, "
      "\"particles_per_cpu_s\": %.4g}\n",
      renderer.c_str(), o.rz ? "rz" : "3d", o.flat ? "flat" : "shaded", r.particles, r.size,
      r.threads, r.contextWall, r.firstWall, r.frameWall, r.frameCpu, r.pngFast, r.pngDefault,
      r.pngBytes, r.pngFastBytes, r.particles / r.frameWall, r.particles / r.frameCpu);
}

int runOnce(const Options& o) {
  if (o.threads > 0) {
    // Before the first context: llvmpipe reads it once.
    const std::string t = std::to_string(o.threads);
    setenv("LP_NUM_THREADS", t.c_str(), 1);
    setenv("OMP_NUM_THREADS", t.c_str(), 1);
  }
  const char* lp = std::getenv("LP_NUM_THREADS");
  const int threads = lp ? std::atoi(lp) : static_cast<int>(sysconf(_SC_NPROCESSORS_ONLN));
  Clock contextClock;
  Renderer renderer;
  const double contextWall = contextClock.elapsed().first;
  if (!o.json)
    std::printf(
        "ejecta_bench_render: %s, LP_NUM_THREADS=%s, view %s, %s discs\n"
        "%10s %6s %10s %10s %10s %10s %9s %9s %8s %8s %12s %12s\n",
        renderer.glRenderer().c_str(), lp ? lp : "(unset: all cores)",
        o.rz ? "rz (mirrored)" : "3d (perspective, cut at z = 0)", o.flat ? "flat" : "shaded",
        "particles", "size", "context_s", "first_s", "frame_s", "frame_cpu", "png_fast",
        "png_deflt", "MB_fast", "MB_deflt", "Mpart/s", "Mpart/cpu_s");
  bool firstConfiguration = true;
  for (long n : o.particles) {
    const Body body = makeBody(n, o.rz);
    for (int size : o.sizes) {
      RenderSettings settings;
      settings.width = settings.height = size;
      renderer.setSettings(settings);
      Picture scene;
      ParticleLayer layer;
      layer.x = body.x;
      layer.y = body.y;
      layer.z = body.z;
      layer.h = body.h;
      layer.values = body.temperature;
      layer.scale.map = ColorMapName::Inferno;
      layer.scale.kind = ScaleKind::Log;
      layer.style = o.flat ? ParticleStyle::Flat : ParticleStyle::Shaded;
      layer.field = "temperature";
      layer.units = "K";
      scene.particles.push_back(layer);
      scene.annotations.time = 1.25e-3;
      scene.annotations.title = "bench: " + std::to_string(n) + " particles";
      View view;
      if (o.rz) {
        view.kind = ViewKind::Axisymmetric;
      } else {
        view.kind = ViewKind::Perspective;
        if (o.cut) view.clipPlanes.push_back({{0.0, 0.0, 1.0}, 0.0});
      }
      Record r;
      r.particles = n;
      r.size = size;
      r.threads = threads;
      r.contextWall = firstConfiguration ? contextWall : 0.0;
      Clock first;
      Frame frame = renderer.render(scene, view);
      r.firstWall = first.elapsed().first;
      r.frameWall = r.frameCpu = 1e300;
      for (int k = 0; k < o.repeats; ++k) {
        Clock c;
        frame = renderer.render(scene, view);
        const auto [wall, cpu] = c.elapsed();
        if (wall < r.frameWall) {
          r.frameWall = wall;
          r.frameCpu = cpu;
        }
      }
      Clock fast;
      const std::string fastBytes = encodePng(frame.image, {PngChannels::Rgb, true});
      r.pngFast = fast.elapsed().first;
      r.pngFastBytes = static_cast<long>(fastBytes.size());
      Clock deflt;
      const std::string bytes = encodePng(frame.image, {PngChannels::Rgb, false});
      r.pngDefault = deflt.elapsed().first;
      r.pngBytes = static_cast<long>(bytes.size());
      if (!o.out.empty()) {
        fs::create_directories(o.out);
        writePng(fs::path(o.out) / ((o.rz ? "rz_" : "3d_") + std::to_string(n) + "_" +
                                    std::to_string(size) + ".png"),
                 frame.image);
      }
      if (o.json)
        printJson(r, o, renderer.glRenderer());
      else
        std::printf(
            "%10ld %6d %10.3f %10.3f %10.3f %10.3f %9.3f %9.3f %8.2f %8.2f %12.2f %12.2f\n", n,
            size, r.contextWall, r.firstWall, r.frameWall, r.frameCpu, r.pngFast, r.pngDefault,
            r.pngFastBytes / 1e6, r.pngBytes / 1e6, n / r.frameWall / 1e6, n / r.frameCpu / 1e6);
      std::fflush(stdout);
      firstConfiguration = false;
    }
  }
  return 0;
}

// The number after "key": in a JSON line.
double field(const std::string& line, const std::string& key) {
  const auto at = line.find("\"" + key + "\": ");
  return at == std::string::npos ? 0.0 : std::atof(line.c_str() + at + key.size() + 4);
}

int sweep(const Options& o, int argc, char** argv) {
  std::vector<std::vector<std::string>> lines;
  for (int threads : {1, 2}) {
    std::vector<std::string> command{fs::read_symlink("/proc/self/exe").string()};
    for (int i = 1; i < argc; ++i)
      if (std::string(argv[i]) != "--threads-sweep" && std::string(argv[i]) != "--json")
        command.push_back(argv[i]);
    command.insert(command.end(), {"--threads", std::to_string(threads), "--json"});
    const ProcessResult r = runProcess(command);
    if (r.exitCode != 0) {
      std::fprintf(stderr, "run with %d threads failed:\n%s\n", threads, r.output.c_str());
      return 1;
    }
    std::vector<std::string> records;
    std::stringstream in(r.output);
    for (std::string line; std::getline(in, line);)
      if (line.rfind("{\"bench\"", 0) == 0) records.push_back(line);
    lines.push_back(records);
  }
  if (o.json) {
    for (const auto& records : lines)
      for (const auto& line : records) std::printf("%s\n", line.c_str());
    return 0;
  }
  std::printf(
      "ejecta_bench_render --threads-sweep: view %s, %s discs (best of %d frames)\n"
      "%10s %6s | %9s %9s %9s | %9s %9s %9s | %10s %12s\n",
      o.rz ? "rz" : "3d", o.flat ? "flat" : "shaded", o.repeats, "particles", "size", "frame_1t",
      "cpu_1t", "first_1t", "frame_2t", "cpu_2t", "first_2t", "speedup", "Mpart/cpu_s");
  for (std::size_t i = 0; i < lines[0].size() && i < lines[1].size(); ++i) {
    const std::string &a = lines[0][i], &b = lines[1][i];
    std::printf("%10.0f %6.0f | %9.3f %9.3f %9.3f | %9.3f %9.3f %9.3f | %10.2f %12.2f\n",
                field(a, "particles"), field(a, "size"), field(a, "frame_s"),
                field(a, "frame_cpu_s"), field(a, "first_frame_s"), field(b, "frame_s"),
                field(b, "frame_cpu_s"), field(b, "first_frame_s"),
                field(a, "frame_s") / field(b, "frame_s"),
                field(a, "particles") / field(a, "frame_cpu_s") / 1e6);
  }
  std::printf(
      "context creation: %.3f s (1 thread), %.3f s (2 threads); PNG of the last frame: "
      "%.3f s fast, %.3f s default\n",
      field(lines[0][0], "context_s"), field(lines[1][0], "context_s"),
      field(lines[1].back(), "png_fast_s"), field(lines[1].back(), "png_default_s"));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parseOptions(argc, argv);
  try {
    return o.sweep ? sweep(o, argc, argv) : runOnce(o);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ejecta_bench_render: %s\n", e.what());
    return 1;
  }
}
