#pragma once
// How far apart two runs' particles are, field by field, matched by particle id: what "the same
// answer on N ranks as on one" is measured by (tests/parallel, `ejecta_compare_snapshots`).
#include <string>
#include <vector>

#include "sim/state/particles.hpp"

namespace ejecta {

struct FieldDifference {
  std::string field;     // "velocity[1]"
  double relative = 0.0; // the largest |a - b| over the field's largest |a|
  double absolute = 0.0; // the largest |a - b|
};

// Every stored field both sets carry (snapshot or restart), component by component; integer
// fields (id, material) count as a difference of 1 where they disagree. The two sets must hold
// the same ids (std::invalid_argument otherwise, naming the first that is missing). Infinite
// entries equal in both (lighting times of material that never burns) compare equal.
std::vector<FieldDifference> particleDifferences(const ParticleSet& a, const ParticleSet& b);

// The entry with the largest relative difference (an empty name when nothing differs).
FieldDifference largestDifference(const std::vector<FieldDifference>& differences);

}  // namespace ejecta
