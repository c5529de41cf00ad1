#pragma once
// Turning a 2D lattice into the 3D grid a user opens: an RZ field revolved about the axis, or a
// planar field as a slab. Grid coordinates: x and y are the run's first two coordinates, z the
// third; the RZ axis is the y axis (r = sqrt(x^2 + z^2)), so a revolved RZ run and a 3D run of
// the same scene line up.
#include <optional>

#include "fields/sparse_lattice.hpp"
#include "fields/splat.hpp"

namespace ejecta::fields {

// Every channel of `rz` (a 2D lattice over (r, z)) at r = sqrt(x^2 + z^2), y = z_axis, by
// bilinear interpolation. A voxel exists where channel 0 (the filled fraction) is positive.
SparseLattice revolveAboutAxis(const SparseLattice& rz, const std::optional<VoxelBox>& clip);

// The planar lattice copied into voxel layers k = 0 .. layers-1.
SparseLattice extrudeSlab(const SparseLattice& planar, int layers,
                          const std::optional<VoxelBox>& clip);

}  // namespace ejecta::fields
