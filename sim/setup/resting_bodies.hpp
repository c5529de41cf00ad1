#pragma once
// A body set to rest on another (`[[bodies]] rest_on = "crust"`): a device on a crater's floor,
// an impactor touching its target. Placed by its centre alone, the gap between its lattice and
// the other body's depends on where both lattices fall, so it changes with the spacing (a
// crater-floor burst's nearest device-floor pair was 1.0 spacing apart at 0.5 m and 0.52 at
// 0.354 m: docs/asteroid_studies.md), and a convergence study then measures the lattices, not
// the physics. Resting, the body is moved along `rest_direction` (down by default) to where its
// nearest particle pair with the other body is `rest_gap` of its spacing apart (1: as if the two
// lattices were one), at every spacing.
#include "sim/setup/scene.hpp"

namespace ejecta {

// Moves every body with `rest_on` into its resting place (the shape and its lattice moved
// together; BodySpec::restMove records by how much). The search runs from 4 of the larger
// spacing back against the direction to 4 on along it; a body that already overlaps the other
// there, or meets nothing of it, is a SceneError naming the file, the key and the distances.
void placeRestingBodies(Scene& scene);

}  // namespace ejecta
