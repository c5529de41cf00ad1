#pragma once
// Charts of a thermal study's outputs (coupling/thermal_outputs.hpp wrote the CSVs into `dir`):
//   flux.png            every face's incident flux along the pass;
//   wall_<patch>.png    the hottest face's wall: hot face, interfaces, cold face;
//   sizing.png          the sizing table: the thinnest coating of each candidate material on each
//                       face (mm; none when the bare structure stays below its limit), from
//                       sizing_chart.csv, the table pivoted to one row per face.
// Used by `ejecta thermal` and by a run's in-situ passes.
#include <filesystem>
#include <string>
#include <vector>

#include "radiation/thermal_study.hpp"
#include "render/charts.hpp"

namespace ejecta::coupling {

// Returns the PNGs' file names. Throws std::runtime_error when the chart script fails.
std::vector<std::string> writeThermalCharts(render::ChartRunner& charts,
                                            const radiation::ThermalResult& result,
                                            const std::filesystem::path& dir,
                                            const std::string& name);

// sizing_chart.csv's text: "patch,<coating>_mm,...,<coating>_kg,..." with one row per sized
// face; "nan" where a coating cannot protect the face up to the thickest considered.
std::string sizingChartCsv(const radiation::ThermalResult& result);

}  // namespace ejecta::coupling
