// ejecta_bench_memory: the memory a run takes per particle, measured, against the constant the
// memory check uses (sim/setup/memory_estimate.hpp, bytesPerParticle). Runs `ejecta run` on one
// scene at two spacings as child processes, reads each one's peak resident memory (wait4's
// rusage) and particle count (summary.json), and prints the slope: bytes per extra particle.
// The intercept (libraries, OpenMP pools, the code) is left out of the slope.
//
//   ejecta_bench_memory [--scene verification/sedov_3d] [--bodies 0] [--spacings 0.04,0.0278]
//                       [--set KEY=VALUE ...] [--ejecta build/apps/ejecta] [--json]
// Defaults: the 3D Sedov (hydro) at 15,625 and 46,656 particles, a few steps (time.t_end set
// short), snapshots off. For the solid-mechanics figure:
//   ejecta_bench_memory --scene impact_3d_oblique --bodies 1,2 --spacings 1.25,1 --set "time.t_end=20 us"
// (--bodies: the indices of the bodies whose spacing changes; the impactor keeps its own).
#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "arguments.hpp"
#include "sim/setup/memory_estimate.hpp"
#include "sim/setup/scene.hpp"
#include "sim/setup/scene_catalog.hpp"

extern char** environ;

namespace fs = std::filesystem;

namespace {

struct Measure {
  double spacing = 0.0;
  long particles = 0;
  double peakBytes = 0.0;
};

std::vector<double> numbers(const std::string& list) {
  std::vector<double> out;
  std::stringstream s(list);
  for (std::string item; std::getline(s, item, ',');) out.push_back(std::stod(item));
  return out;
}

long summaryParticles(const fs::path& summary) {
  std::ifstream in(summary);
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  const std::size_t at = s.find("\"particles\":");
  return at == std::string::npos ? -1 : std::stol(s.substr(at + 12));
}

Measure run(const std::string& ejecta, const std::string& scene, const std::vector<double>& bodies, double spacing,
            const std::vector<std::string>& sets, const fs::path& out) {
  std::vector<std::string> args{ejecta, "run", scene, "--out", out.string(), "--overwrite",
                                "--quiet", "--no-charts"};
  for (const double b : bodies) {
    char text[96];
    std::snprintf(text, sizeof text, "bodies[%d].spacing=%.17g", static_cast<int>(b), spacing);
    args.insert(args.end(), {"--set", text});
  }
  for (const std::string& s : sets) args.insert(args.end(), {"--set", s});
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  // The runs' own output would bury the table: to /dev/null.
  posix_spawn_file_actions_t quiet;
  posix_spawn_file_actions_init(&quiet);
  posix_spawn_file_actions_addopen(&quiet, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&quiet, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, ejecta.c_str(), &quiet, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&quiet);
  if (spawned != 0) {
    std::fprintf(stderr, "ejecta_bench_memory: cannot start %s\n", ejecta.c_str());
    std::exit(2);
  }
  int status = 0;
  rusage usage{};
  if (wait4(pid, &status, 0, &usage) != pid) {
    std::fprintf(stderr, "ejecta_bench_memory: lost the run at spacing %g\n", spacing);
    std::exit(2);
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::fprintf(stderr, "ejecta_bench_memory: the run at spacing %g failed (status %d); its summary: %s\n",
                 spacing, WIFEXITED(status) ? WEXITSTATUS(status) : -1, (out / "summary.json").c_str());
    std::exit(2);
  }
  return {spacing, summaryParticles(out / "summary.json"), 1024.0 * static_cast<double>(usage.ru_maxrss)};
}

}  // namespace

int main(int argc, char** argv) {
  std::string scene = "verification/sedov_3d", ejecta = EJECTA_BINARY_DIR "/apps/ejecta";
  std::vector<double> bodies{0};
  std::vector<double> spacings{0.04, 1.0 / 36.0};
  std::vector<std::string> sets{"time.t_end=0.001 s", "output.snapshots=false"};
  bool json = false;
  ejecta::bench::Arguments a(argc, argv);
  for (std::string o; a.next(o);) {
    if (o == "--scene") scene = a.value();
    else if (o == "--bodies") bodies = numbers(a.value());
    else if (o == "--spacings") spacings = numbers(a.value());
    else if (o == "--set") sets.push_back(a.value());
    else if (o == "--ejecta") ejecta = a.value();
    else if (o == "--json") json = true;
    else {
      std::fprintf(stderr, "ejecta_bench_memory: unknown option %s (see the top of bench/memory.cpp)\n", o.c_str());
      return 2;
    }
  }
  if (spacings.size() != 2) {
    std::fprintf(stderr, "ejecta_bench_memory: --spacings takes two values, coarse then fine\n");
    return 2;
  }
  const fs::path dir = fs::temp_directory_path() / ("ejecta_bench_memory_" + std::to_string(::getpid()));
  const Measure coarse = run(ejecta, scene, bodies, spacings[0], sets, dir / "coarse");
  const Measure fine = run(ejecta, scene, bodies, spacings[1], sets, dir / "fine");
  fs::remove_all(dir);
  if (fine.particles <= coarse.particles) {
    std::fprintf(stderr, "ejecta_bench_memory: the finer spacing gave no more particles (%ld, %ld)\n",
                 coarse.particles, fine.particles);
    return 2;
  }
  const double slope = (fine.peakBytes - coarse.peakBytes) / static_cast<double>(fine.particles - coarse.particles);
  // What the memory check assumes for this scene with these settings.
  const ejecta::SceneText text = ejecta::readSceneArgument(scene);
  const double assumed = ejecta::bytesPerParticle(ejecta::parseScene(text.text, text.label, sets));
  if (json) {
    std::printf("{\"scene\": \"%s\", \"particles\": [%ld, %ld], \"peak_bytes\": [%.0f, %.0f], "
                "\"bytes_per_particle\": %.1f, \"estimate_bytes_per_particle\": %.1f}\n",
                scene.c_str(), coarse.particles, fine.particles, coarse.peakBytes, fine.peakBytes, slope,
                assumed);
    return 0;
  }
  std::printf("%s: peak resident memory of `ejecta run`\n", scene.c_str());
  for (const Measure& m : {coarse, fine})
    std::printf("  spacing %-10.4g %9ld particles  %8.1f MB\n", m.spacing, m.particles, m.peakBytes / 1e6);
  std::printf("  slope: %.0f bytes per particle (%.2f kB); the memory check assumes %.0f (%.2f of it)\n", slope,
              slope / 1024.0, assumed, slope / assumed);
  return 0;
}
