#pragma once
// What `ejecta run` draws: frames of the particles at the snapshot cadence when the scene has an
// [images] table (images/<field>_NNNN.png), and charts of energy.csv (and gauges.csv) at the end
// of every run when python3 with matplotlib is present (the CSVs are always written).
#include "sim/run.hpp"
#include "sim/scene.hpp"

namespace ejecta::app {

void addImageOutputs(RunOptions& options, const Scene& scene);

}  // namespace ejecta::app
