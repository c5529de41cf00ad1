#pragma once
// The crater at the end of an impact run, typed: what summary.json's "crater_*" entries hold
// (docs/output_format.md) and what `ejecta run` prints.
#include <string>

#include <optional>

#include "fields/crater.hpp"
#include "fields/crater_growth.hpp"
#include "fields/crater_scaling.hpp"
#include "sim/run/summary.hpp"

namespace ejecta::fields {

struct CraterSummary {
  bool found = false;
  std::string note;     // why none was found, or a remark; empty: none
  bool planar = false;  // a 2D planar run's crater is a trench of unit depth
  double depth = 0.0, apparentDiameter = 0.0, rimDiameter = 0.0, rimHeight = 0.0;  // [m]
  double volume = 0.0;         // [m^3]; planar: the trench's cross-section [m^2]
  double excavatedMass = 0.0;  // [kg]; planar: per metre [kg/m]
  double elongation = 1.0;     // along-track / cross-track diameter; not for planar runs
  // Over the last fifth of the run (fields/crater_growth.hpp); none when the history is short.
  std::optional<CraterGrowth> growth;
  // [crater] scaling: the class and the crater pi-group scaling gives (fields/crater_scaling.hpp).
  std::string scalingClass;
  std::optional<ScaledCrater> scaled;
};

CraterSummary craterSummary(const CraterMetrics& metrics, bool planar);
// The line `ejecta run` and `ejecta crater` print for [crater] scaling, with the measured
// crater's volume and apparent diameter over the scaled ones when there is a crater.
std::string describeScaledCrater(const std::string& scalingClass, const ScaledCrater& scaled,
                                 std::optional<double> measuredVolume,
                                 std::optional<double> measuredDiameter = std::nullopt);
// A measurement that failed: no crater, and why.
CraterSummary craterFailure(const std::string& why);

// Writes the crater into the summary's extras: the one place its summary.json keys are named.
void addToSummary(const CraterSummary& crater, RunSummary& summary);

}  // namespace ejecta::fields
