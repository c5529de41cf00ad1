#pragma once
// How a geometry's view factors converge with the number of rays: the same geometry cast at
// rays = minRays, ratio x minRays, ... up to maxRays (fixed counts, no adaptivity), with the
// estimate, its standard error and the wall time of each. Against an exact value where the
// geometry file gives one ([[references]]), the error too. `ejecta viewfactor --convergence`
// writes the table as CSV and charts it (docs/view_factors.md).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "radiation/geometry_file.hpp"

namespace ejecta::radiation {

struct TrackedFactor {
  std::string from, to;           // receiver (patch or point) and target (patch or group)
  std::optional<double> exact;    // from the file's [[references]]
  std::string source;             // of the exact value
};

struct ConvergenceStep {
  std::uint64_t rays = 0;         // per receiver
  double seconds = 0.0;           // wall time of the whole geometry at this count
  std::vector<Estimate> factors;  // per tracked factor
};

struct ViewFactorConvergence {
  std::string name;
  std::vector<TrackedFactor> factors;
  std::vector<ConvergenceStep> steps;  // fewest rays first
};

// The tracked factors are the file's references; without any, every factor from a receiver
// (at the first time) to a patch or group that the finest run finds non-zero. Throws
// GeometryFileError naming the file, line and key for a reference whose receiver or target does
// not exist, and std::invalid_argument for minRays < 256, maxRays < minRays or ratio < 2.
ViewFactorConvergence studyViewFactorConvergence(const GeometryConfig& config,
                                                 std::uint64_t minRays, std::uint64_t maxRays,
                                                 int ratio = 4);

// One row per step: rays, wall_s, then per factor k (named from_to_to, characters other than
// letters, digits and '_' replaced by '_'): <name>, <name>_stderr and, with an exact value,
// <name>_error (|estimate - exact|); and inverse_sqrt: the first factor's first standard error
// scaled by sqrt(rays_0 / rays), the Monte Carlo rate to compare with.
std::string formatConvergenceCsv(const ViewFactorConvergence& study);
// The column name of factor k in that CSV.
std::string convergenceColumn(const TrackedFactor& factor);
std::string formatConvergenceText(const ViewFactorConvergence& study);

}  // namespace ejecta::radiation
