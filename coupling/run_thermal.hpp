#pragma once
// The in-situ radiation chain of a run whose scene has a [thermal] table (docs/thermal.md). The
// hot particles become emitters (coupling/snapshot_emitters.hpp), the asteroid's surface from the
// run's latest grid file (if it writes any) occludes (coupling/surface_occluder.hpp), and the study's
// spacecraft flies its pass (radiation/thermal_study.hpp):
//  - hot_material = "snapshot": at the first output at or after each requested time (or at the
//    last output), over that output's material, frozen during the pass; thermal_NNNN/ (NNNN: the
//    snapshot index), the same numbers as `ejecta thermal --from` on that snapshot;
//  - hot_material = "evolving": from each requested time, while the run goes on, each sample
//    time of the pass seeing the material of its step; thermal_from_<t>ms/.
// Each pass writes the files of `ejecta thermal` and crater.png; at the end the summary gets the
// governing pass (the one with the hottest steady face): per-face flux and temperatures, the
// structure's peak, each candidate coating's thickness and mass, and charts of its flux and wall.
#include <filesystem>
#include <functional>
#include <string>

#include "coupling/thermal_summary.hpp"
#include "radiation/thermal_study.hpp"
#include "sim/run/run.hpp"
#include "sim/setup/scene.hpp"

namespace ejecta::coupling {

// The study a scene's [thermal] table names: a file relative to the scene file's folder, else a
// study compiled in with the scenes. Throws SceneError naming the scene, the key and the reason.
radiation::ThermalStudy loadSceneThermalStudy(const Scene& scene);

// Adds the passes to the run's outputs. Throws SceneError for a study that cannot be loaded or a
// geometry without 3D extent (1D, 2D planar), before the run starts.
// `charts` false: no flux and wall charts (the CSVs are written). `onThermal`, when given, is
// called at the end with the result written into the summary.
void addThermalOutputs(RunOptions& options, const Scene& scene, bool charts = true,
                       std::function<void(const ThermalSummary&)> onThermal = {});

}  // namespace ejecta::coupling
