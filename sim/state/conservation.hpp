#pragma once
// Conserved totals over the real particles, summed in a fixed order (deterministic).
#include <array>
#include <cstddef>
#include <vector>

#include "sim/state/particles.hpp"

namespace ejecta {

struct ConservedTotals {
  double kinetic = 0.0;   // [J] (2D planar: per metre depth)
  double internal = 0.0;  // [J]
  double total() const { return kinetic + internal; }
  std::array<double, 3> momentum{};  // [kg m/s]; RZ: only the z component (index 1) is conserved
  double mass = 0.0;
};

ConservedTotals conservedTotals(const ParticleSet& p);

// The same totals per material index [0, materials): the energy partition of the ledger (which
// material holds how much kinetic and internal energy). Deterministic, serial.
std::vector<ConservedTotals> conservedTotalsByMaterial(const ParticleSet& p, std::size_t materials);

}  // namespace ejecta
