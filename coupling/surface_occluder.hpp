#pragma once
// Grid file -> occluder: the material surface of a run's grid file (the "surface" level set,
// docs/fields.md) meshed by fields::meshSurfaceFile as a radiation::TriangleMesh (one patch,
// "asteroid"), for runThermalStudy's occluder: opaque, cold, not a receiver. The glue between
// fields/ and radiation/. docs/thermal.md, "Voxel emitters and occlusion".
//
// The inset. The emitters of the material at the surface (particle spheres, voxel spheres) sit
// about half a spacing inside the level set's zero (the 0.5 contour of the filled fraction) and
// reach only a little beyond it: a mesh of the zero itself would cover the hot skin it is meant
// to leave visible and hide all but the tops of its spheres. So the occluder is the surface moved
// inwards by `inset`: emitters within that depth stay visible (they are the surface that
// radiates), hot material deeper than that is behind rock, and rays through the body (its limb,
// the crater's far wall) are blocked.
#include <cstddef>
#include <string>

#include "radiation/mesh.hpp"

namespace ejecta::coupling {

struct SurfaceOccluderOptions {
  std::string grid = "surface";   // the level set
  // How far inside the surface the occluder lies, in voxels of the level set; >= 0 and at most
  // 2 (the narrow band is 3 voxels: docs/fields.md).
  double insetVoxels = 1.5;
  double adaptivity = 0.0;        // volumeToMesh's, in [0, 1]
};

struct SurfaceOccluderStats {
  std::size_t triangles = 0;
  double voxelSize = 0.0;         // [m]
  double inset = 0.0;             // [m]
  double area = 0.0;              // [m^2]
};

// The occluder of grid file `path`. Throws std::runtime_error naming the file (no such file or
// level set) and std::invalid_argument for options out of range or a level set with no surface
// at the inset.
radiation::TriangleMesh occluderFromGridFile(const std::string& path, const SurfaceOccluderOptions& options = {},
                                             SurfaceOccluderStats* stats = nullptr);

// True when `path` is a grid file with a level set called `grid`.
bool gridFileHasSurface(const std::string& path, const std::string& grid = "surface");

}  // namespace ejecta::coupling
