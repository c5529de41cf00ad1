// `ejecta sweep SCENE --vary key=v1,v2,...`: runs the variants of a scene as separate `ejecta run`
// processes (several at once where cores allow), then collects what each coupled into the
// target into sweep.csv, prints it as a table and charts it as sweep.png (coupling/sweep_chart.hpp;
// docs/coupling.md, docs/asteroid_studies.md). Under `mpirun -np N` the variants are spread over
// groups of ranks instead, each variant a distributed run on its group (docs/parallel.md).
#include <nlohmann/json.hpp>
#include <omp.h>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "apps/commands.hpp"
#include "coupling/sweep_chart.hpp"
#include "core/atomic_file.hpp"
#include "render/charts.hpp"
#include "sim/parallel/communicator.hpp"
#include "sim/run/run.hpp"
#include "sim/run/sweep.hpp"
#include "sim/setup/scene.hpp"
#include "sim/setup/scene_catalog.hpp"

extern char** environ;

namespace fs = std::filesystem;

namespace ejecta::app {

using namespace ejecta::coupling;  // the in-situ chain (coupling/)

namespace {

// Summary keys reported per variant when present, in this order.
const std::vector<std::string> kReported{
    "target_share_of_yield",  "target_kinetic_fraction", "target_internal_fraction",
    "explosive_share_of_yield", "target_share_of_impactor_energy", "yield_kt",
    "depth_of_burst_m",       "scaled_depth_of_burst_m_per_kt3", "crater_depth_m",
    "crater_apparent_diameter_m"};

struct Child {
  pid_t pid = 0;
  std::size_t variant = 0;
};

pid_t spawnRun(const std::string& scene, const std::vector<std::string>& overrides,
               const std::string& outDir, int threads, const fs::path& log) {
  std::vector<std::string> args{"ejecta", "run", scene, "--out", outDir, "--threads",
                                std::to_string(threads), "--quiet"};
  for (const std::string& o : overrides) {
    args.push_back("--set");
    args.push_back(o);
  }
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, "/proc/self/exe", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw std::runtime_error("sweep: cannot start 'ejecta run' (" + std::to_string(rc) + ")");
  return pid;
}

// One rank: each variant a separate `ejecta run` process, as many at once as cores allow (each
// with its share of the threads); returns their exit statuses.
std::vector<int> runVariantsAsProcesses(const SweepArgs& args,
                                        const std::vector<std::vector<std::string>>& variants,
                                        const std::string& name, const fs::path& out,
                                        const std::function<fs::path(std::size_t)>& dirOf) {
  fs::create_directories(out);
  // The cores this sweep may use: OMP_NUM_THREADS when set (a shared machine), else all.
  const int cores = std::max(1, std::min(omp_get_num_procs(), omp_get_max_threads()));
  const int jobs = std::clamp(args.jobs > 0 ? args.jobs : cores, 1, static_cast<int>(variants.size()));
  const int threads = std::max(1, cores / jobs);
  std::fprintf(stderr, "ejecta: sweep of '%s': %zu variants, %d at a time with %d thread%s each -> %s\n",
               name.c_str(), variants.size(), jobs, threads, threads == 1 ? "" : "s", out.c_str());

  std::vector<int> status(variants.size(), -1);
  std::vector<Child> running;
  std::size_t next = 0;
  while (next < variants.size() || !running.empty()) {
    while (next < variants.size() && static_cast<int>(running.size()) < jobs) {
      std::vector<std::string> all = args.overrides;
      all.insert(all.end(), variants[next].begin(), variants[next].end());
      fs::create_directories(dirOf(next));
      running.push_back({spawnRun(args.scene, all, dirOf(next).string(), threads,
                                  dirOf(next) / "run.log"), next});
      ++next;
    }
    int wstatus = 0;
    const pid_t done = ::wait(&wstatus);
    if (done < 0) throw std::runtime_error("sweep: wait failed");
    for (auto it = running.begin(); it != running.end(); ++it)
      if (it->pid == done) {
        status[it->variant] = WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : 128;
        std::fprintf(stderr, "ejecta: variant %zu (%s) %s\n", it->variant,
                     variants[it->variant].front().c_str(),
                     status[it->variant] == 0 ? "done" : "FAILED (see its run.log)");
        running.erase(it);
        break;
      }
  }
  return status;
}

// Under an MPI launcher: the ranks split into min(ranks, variants) groups, group g runs variants
// g, g + groups, ... in this process (each a distributed run on the group's sub-communicator),
// and rank 0 learns every variant's exit status (0 completed, 2 failed, 1 an error). A variant's
// run.log holds its outcome.
std::vector<int> runVariantsOnRanks(const Communicator& world, const SweepArgs& args,
                                    const std::vector<std::vector<std::string>>& variants,
                                    const std::function<fs::path(std::size_t)>& dirOf) {
  const int groups = std::min(world.size(), static_cast<int>(variants.size()));
  const int group = world.rank() * groups / world.size();
  const std::shared_ptr<const Communicator> ranks = world.split(group);
  const SceneText scene = readSceneArgument(args.scene);
  std::vector<int> status(variants.size(), 0);
  for (std::size_t k = static_cast<std::size_t>(group); k < variants.size(); k += static_cast<std::size_t>(groups)) {
    std::vector<std::string> all = args.overrides;
    all.insert(all.end(), variants[k].begin(), variants[k].end());
    RunOptions options;
    options.outDir = dirOf(k).string();
    options.sceneSource = scene.text;
    options.overrides = all;
    options.ranks = ranks;
    options.configure = [](const Scene& s, RunOptions& o) { addInSituOutputs(s, o, true); };
    std::string outcome;
    try {
      const RunOutcome r = runScene(parseScene(scene.text, scene.label, all), options);
      status[k] = r.ok ? 0 : 2;
      outcome = r.ok ? "completed" : "failed: " + r.error;
    } catch (const SceneError& e) {  // a bad scene: raised alike on every rank of the group
      status[k] = 1;
      outcome = std::string("error: ") + e.what();
    } catch (const std::exception& e) {
      // Another error (a file rank 0 cannot write) may be on one rank only, with the others in
      // a collective of this variant: the next variant's collectives would pair with theirs.
      std::fprintf(stderr, "ejecta: sweep: variant %zu: %s\n", k, e.what());
      MpiSession::abortAll(1);
      throw;
    }
    if (ranks->isRoot()) {
      std::ofstream log(dirOf(k) / "run.log");
      log << "ejecta: variant " << k << " on " << ranks->size() << " rank(s): " << outcome << "\n";
      std::fprintf(stderr, "ejecta: variant %zu (%s) %s\n", k, variants[k].front().c_str(),
                   status[k] == 0 ? "done" : "FAILED (see its run.log)");
    }
  }
  // Each group's root reports its variants; the others report 0 (the sum is the status).
  std::vector<std::uint64_t> reported(variants.size());
  for (std::size_t k = 0; k < variants.size(); ++k)
    reported[k] = ranks->isRoot() ? static_cast<std::uint64_t>(status[k]) : 0;
  world.sumInPlace(reported);
  return {reported.begin(), reported.end()};
}

std::string csvCell(std::string s) {
  if (s.find_first_of(",\"") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

// sweep.png from sweep.csv, or a line saying why there is none; a sweep never fails for a chart.
void writeSweepChart(const fs::path& out, const std::string& name, const std::vector<SweepAxis>& axes,
                     const std::map<std::string, std::vector<std::optional<double>>>& numeric) {
  const SweepChartChoice choice = chooseSweepChart(axes, numeric);
  if (!choice.draw) {
    std::printf("ejecta: no sweep chart: %s\n", choice.why.c_str());
    return;
  }
  render::ChartRunner charts;
  if (!charts.chartsAvailable()) {
    std::printf("ejecta: no sweep chart: %s (sweep.csv is written)\n",
                charts.unavailableReason().c_str());
    return;
  }
  render::ChartSpec spec{.kind = choice.bars ? render::ChartKind::Bar : render::ChartKind::Line,
                         .csv = out / "sweep.csv",
                         .x = choice.x,
                         .series = {{.y = choice.y, .label = choice.ylabel, .markers = true}},
                         .xlabel = choice.xlabel,
                         .ylabel = choice.ylabel,
                         .title = name + ": energy coupled into the target",
                         .out = out / "sweep.png"};
  try {
    charts.writeChart(spec);
    std::printf("ejecta: sweep chart: %s\n", (out / "sweep.png").c_str());
  } catch (const std::exception& e) {
    std::printf("ejecta: sweep chart failed: %s\n", e.what());
  }
}

}  // namespace

int sweepCommand(const SweepArgs& args) {
  std::vector<SweepAxis> axes;
  for (const std::string& v : args.vary) axes.push_back(parseSweepAxis(v));
  const std::vector<std::vector<std::string>> variants = sweepVariants(axes);
  // Validate every variant before running any: a bad value fails now, naming the key.
  const SceneText scene = readSceneArgument(args.scene);
  std::string name;
  for (const auto& overrides : variants) {
    std::vector<std::string> all = args.overrides;
    all.insert(all.end(), overrides.begin(), overrides.end());
    name = parseScene(scene.text, scene.label, all).name;
  }
  const fs::path out = args.outDir.empty() ? fs::path("runs") / (name + "_sweep") : fs::path(args.outDir);
  const std::shared_ptr<const Communicator> world = worldCommunicator();
  auto dirOf = [&](std::size_t k) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "variant_%03zu", k);
    return out / buf;
  };
  std::vector<int> status(variants.size(), -1);
  if (world->size() > 1) {
    if (world->isRoot()) {
      for (std::size_t k = 0; k < variants.size(); ++k) fs::create_directories(dirOf(k));
      std::fprintf(stderr, "ejecta: sweep of '%s': %zu variants over %d ranks -> %s\n", name.c_str(),
                   variants.size(), world->size(), out.c_str());
    }
    world->sum(0);  // the folders exist before any group writes
    status = runVariantsOnRanks(*world, args, variants, dirOf);
    if (!world->isRoot()) return 0;  // rank 0 tabulates and returns the sweep's status
  } else {
    status = runVariantsAsProcesses(args, variants, name, out, dirOf);
  }

  // Collect: one row per variant, the varied values and what the summary reports.
  std::ostringstream csv;
  csv << "variant";
  for (const SweepAxis& a : axes) csv << ',' << csvCell(a.key);
  csv << ",status";
  std::vector<std::string> columns;
  std::vector<std::map<std::string, double>> values(variants.size());
  std::map<std::string, std::vector<std::optional<double>>> numeric;
  for (std::size_t k = 0; k < variants.size(); ++k) {
    std::ifstream in(dirOf(k) / "summary.json");
    if (!in) continue;
    const nlohmann::json extras = nlohmann::json::parse(in)["extras"];
    for (const std::string& key : kReported)
      if (extras.contains(key) && extras[key].is_number()) values[k][key] = extras[key].get<double>();
  }
  for (const std::string& key : kReported)
    for (const auto& v : values)
      if (v.count(key)) {
        columns.push_back(key);
        break;
      }
  // The chart takes completed variants only: a run that stopped still writes its shares so far
  // (sweep.csv keeps them, marked failed), and a chart would draw them as results.
  for (const std::string& c : columns) {
    csv << ',' << c;
    auto& column = numeric[c];
    for (std::size_t k = 0; k < variants.size(); ++k) {
      const auto it = values[k].find(c);
      column.push_back(it == values[k].end() || status[k] != 0 ? std::nullopt
                                                                  : std::optional<double>(it->second));
    }
  }
  csv << ",label\n";  // the variant's values as a chart's tick label
  csv.precision(8);
  std::printf("%-8s", "variant");
  for (const SweepAxis& a : axes) std::printf("  %-24s", a.key.c_str());
  std::printf("  %-9s", "status");
  for (const std::string& c : columns) std::printf("  %-14.14s", c.c_str());
  std::printf("\n");
  for (std::size_t k = 0; k < variants.size(); ++k) {
    csv << k;
    std::printf("%-8zu", k);
    for (const SweepAxis& a : axes) {
      csv << ',' << csvCell(a.values[k]);
      std::printf("  %-24s", a.values[k].c_str());
    }
    csv << ',' << (status[k] == 0 ? "completed" : "failed");
    std::printf("  %-9s", status[k] == 0 ? "completed" : "FAILED");
    for (const std::string& c : columns) {
      const auto it = values[k].find(c);
      if (it != values[k].end()) {
        csv << ',' << it->second;
        std::printf("  %-14.6g", it->second);
      } else {
        csv << ',';
        std::printf("  %-14s", "-");
      }
    }
    std::vector<std::string> varied;
    for (const SweepAxis& a : axes) varied.push_back(a.values[k]);
    csv << ',' << csvCell(sweepVariantLabel(varied)) << '\n';
    std::printf("\n");
  }
  writeFileAtomically(out / "sweep.csv", csv.str());
  std::printf("ejecta: sweep table: %s\n", (out / "sweep.csv").c_str());
  writeSweepChart(out, name, axes, numeric);
  const bool allOk = std::all_of(status.begin(), status.end(), [](int s) { return s == 0; });
  return allOk ? 0 : 2;
}

}  // namespace ejecta::app
