// Individual against global time steps on one verification problem (docs/time_steps.md): runs
// it with `[time] stepping = "global"` and `"individual"` at the same resolution and prints, for
// each, the (sub-)steps, the particle-steps, the wall time, the particle-steps per second per
// core, the problem's error measures and the energy error; then the ratios individual/global.
//
//   ejecta_bench_time_steps [--problem sedov_rz] [--threads T] [--set KEY=VALUE]... [--json]
//                           [--limiter-factor F]
//   ejecta_bench_time_steps --scene scenes/case2_rz_follower.toml [--threads T] [--set ...]
//
// `--set` goes to both runs (e.g. --set "bodies[0].spacing=0.01" for a coarser Sedov 2D).
// `--scene`: any scene, run with its in-situ grids and crater; with no exact answer, the measures
// are the summary's numbers (the crater, the coupled shares), side by side.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <variant>
#include <vector>

#include "bench/arguments.hpp"
#include "fields/run_outputs.hpp"
#include "sim/run/run.hpp"
#include "sim/setup/scene.hpp"
#include "sim/verify/verification.hpp"

using namespace ejecta;

namespace {

// A scene file with global and with individual steps, reported as the problems are: the run's
// numbers as ResolutionRun, the summary's numeric extras as its measures.
int compareScene(const std::string& file, const std::vector<std::string>& overrides, int threads,
                 const std::string& limiter) {
  verify::ResolutionRun runs[2];
  const char* names[2] = {"global", "individual"};
  for (int k = 0; k < 2; ++k) {
    std::vector<std::string> set = overrides;
    set.push_back(std::string("time.stepping=") + names[k]);
    if (k == 1 && !limiter.empty()) set.push_back("time.limiter_factor=" + limiter);
    const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                      ("ejecta_bench_time_steps_" + std::string(names[k]));
    std::filesystem::remove_all(dir);
    RunOptions options;
    options.outDir = dir.string();
    options.threads = threads;
    options.configure = [](const Scene& s, RunOptions& o) { fields::addFieldOutputs(o, s); };
    const RunOutcome r = runScene(loadScene(file, set), options);
    std::filesystem::remove_all(dir);
    if (!r.ok) {
      std::fprintf(stderr, "ejecta_bench_time_steps: %s (%s): %s\n", file.c_str(), names[k],
                   r.error.c_str());
      return 1;
    }
    verify::ResolutionRun& run = runs[k];
    run.particles = r.summary.particles;
    run.steps = r.summary.steps;
    run.wallSeconds = r.summary.wallSeconds;
    run.energyError = r.summary.energy.relativeError;
    run.particleUpdates = r.summary.has("particle_updates")
                              ? static_cast<std::uint64_t>(r.summary.integer("particle_updates"))
                              : static_cast<std::uint64_t>(r.summary.particles) *
                                    static_cast<std::uint64_t>(r.summary.steps);
    for (const auto& [key, value] : r.summary.extras)
      if (const double* x = std::get_if<double>(&value);
          x && (key.rfind("crater_", 0) == 0 || key.find("share") != std::string::npos))
        run.metrics.push_back({key, *x, ""});
  }
  std::printf("%s, %zu particles, %d threads\n", file.c_str(), runs[0].particles, threads);
  for (int k = 0; k < 2; ++k)
    std::printf("  %-10s %8ld steps %14llu particle-steps %9.2f s wall  energy error %.2e\n",
                names[k], runs[k].steps, static_cast<unsigned long long>(runs[k].particleUpdates),
                runs[k].wallSeconds, runs[k].energyError);
  std::printf("  %-36s %14s %14s %10s\n", "measure", "global", "individual", "change");
  for (const verify::Metric& m : runs[0].metrics)
    for (const verify::Metric& n : runs[1].metrics)
      if (n.name == m.name)
        std::printf("  %-36s %14.6g %14.6g %+9.2f%%\n", m.name.c_str(), m.value, n.value,
                    m.value != 0.0 ? 100.0 * (n.value - m.value) / std::abs(m.value) : 0.0);
  const double wallRatio = runs[1].wallSeconds / runs[0].wallSeconds;
  std::printf("  individual / global: wall %.3f (%.2fx faster), particle-steps %.4f\n", wallRatio,
              1.0 / wallRatio,
              static_cast<double>(runs[1].particleUpdates) / static_cast<double>(runs[0].particleUpdates));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::string problem = "sedov_rz";
  int threads = 0;
  bool json = false;
  std::vector<std::string> overrides;
  std::string limiter, scene;
  bench::Arguments args(argc, argv);
  for (std::string arg; args.next(arg);) {
    if (arg == "--problem") problem = args.value();
    else if (arg == "--threads") threads = std::atoi(args.value());
    else if (arg == "--set") overrides.emplace_back(args.value());
    else if (arg == "--limiter-factor") limiter = args.value();
    else if (arg == "--scene") scene = args.value();
    else if (arg == "--json") json = true;
    else { std::fprintf(stderr, "unknown option %s\n", arg.c_str()); return 2; }
  }
  const int nThreads = resolveThreads(threads);
  if (!scene.empty()) {
    try {
      return compareScene(scene, overrides, nThreads, limiter);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "ejecta_bench_time_steps: %s\n", e.what());
      return 1;
    }
  }
  verify::Options options;
  options.threads = nThreads;
  options.resolutions = 1;
  options.overrides = overrides;
  std::vector<verify::ResolutionRun> runs;
  try {
    runs.push_back(verify::runProblem(problem, options).runs.back());
    options.overrides.push_back("time.stepping=individual");
    if (!limiter.empty()) options.overrides.push_back("time.limiter_factor=" + limiter);
    runs.push_back(verify::runProblem(problem, options).runs.back());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ejecta_bench_time_steps: %s\n", e.what());
    return 1;
  }
  const char* names[2] = {"global", "individual"};
  auto perCore = [&](const verify::ResolutionRun& r) {
    return r.wallSeconds > 0 ? static_cast<double>(r.particleUpdates) / r.wallSeconds / nThreads : 0.0;
  };
  const double wallRatio = runs[1].wallSeconds / runs[0].wallSeconds;
  const double updateRatio =
      static_cast<double>(runs[1].particleUpdates) / static_cast<double>(runs[0].particleUpdates);
  if (json) {
    std::printf("{\"problem\": \"%s\", \"threads\": %d, \"particles\": %zu, \"runs\": [", problem.c_str(),
                nThreads, runs[0].particles);
    for (int k = 0; k < 2; ++k) {
      const verify::ResolutionRun& r = runs[static_cast<std::size_t>(k)];
      std::printf("%s{\"stepping\": \"%s\", \"steps\": %ld, \"particle_updates\": %llu, "
                  "\"wall_seconds\": %.3f, \"updates_per_second_per_core\": %.4g, "
                  "\"energy_error\": %.3g",
                  k ? ", " : "", names[k], r.steps, static_cast<unsigned long long>(r.particleUpdates),
                  r.wallSeconds, perCore(r), r.energyError);
      for (const verify::Metric& m : r.metrics) std::printf(", \"%s\": %.6g", m.name.c_str(), m.value);
      std::printf("}");
    }
    std::printf("], \"wall_ratio\": %.4f, \"update_ratio\": %.4f}\n", wallRatio, updateRatio);
    return 0;
  }
  std::printf("%s, %zu particles, %d threads\n", problem.c_str(), runs[0].particles, nThreads);
  std::printf("  %-10s %8s %14s %9s %16s %11s\n", "stepping", "steps", "particle-steps",
              "wall [s]", "steps/s per core", "energy err");
  for (int k = 0; k < 2; ++k) {
    const verify::ResolutionRun& r = runs[static_cast<std::size_t>(k)];
    std::printf("  %-10s %8ld %14llu %9.2f %16.4g %11.2e\n", names[k], r.steps,
                static_cast<unsigned long long>(r.particleUpdates), r.wallSeconds, perCore(r),
                r.energyError);
  }
  // The problem's own error measures, side by side.
  std::printf("  %-28s %14s %14s\n", "measure", "global", "individual");
  for (std::size_t m = 0; m < runs[0].metrics.size() && m < runs[1].metrics.size(); ++m)
    std::printf("  %-28s %14.6g %14.6g %s\n", runs[0].metrics[m].name.c_str(),
                runs[0].metrics[m].value, runs[1].metrics[m].value, runs[0].metrics[m].unit.c_str());
  std::printf("  individual / global: wall %.3f (%.2fx faster), particle-steps %.4f\n", wallRatio,
              1.0 / wallRatio, updateRatio);
  return 0;
}
