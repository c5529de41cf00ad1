#pragma once
// Charts of an impact run's crater, drawn at the end of `ejecta run` with the run's other
// charts (coupling/run_images.cpp), from the CSVs fields/run_outputs.cpp writes:
//   crater_growth.png   depth and apparent diameter against time (crater_history.csv)
//   crater_volume.png   volume (2D planar: area per metre) against time (crater_history.csv)
//   crater_profile.png  the final radial profile (crater_profile.csv): RZ one line (the same
//                       at every azimuth), 2D the two sides, 3D the mean and the azimuths'
//                       extremes
// A chart whose CSV is missing is skipped: not every run is an impact.
#include <filesystem>
#include <string>
#include <vector>

#include "render/charts.hpp"
#include "sim/setup/scene.hpp"

namespace ejecta::coupling {

// Draws the charts whose CSVs are in `dir`; returns the names of the PNGs written. `charts`
// must have charts available. Throws what ChartRunner::writeChart throws.
std::vector<std::string> writeCraterCharts(render::ChartRunner& charts,
                                           const std::filesystem::path& dir,
                                           const std::string& sceneName, Geometry geometry);

}  // namespace ejecta::coupling
