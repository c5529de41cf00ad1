// `ejecta run`: load a scene (or the embedded default), run it, write outputs, print a summary.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "apps/commands.hpp"
#include "coupling/run_images.hpp"
#include "coupling/run_thermal.hpp"
#include "fields/run_outputs.hpp"
#include "sim/setup/embedded_scenes.hpp"
#include "sim/run/run.hpp"
#include "sim/setup/scene.hpp"

namespace fs = std::filesystem;

namespace ejecta::app {

using namespace ejecta::coupling;  // the in-situ chain (coupling/)

namespace {

std::string readText(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw SceneError(path + ": cannot open scene file");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void printSummary(const RunOutcome& r, const std::string& outDir) {
  const RunSummary& s = r.summary;
  std::printf("ejecta: %s %s: %zu particles, %ld steps to t = %.6g s in %.2f s wall (%d threads)\n",
              s.scene.c_str(), r.ok ? "completed" : "FAILED", s.particles, s.steps, s.tEnd,
              s.wallSeconds, s.threads);
  std::printf("  energy: initial %.8g J, final %.8g J, relative error %.3g\n", s.energy.initial,
              s.energy.final, s.energy.relativeError);
  auto extra = [&](const char* key) -> const SummaryValue* {
    const SummaryValue* found = nullptr;
    for (const auto& [k, v] : s.extras)
      if (k == key) found = &v;
    return found;
  };
  auto number = [&](const char* key) {
    const SummaryValue* v = extra(key);
    return v && std::holds_alternative<double>(*v) ? std::get<double>(*v) : 0.0;
  };
  if (const SummaryValue* found = extra("crater_found")) {
    if (std::get<bool>(*found))
      std::printf("  crater: depth %.3g m, apparent diameter %.3g m, rim-to-rim %.3g m "
                  "(profile: crater_profile.csv)\n",
                  number("crater_depth_m"), number("crater_apparent_diameter_m"),
                  number("crater_rim_diameter_m"));
    else if (const SummaryValue* note = extra("crater_note"))
      std::printf("  crater: none measured (%s)\n", std::get<std::string>(*note).c_str());
  }
  if (extra("yield_J") || extra("yield_J_per_m")) {
    if (extra("yield_kt"))
      std::printf("  source: yield %.4g kt (%.4g J)", number("yield_kt"), number("yield_J"));
    else
      std::printf("  source: yield %.4g J per metre (2D planar)", number("yield_J_per_m"));
    if (extra("depth_of_burst_m")) {
      std::printf(", depth of burst %.3g m", number("depth_of_burst_m"));
      if (extra("scaled_depth_of_burst_m_per_kt3"))
        std::printf(" (scaled %.3g m/kt^1/3)", number("scaled_depth_of_burst_m_per_kt3"));
    }
    std::printf("\n");
    if (extra("target_share_of_yield"))
      std::printf("  coupling: the target holds %.1f%% of the yield (%.1f%% kinetic, %.1f%% "
                  "internal); the device keeps %.1f%%\n",
                  100 * number("target_share_of_yield"), 100 * number("target_kinetic_fraction"),
                  100 * number("target_internal_fraction"), 100 * number("explosive_share_of_yield"));
  }
  auto text = [&](const char* key) -> std::string {
    const SummaryValue* v = extra(key);
    return v && std::holds_alternative<std::string>(*v) ? std::get<std::string>(*v) : std::string();
  };
  if (extra("thermal_time_s")) {
    const auto count = [&](const char* key) {
      const SummaryValue* v = extra(key);
      return v && std::holds_alternative<std::int64_t>(*v) ? std::get<std::int64_t>(*v) : 0;
    };
    std::printf("  spacecraft: the hottest of %ld pass(es), %s t = %.3g ms (%s/; up to %ld hot "
                "particles -> %ld emitters)\n",
                static_cast<long>(count("thermal_passes")),
                text("thermal_hot_material") == "evolving" ? "the one from" : "over the rock of",
                number("thermal_time_s") * 1e3,
                text("thermal_dir").c_str(), static_cast<long>(count("thermal_hot_particles")),
                static_cast<long>(count("thermal_emitters")));
    std::printf("    %-8s %15s %18s %14s\n", "face", "peak flux", "steady (eq. 4.8)", "wall peak");
    std::stringstream faces(text("thermal_faces"));
    for (std::string face; std::getline(faces, face, ',');) {
      const std::string k = "thermal_" + face;
      std::printf("    %-8s %9.3g W/m^2 %16.0f K", face.c_str(), number((k + "_peak_flux_W_m2").c_str()),
                  number((k + "_steady_K").c_str()));
      if (extra((k + "_structure_peak_K").c_str()))
        std::printf(" %12.0f K", number((k + "_structure_peak_K").c_str()));
      std::printf("\n");
    }
    std::printf("  shield: %s\n", text("thermal_shield").c_str());
  }
  if (extra("thermal_note")) std::printf("  thermal: %s\n", text("thermal_note").c_str());
  // One line per gauge: the pulse it recorded (sim/sources/gauge_decay.hpp).
  for (const auto& [k, v] : s.extras) {
    const std::string suffix = "_peak_pressure_Pa";
    if (k.rfind("gauge_", 0) != 0 || k.size() <= suffix.size() + 6 ||
        k.compare(k.size() - suffix.size(), suffix.size(), suffix) != 0)
      continue;
    const std::string g = k.substr(0, k.size() - suffix.size());
    std::printf("  gauge %s: peak %.4g MPa at %.4g ms", g.substr(6).c_str(), std::get<double>(v) * 1e-6,
                number((g + "_peak_time_s").c_str()) * 1e3);
    if (extra((g + "_decay_time_s").c_str()))
      std::printf(", decay constant %.3g us (1/e; fit %.3g us)", number((g + "_decay_time_s").c_str()) * 1e6,
                  number((g + "_decay_fit_s").c_str()) * 1e6);
    std::printf("\n");
  }
  if (!outDir.empty()) {
    const fs::path dir(outDir);
    std::printf("  outputs: %s/{summary.json, energy.csv, snapshots.xdmf, snapshots/%s%s%s%s%s%s}\n",
                outDir.c_str(), fs::is_directory(dir / "fields") ? ", fields/" : "",
                extra("thermal_time_s") ? ", thermal_*/" : "",
                fs::is_directory(dir / "images") ? ", images/" : "",
                fs::exists(dir / "gauges.csv") ? ", gauges.csv" : "",
                fs::exists(dir / "crater_profile.csv") ? ", crater_profile.csv" : "",
                fs::exists(dir / "crater_history.csv") ? ", crater_history.csv" : "");
    if (const SummaryValue* charts = extra("charts"))
      std::printf("  charts: %s\n", std::get<std::string>(*charts).c_str());
    else if (const SummaryValue* note = extra("charts_note"))
      std::printf("  charts: %s\n", std::get<std::string>(*note).c_str());
  }
  if (!r.ok) std::fprintf(stderr, "ejecta: run failed: %s\n", r.error.c_str());
}

}  // namespace

int runCommand(const RunArgs& args) {
  RunOptions options;
  options.threads = args.threads;
  options.progress = !args.quiet && interactive();
  options.configure = [charts = args.charts](const Scene& scene, RunOptions& o) {
    fields::addFieldOutputs(o, scene);
    addImageOutputs(o, scene, charts);
    addThermalOutputs(o, scene, charts);
  };
  if (!args.restartDir.empty()) {
    if (!args.scene.empty() || !args.overrides.empty())
      throw std::runtime_error("--restart takes the scene and overrides stored in the run; "
                               "do not give a SCENE or --set with it");
    const RunOutcome r = restartRun(args.restartDir, options);
    printSummary(r, args.restartDir);
    return r.ok ? 0 : 2;
  }
  std::string source, path;
  if (args.scene.empty()) {
    source = std::string(findEmbeddedScene("default"));
    path = "<default scene>";
  } else {
    path = args.scene;
    source = readText(path);
  }
  const Scene scene = parseScene(source, path, args.overrides);
  options.outDir = args.outDir.empty() ? (fs::path("runs") / scene.name).string() : args.outDir;
  options.sceneSource = source;
  options.overrides = args.overrides;
  std::fprintf(stderr, "ejecta: running '%s' (%s) -> %s\n", scene.name.c_str(), path.c_str(),
               options.outDir.c_str());
  const RunOutcome r = runScene(scene, options);
  printSummary(r, options.outDir);
  return r.ok ? 0 : 2;
}

}  // namespace ejecta::app
