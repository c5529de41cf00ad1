#pragma once
// What `ejecta run` draws: frames of the particles at the snapshot cadence when the scene has an
// [images] table (images/<field>_NNNN.png), pictures of its grid files when the table asks for
// them (images/grid_<name>_NNNN.png, images/surface_NNNN.png; coupling/grid_images.hpp), and charts
// of energy.csv (and gauges.csv) at the end of every run when python3 with matplotlib is present
// (the CSVs are always written).
#include "sim/run/run.hpp"
#include "sim/setup/scene.hpp"

namespace ejecta::coupling {

// `charts` false: the CSVs only (no python start-ups), as `ejecta run --no-charts`.
void addImageOutputs(RunOptions& options, const Scene& scene, bool charts = true);

}  // namespace ejecta::coupling
