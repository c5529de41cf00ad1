#pragma once
// The material surface of a grid file as a triangle mesh: the "surface" level set (a signed
// distance, negative inside: docs/fields.md) meshed by OpenVDB's volumeToMesh (dual contouring
// of the voxel sign changes), its quads split into triangles. Plain arrays, so that the
// radiation code can use the mesh as an occluder without fields/ knowing about radiation/.
// OpenVDB stays in surface_mesh.cpp.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace ejecta::fields {

struct SurfaceMeshOptions {
  std::string grid = "surface";  // a level-set grid of the file
  // The level to mesh [m]: 0 is the surface itself; -d the surface moved d inwards. OpenVDB's
  // narrow band is 3 voxels each side (docs/fields.md), so |isovalue| must stay inside it:
  // at most the band's half width less one voxel, else std::invalid_argument.
  double isovalue = 0.0;
  // volumeToMesh's adaptivity in [0, 1]: 0 gives one quad per voxel face crossed by the surface;
  // larger values merge flat regions into fewer, larger polygons.
  double adaptivity = 0.0;
};

struct SurfaceMesh {
  std::vector<std::array<double, 3>> vertices;          // world coordinates [m]
  std::vector<std::array<std::uint32_t, 3>> triangles;  // counter-clockwise seen from outside
  double voxelSize = 0.0;                               // of the level set [m]
  std::size_t quads = 0;                                // volumeToMesh's quads (each split in two)

  std::size_t size() const { return triangles.size(); }
  bool empty() const { return triangles.empty(); }
  double area() const;                                  // [m^2]
  // The signed volume the triangles enclose (divergence theorem) [m^3]: positive for a closed
  // mesh whose right-hand normals point outwards.
  double enclosedVolume() const;
};

// Meshes `options.grid` of the OpenVDB file `path`. Throws std::runtime_error naming the file
// when it cannot be read or has no such float grid, and std::invalid_argument for an isovalue
// outside the narrow band or an adaptivity outside [0, 1]. A grid without a zero crossing at
// the isovalue gives an empty mesh.
SurfaceMesh meshSurfaceFile(const std::string& path, const SurfaceMeshOptions& options = {});

// The iso-surface `options.grid` = `options.isovalue` of any float grid of the file. A level set
// is meshed as by meshSurfaceFile (the same narrow-band limit). A fog volume is meshed at an
// isovalue in the grid's units, enclosing the values above it (density above half the reference
// density, temperature above 1500 K); the isovalue must exceed the grid's background (the value
// of its inactive voxels, 0 in ejecta's files), so that the surface closes where the grid ends,
// else std::invalid_argument. Either way the triangles are counter-clockwise seen from outside
// (a fog volume's outside is the side of lower values). No crossing: an empty mesh. Throws
// std::runtime_error naming the file when it cannot be read or has no such float grid.
SurfaceMesh meshIsoSurfaceFile(const std::string& path, const SurfaceMeshOptions& options);

// The voxel size [m] of grid `grid` of the OpenVDB file `path`, from its transform alone (the
// tree is not read: cheap); nothing when the file is missing or unreadable or has no such grid.
std::optional<double> gridVoxelSize(const std::string& path, const std::string& grid = "surface");

}  // namespace ejecta::fields
