#pragma once
// The shield analysis of `ejecta run` for a scene with a [shield] table (fields/shield_analysis):
//   - RUN_DIR/shield_history.csv at every snapshot output: the wall (perforated, hole, mass
//     behind it, deflection and its peak over the outputs so far) and the debris cloud (mass,
//     momentum, leading edge, spread);
//   - the verdict at the end, into summary.json ("shield_*") and the printed summary.
// A restarted run keeps the history's earlier rows and their peak deflection.
#include <functional>
#include <optional>
#include <string>

#include "fields/shield_analysis.hpp"
#include "sim/run/run.hpp"

namespace ejecta::fields {

struct ShieldSummary {
  bool perforated = false;
  std::string reason;                    // what made the verdict (or "intact")
  WallState wall;                        // at the end
  double peakDeflection = 0.0;           // [m] over the outputs (the snapshot cadence)
  std::optional<double> firstPerforated; // [s] the first output at which the wall was perforated
  DebrisCloud cloud;                     // at the end
  std::string wallName;
};

// Adds the hooks (keeping any already there); `onShield` is called at the end with the verdict.
void addShieldOutputs(RunOptions& options, const Scene& scene,
                      std::function<void(const ShieldSummary&)> onShield = {});

// The verdict in a sentence ("perforated: a hole 4.1 mm across and 0.31 g behind the wall").
std::string describeVerdict(const ShieldSummary& s);

// Writes the summary into summary.json's extras: the one place its keys are named.
void addToSummary(const ShieldSummary& s, RunSummary& summary);

// The history's header and one row (no newline).
std::string shieldHistoryHeader();
std::string shieldHistoryRow(double time, const WallState& w, double peakDeflection,
                             const DebrisCloud& c);

}  // namespace ejecta::fields
