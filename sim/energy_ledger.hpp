#pragma once
// The energy ledger: how the energy of a run is shared among its materials over time, and for an
// impact, how much of the impactor's kinetic energy the target now holds. energy.csv carries the
// per-material columns every step; summary.json the initial and final partition
// (docs/output_format.md).
#include <string>
#include <vector>

#include "sim/conservation.hpp"
#include "sim/scene.hpp"
#include "sim/summary.hpp"

namespace ejecta {

// Materials of moving bodies (the impactor) and of bodies at rest that no moving body uses (the
// target). Either is empty when the scene has none.
struct LedgerGroups {
  std::vector<int> impactor;
  std::vector<int> target;
};
LedgerGroups ledgerGroups(const Scene& scene);

// The material's name as a CSV/JSON key part: letters, digits, '-' and '_' kept, others '_'.
std::string ledgerKey(const std::string& materialName);

// Adds the partition to the summary's extras: per material the initial and final kinetic and
// internal energy; for an impact the impactor's initial kinetic energy, the target's gain, its
// kinetic/internal split and the share of the impactor's kinetic energy it represents.
void addEnergyPartition(const Scene& scene, const std::vector<double>& initialKinetic,
                        const std::vector<double>& initialInternal,
                        const std::vector<ConservedTotals>& now, RunSummary& summary);

}  // namespace ejecta
