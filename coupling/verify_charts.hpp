#pragma once
// What `ejecta verify NAME --out DIR` leaves beside the profile CSVs the problem wrote: the
// convergence table NAME_convergence.csv and, when charts are available, PNGs a reader can judge
// at a glance:
//   NAME_error_vs_spacing.png  every L1 error over its coarsest value against the spacing
//                              (log-log), with the first-order line;
//   NAME_error_vs_time.png     the same errors against the run's wall time: accuracy for cost;
//   <profile>_<column>.png     for every CSV of the problem with a column `c` and its reference
//                              `c_exact`, `c_ref` or `c_reference`: the particles (or samples) as
//                              points and the reference dashed.
#include <filesystem>
#include <string>
#include <vector>

#include "render/charts.hpp"
#include "sim/verify/verification.hpp"

namespace ejecta::coupling {

// Writes NAME_convergence.csv into dir (atomically) and returns its name.
std::string writeConvergenceTable(const verify::Report& report, const std::filesystem::path& dir);

// Draws the charts above from the CSVs in dir; returns the PNGs' file names. The error charts
// need at least two resolutions. Throws std::runtime_error when the chart script fails.
std::vector<std::string> writeVerificationCharts(render::ChartRunner& charts,
                                                 const verify::Report& report,
                                                 const std::filesystem::path& dir);

}  // namespace ejecta::coupling
