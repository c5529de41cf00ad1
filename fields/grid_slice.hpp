#pragma once
// A grid of a file sampled on an axis-aligned plane (a slice for a picture) or at given points
// (an iso-surface's vertices coloured by another grid), as plain arrays, with the grid's
// metadata (units, time, class) and value range. Layout of the files: docs/fields.md. OpenVDB
// stays in grid_slice.cpp.
//
// The sampling rule. Voxel (i, j, k) is centred at (i, j, k) * voxel (docs/fields.md). A point
// whose nearest voxel is inactive is outside the grid: NaN, drawn transparent. Any other point
// interpolates trilinearly between the 8 voxel centres around it, over the active ones only
// (their weights renormalised), so that the background value of the inactive voxels beyond a
// grid's edge does not drag the values near the edge towards it. Where all 8 are active this is
// plain trilinear interpolation: exact for a field linear in x, y and z. InactiveRule names the
// variants.
#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace ejecta::fields {

// Which samples are outside the grid.
enum class InactiveRule {
  NearestInactive,  // NaN where the nearest voxel is inactive: the grid's cells as they are
  AllInactive,      // NaN only where all 8 voxels around are inactive: reaches up to a voxel
                    // beyond the active ones (an iso-surface of another grid, which may lie
                    // there, still takes their values)
  Stored,           // never NaN: OpenVDB's trilinear interpolation of the stored values,
                    // inactive ones included (a level set then reads negative all through its
                    // inside, not only in its narrow band: a mask of "inside the surface")
};

// The in-plane axes of a slice through the plane `axis` = value: the remaining two in the order
// x, y, z. Plane x: (u, v) = (y, z); plane y: (x, z); plane z: (x, y).
std::array<int, 2> slicePlaneAxes(int axis);

struct GridSliceOptions {
  std::string grid = "density";
  int axis = 2;        // the plane's normal: 0 = x, 1 = y, 2 = z
  double value = 0.0;  // its position along that axis [m]
  // The rectangle sampled, in the plane's (u, v) coordinates [m]: {uMin, uMax, vMin, vMax}.
  // None: the grid's active bounding box in those two axes, to the outer faces of its voxels.
  std::optional<std::array<double, 4>> window;
  // Samples along the longer side of the window (cells are square, as near as a whole number of
  // them allows); 0: one per voxel, so that without a window sample centres sit on voxel centres.
  int samples = 0;
  InactiveRule inactive = InactiveRule::NearestInactive;
};

// What a file says about one of its grids, read without its voxels (cheap).
struct GridHeader {
  std::string name;
  std::string gridClass;           // "fog volume", "level set" (OpenVDB's class names)
  std::string units;               // "kg/m^3", "K", "m", ... ("" when not stored)
  std::string scene;
  std::string sourceGeometry;      // "3d", "rz" (revolved about y), "2d" (slab)
  double time = 0.0;               // [s]
  long step = 0;
  double voxelSize = 0.0;          // [m]
  // The active voxels' box in world coordinates, to the voxels' outer faces [m]; lo > hi when
  // the grid has no active voxel.
  std::array<double, 3> lo{}, hi{};
  // The impact target's reference density [kg/m^3] from the file's crater metadata (files of
  // impact runs; docs/fields.md), if stored.
  std::optional<double> targetDensity;

  bool levelSet() const { return gridClass == "level set"; }
  bool emptyBox() const { return lo[0] > hi[0]; }
};

struct GridSlice {
  GridHeader header;
  int axis = 2;
  double value = 0.0;
  std::array<int, 2> planeAxes{0, 1};  // world axes along i and j (slicePlaneAxes)
  int nx = 0, ny = 0;
  std::array<double, 2> origin{};      // (u, v) of the centre of sample (0, 0) [m]
  std::array<double, 2> spacing{};     // [m]
  std::vector<double> values;          // values[i + nx * j]; NaN outside the active voxels
  // The grid's range over all its active voxels (not only this slice's); NaN when it has none.
  double minValue = 0.0, maxValue = 0.0;

  // The world position of sample (i, j) [m].
  std::array<double, 3> position(int i, int j) const;
  std::size_t finiteCount() const;
};

// Samples grid `options.grid` of the OpenVDB file `path` on the plane. Throws std::runtime_error
// naming the file and the grid when the file cannot be read, has no such grid or it is not a
// float grid, or its voxels are not cubes on a linear transform, or (no window given) it has no
// active voxel; std::invalid_argument naming the file for an axis outside 0-2, a non-finite
// value, an empty or non-finite window, or samples < 0 or above 16384.
GridSlice sampleGridSlice(const std::string& path, const GridSliceOptions& options = {});

// The values of grid `grid` of file `path` at world points [m], by the rule above. Throws
// std::runtime_error as sampleGridSlice.
std::vector<double> sampleGridPoints(const std::string& path, const std::string& grid,
                                     std::span<const std::array<double, 3>> points,
                                     InactiveRule inactive = InactiveRule::NearestInactive);

// The header of grid `grid`. Throws std::runtime_error naming the file (and the grids it has)
// when it cannot be read or has no such grid.
GridHeader readGridHeader(const std::string& path, const std::string& grid);

// The names of a file's grids in file order. Throws std::runtime_error naming the file.
std::vector<std::string> gridNames(const std::string& path);

}  // namespace ejecta::fields
