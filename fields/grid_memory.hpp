#pragma once
// The memory a grid set will take, estimated from the particles before any voxel is allocated,
// so that a voxel far below the particles' size ("[fields] voxel = 1e-7") is refused with the
// number it would need instead of dying in std::bad_alloc.
#include "fields/grid_set.hpp"

namespace ejecta::fields {

struct GridMemoryEstimate {
  double voxels = 0.0;  // active voxels of the 3D grids (RZ revolved, planar extruded)
  double bytes = 0.0;
};

// The smaller of two upper bounds: every particle's own footprint (its support, revolved in
// RZ), and the particles' bounding box (with the support, clipped to the request's region).
GridMemoryEstimate estimateGridMemory(const ParticleSet& p, const ParticleContext& ctx,
                                      const GridRequest& request, double voxel, std::size_t grids);

// Throws InputError when the grids would not fit in this machine's memory.
void requireGridMemory(const ParticleSet& p, const ParticleContext& ctx, const GridRequest& request,
                       double voxel, std::size_t grids);

}  // namespace ejecta::fields
