#pragma once
// The in-situ radiation chain of a run whose scene has a [thermal] table (docs/thermal.md): at
// the first output at or after each requested time (or at the last output), the hot particles
// become emitters (apps/snapshot_emitters.hpp) and the study's spacecraft flies its pass over
// them (radiation/thermal_study.hpp). Each pass writes thermal_NNNN/ (NNNN: the output's
// snapshot index) with the files of `ejecta thermal` and a picture, crater.png; at the end the
// summary gets the governing pass (the one with the hottest steady face): per-face flux and
// temperatures, the structure's peak, and each candidate coating's thickness and mass, and
// charts of its flux and wall histories.
#include <filesystem>
#include <string>

#include "radiation/thermal_study.hpp"
#include "sim/run.hpp"
#include "sim/scene.hpp"

namespace ejecta::app {

// The study a scene's [thermal] table names: a file relative to the scene file's folder, else a
// study compiled in with the scenes. Throws SceneError naming the scene, the key and the reason.
radiation::ThermalStudy loadSceneThermalStudy(const Scene& scene);

// Adds the passes to the run's outputs. Throws SceneError for a study that cannot be loaded or a
// geometry without 3D extent (1D, 2D planar), before the run starts.
// `charts` false: no flux and wall charts (the CSVs are written).
void addThermalOutputs(RunOptions& options, const Scene& scene, bool charts = true);

}  // namespace ejecta::app
