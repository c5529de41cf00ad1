#include "fields/run_outputs.hpp"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "core/atomic_file.hpp"
#include "fields/crater_history.hpp"
#include "fields/crater_summary.hpp"
#include "fields/crater_setup.hpp"
#include "fields/grid_set.hpp"
#include "fields/measure_crater.hpp"
#include "fields/vdb_grids.hpp"

namespace fs = std::filesystem;

namespace ejecta::fields {

std::string fieldFileName(long snapshotIndex) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "fields_%04ld.vdb", snapshotIndex);
  return buf;
}

void addFieldOutputs(RunOptions& options, const Scene& scene,
                     std::function<void(const CraterSummary&)> onCrater) {
  if (options.outDir.empty() || scene.geometry == Geometry::Line) return;
  const std::string outDir = options.outDir;
  const ParticleContext ctx = ParticleContext::fromScene(scene);
  // Worked out now, so a scene whose target cannot be found fails before the run, not after.
  const std::optional<CraterSetup> crater = craterSetupFromScene(scene);

  if (scene.fields.enabled) {
    const GridRequest request = GridRequest::fromScene(scene.fields);
    const int every = scene.fields.every;
    const bool levelSet = scene.fields.levelSet;
    const std::string sceneName = scene.name;
    auto previous = options.onOutput;
    options.onOutput = [=](const Simulation& sim, const SnapshotInfo& info, bool final) {
      if (previous) previous(sim, info, final);
      if (!final && info.snapshotIndex % every != 0) return;
      // Every rank splats its own particles; rank 0 writes the sum.
      const GridSet set = buildGridSet(sim.particles(), ctx, request, &sim.ranks());
      if (!sim.ranks().isRoot()) return;
      GridFileMeta meta;
      meta.scene = sceneName;
      meta.time = info.time;
      meta.step = info.step;
      meta.levelSet = levelSet;
      meta.crater = crater;
      writeGridFile((fs::path(outDir) / "fields" / fieldFileName(info.snapshotIndex)).string(), set, meta);
    };
  }

  if (crater) {
    const double resolution = scene.crater.resolution;
    // The crater at every output, into crater_history.csv. The last output's measurement is
    // kept for the summary, so that the two agree and the end is not measured twice.
    struct Tracking {
      CraterHistory history;
      std::optional<CraterMetrics> last;
      double lastTime = 0.0;
    };
    auto tracking = std::make_shared<Tracking>(
        Tracking{CraterHistory(fs::path(outDir) / "crater_history.csv", crater->planar), {}, 0.0});
    auto previousOutput = options.onOutput;
    options.onOutput = [=](const Simulation& sim, const SnapshotInfo& info, bool final) {
      if (previousOutput) previousOutput(sim, info, final);
      CraterMetrics m;
      try {
        m = measureCrater(sim.particles(), ctx, *crater, resolution, &sim.ranks());
      } catch (const std::exception& e) {
        // A row that says "not found" (found = 0); the run goes on.
        m = CraterMetrics{};
        m.note = std::string("crater measurement failed: ") + e.what();
      }
      // Every rank keeps when it measured (so all agree on measuring again at the end).
      tracking->last = m;
      tracking->lastTime = info.time;
      if (sim.ranks().isRoot()) tracking->history.record(info.time, m);
    };
    auto previous = options.onFinish;
    options.onFinish = [=](const Simulation& sim, RunSummary& summary) {
      if (previous) previous(sim, summary);
      try {
        const CraterMetrics m = tracking->last && tracking->lastTime == sim.time()
                                    ? *tracking->last
                                    : measureCrater(sim.particles(), ctx, *crater, resolution, &sim.ranks());
        if (!sim.ranks().isRoot()) return;
        CraterSummary c = craterSummary(m, crater->planar);
        if (crater->scaling) {
          c.scalingClass = crater->scaling->law.name;
          c.scaled = scaleCrater(crater->scaling->law, crater->scaling->impact);
        }
        std::vector<std::string> rows = tracking->history.rows();
        if (!(tracking->last && tracking->lastTime == sim.time()))
          rows.push_back(craterHistoryRow(sim.time(), m, crater->planar));
        c.growth = craterGrowth(rows);
        addToSummary(c, summary);
        writeFileAtomically(fs::path(outDir) / "crater_profile.csv", craterProfileCsv(m));
        if (onCrater) onCrater(c);
      } catch (const std::exception& e) {
        if (!sim.ranks().isRoot()) return;
        // The run's own results stand; say why the crater is missing.
        const CraterSummary c = craterFailure(std::string("crater measurement failed: ") + e.what());
        addToSummary(c, summary);
        if (onCrater) onCrater(c);
      }
    };
  }
}

}  // namespace ejecta::fields
