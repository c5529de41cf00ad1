// `ejecta thermal STUDY.toml --from RUN_DIR|SNAPSHOT.h5 [--out DIR] [--json]`: the radiation
// chain on a snapshot's hot material: flux on every spacecraft patch along the pass, eq. 4.8
// face temperatures, transient walls and coating sizing (radiation/thermal_study.hpp,
// docs/thermal.md). Writes flux.csv, wall_<patch>.csv, sizing.csv and thermal.json.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "apps/commands.hpp"
#include "apps/snapshot_emitters.hpp"
#include "radiation/thermal_study.hpp"
#include "sim/atomic_file.hpp"
#include "sim/run.hpp"
#include "sim/snapshot.hpp"

namespace ejecta::app {

namespace fs = std::filesystem;

namespace {

std::string jsonText(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) >= 0x20) out += c;
  }
  return out + "\"";
}

// Where the outputs go: RUN_DIR/thermal for a run's snapshot, else runs/<study name>.
fs::path defaultOutDir(const fs::path& snapshot, const std::string& name) {
  const fs::path parent = snapshot.parent_path();
  if (parent.filename() == "snapshots") return parent.parent_path() / "thermal";
  return fs::path("runs") / name;
}

}  // namespace

int thermalCommand(const ThermalArgs& args) {
  const radiation::ThermalStudy study = radiation::loadThermalStudy(args.scene);
  if (args.from.empty())
    throw std::runtime_error(args.scene + ": no hot material: give --from RUN_DIR or --from SNAPSHOT.h5");
  const std::string snapshot = resolveSnapshotPath(args.from);
  SnapshotInfo info;
  const ParticleSet particles = readSnapshot(snapshot, info);

  SnapshotEmitterOptions options;
  options.minTemperature = study.emitters.minTemperature;
  options.defaultEmissivity = study.emitters.defaultEmissivity;
  try {
    for (const MaterialSpec& m : storedScene(info, snapshot).materials) options.materialNames.push_back(m.name);
  } catch (const std::exception&) {
    // No stored scene: the groups are "material<m>" and every material takes the default.
  }
  for (const std::string& name : options.materialNames) {
    const auto it = study.emitters.emissivityByMaterial.find(name);
    options.emissivityByMaterial.push_back(it != study.emitters.emissivityByMaterial.end()
                                               ? it->second : study.emitters.defaultEmissivity);
  }
  for (const auto& [name, eps] : study.emitters.emissivityByMaterial)
    if (std::find(options.materialNames.begin(), options.materialNames.end(), name) == options.materialNames.end())
      std::fprintf(stderr, "ejecta thermal: warning: %s: emissivity given for '%s', a material the snapshot lacks\n",
                   args.scene.c_str(), name.c_str());
  SnapshotEmitterStats stats;
  const radiation::Emitters emitters = emittersFromParticles(particles, info.geometry, options, &stats);

  const radiation::ThermalResult result = radiation::runThermalStudy(study, emitters);

  const fs::path out = args.outDir.empty() ? defaultOutDir(snapshot, study.name) : fs::path(args.outDir);
  fs::create_directories(out);
  writeFileAtomically(out / "flux.csv", radiation::formatThermalFluxCsv(result));
  for (const radiation::PatchThermal& p : result.patches)
    if (p.wall) radiation::writeWallHistoryCsv(out / ("wall_" + p.patch + ".csv"), *p.wall);
  if (!study.sizing.coatings.empty())
    writeFileAtomically(out / "sizing.csv", radiation::formatThermalSizingCsv(result));
  const std::string extra =
      "  \"snapshot\": {\"path\": " + jsonText(snapshot) + ", \"time_s\": " + std::to_string(info.time) +
      ", \"geometry\": " + jsonText(std::string(geometryName(info.geometry))) +
      ", \"particles\": " + std::to_string(stats.particles) + ", \"hot_particles\": " + std::to_string(stats.hot) +
      ", \"max_ring_copies\": " + std::to_string(stats.maxCopies) + "}";
  const std::string json = radiation::formatThermalJson(result, extra);
  writeFileAtomically(out / "thermal.json", json);

  if (args.json) {
    std::fputs(json.c_str(), stdout);
  } else {
    std::printf("snapshot %s (t = %g s, %s): %zu particles, %zu at >= %g K -> %zu emitter spheres\n",
                snapshot.c_str(), info.time, std::string(geometryName(info.geometry)).c_str(), stats.particles,
                stats.hot, study.emitters.minTemperature, stats.emitters);
    std::fputs(radiation::formatThermalText(result).c_str(), stdout);
    std::printf("wrote %s/{flux.csv, wall_<patch>.csv%s, thermal.json}\n", out.string().c_str(),
                study.sizing.coatings.empty() ? "" : ", sizing.csv");
  }
  return 0;
}

}  // namespace ejecta::app
