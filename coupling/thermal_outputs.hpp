#pragma once
// What `ejecta thermal` and a run's in-situ [thermal] passes share: the emitter options a study
// asks for on a run's materials, the JSON that says where the hot material and the occluder came
// from, and the files a pass writes (flux.csv, wall_<patch>.csv, sizing.csv, thermal.json;
// docs/thermal.md).
#include <filesystem>
#include <string>
#include <vector>

#include "coupling/json_text.hpp"
#include "coupling/snapshot_emitters.hpp"
#include "coupling/surface_occluder.hpp"
#include "radiation/thermal_study.hpp"

namespace ejecta::coupling {

// Threshold and emissivities of `study` for a run whose materials are `materialNames` (in
// material index order). Each emissivity the study gives for a material the run lacks is
// returned in `unknownMaterials`, for a warning.
SnapshotEmitterOptions emitterOptionsFor(const radiation::ThermalStudy& study,
                                         const std::vector<std::string>& materialNames,
                                         std::vector<std::string>* unknownMaterials = nullptr);

// thermal.json's fields for particle emitters: "emitter_kind" and "snapshot" (`path` is the
// snapshot file, or "in-situ").
std::string particleSourceJson(const std::string& path, double time, Geometry geometry,
                               const SnapshotEmitterStats& stats);
// thermal.json's "occluder" field: null without one.
std::string occluderJson(const std::string* gridFile, const SurfaceOccluderOptions& options,
                         const SurfaceOccluderStats& stats);

// Writes the pass's files into `dir` (created), each atomically, with `extraJson` (fields as
// above, comma-separated, no trailing comma) in thermal.json, and returns thermal.json's text.
std::string writeThermalOutputs(const std::filesystem::path& dir, const radiation::ThermalStudy& study,
                                const radiation::ThermalResult& result, const std::string& extraJson);

}  // namespace ejecta::coupling
