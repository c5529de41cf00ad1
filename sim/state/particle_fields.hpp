#pragma once
// Per-particle scalar fields by name: what `[fields] grids`, `ejecta fields --grids` and the
// renderer may ask for. One list, so scene validation, grids and images agree on the names.
#include <string>
#include <string_view>
#include <vector>

#include "sim/state/particles.hpp"

namespace ejecta {

struct ParticleFieldInfo {
  std::string_view name;
  std::string_view units;        // SI, as written into grid metadata ("1": dimensionless)
  std::string_view description;
};

// Every named scalar field, in a fixed order.
const std::vector<ParticleFieldInfo>& particleScalarFields();
// The entry for `name`, or nullptr.
const ParticleFieldInfo* findParticleScalarField(std::string_view name);
// The names joined for messages: "'density', 'temperature', ...".
std::string particleScalarFieldList();

// The values of field `name` for the real particles [0, numReal). Fields a run does not carry
// (damage without fracture, plastic strain without strength) are zero. Throws
// std::invalid_argument for an unknown name.
std::vector<double> particleScalarField(const ParticleSet& p, std::string_view name);

}  // namespace ejecta
