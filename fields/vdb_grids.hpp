#pragma once
// OpenVDB files of ejecta's grids: one file per output time holding every grid (fog volumes of
// the fields, a level set of the material surface), each with its metadata, and the file's own
// metadata for later crater measurement. Layout: docs/fields.md. OpenVDB itself stays in
// vdb_grids.cpp: including it costs seconds per translation unit.
#include <optional>
#include <string>
#include <vector>

#include "fields/crater.hpp"
#include "fields/crater_setup.hpp"
#include "fields/grid_set.hpp"

namespace ejecta::fields {

struct GridFileMeta {
  std::string scene;
  double time = 0.0;     // [s]
  long step = 0;
  bool levelSet = true;  // add the "surface" level set (3D and RZ; planar only when extruded)
  std::optional<CraterSetup> crater;  // stored so `ejecta crater FILE.vdb` can measure
};

// Writes the grids of `set` to `path` atomically (a temporary file, then rename): an earlier
// file at `path` is intact on any failure. Throws std::runtime_error naming the file.
void writeGridFile(const std::string& path, const GridSet& set, const GridFileMeta& meta);

// One grid of a file as read back.
struct StoredGrid {
  std::string name;
  std::string gridClass;     // "fog volume", "level set"
  std::string units;
  double voxelSize = 0.0;
  std::size_t activeVoxels = 0;
  float minValue = 0.0f, maxValue = 0.0f;  // over active voxels
  double time = 0.0;
  long step = 0;
  std::string scene;
  std::string sourceGeometry;  // "3d", "rz", "2d"
  std::string normalisation;   // "shepard", "none", "capped" (fractions), or "" for the level set
};

// Reads every grid's metadata and value range. Throws std::runtime_error naming the file.
std::vector<StoredGrid> readGridFileInfo(const std::string& path);

// The value of grid `name` at a world position, trilinear (for tests and tools).
double sampleGridFile(const std::string& path, const std::string& name, const Point& x);

// What `ejecta crater FILE.vdb` measures on: the sum of the target materials' fraction grids as a
// field, the setup stored in the file, and its voxel size. Throws std::runtime_error naming the
// file and what is missing (no crater metadata, no fraction grids).
struct GridFileCraterInput {
  FractionField field;
  CraterSetup setup;
  double voxel = 0.0;
};
GridFileCraterInput craterInputFromGridFile(const std::string& path);

}  // namespace ejecta::fields
