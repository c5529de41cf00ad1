#pragma once
// The declarations of the built-in per-particle fields, by group. A run carries the Core group
// always and each other group only when a term needs it (ParticleSet::enableStrength, ...).
#include <vector>

#include "sim/state/particles.hpp"

namespace ejecta {

// The fields of `group` (not Package); stress fields get `stressComponents` components.
std::vector<Field> builtinFields(FieldGroup group, int stressComponents = 6);

// Every built-in field of every group, in registry order: what grids, images and scene
// validation may name even when a run does not carry it.
const std::vector<Field>& allBuiltinFields();

}  // namespace ejecta
