#pragma once
// The fields/ outputs of `ejecta run`: VDB grids written in-situ at the scene's [fields] cadence
// (RUN_DIR/fields/fields_NNNN.vdb, NNNN the snapshot index), and, for impact scenes, the crater
// measured at every snapshot output (RUN_DIR/crater_history.csv, fields/crater_history.hpp) and
// at the end (summary.json "crater_*" entries and RUN_DIR/crater_profile.csv).
#include <functional>

#include "fields/crater_summary.hpp"
#include "sim/run/run.hpp"
#include "sim/setup/scene.hpp"

namespace ejecta::fields {

// Adds the hooks to `options` (keeping any hooks already there). `onCrater`, when given, is
// called at the end with the crater written into the summary.
void addFieldOutputs(RunOptions& options, const Scene& scene,
                     std::function<void(const CraterSummary&)> onCrater = {});

// RUN_DIR/fields/fields_NNNN.vdb
std::string fieldFileName(long snapshotIndex);

}  // namespace ejecta::fields
