#pragma once
// Grid file -> radiation emitters: the hot voxels of a run's temperature grid
// (RUN_DIR/fields/fields_NNNN.vdb, docs/fields.md) as voxel emitters (radiation/emitters.hpp:
// selectVoxelEmitters), the glue between fields/ and radiation/ (neither depends on the other).
// docs/thermal.md, "Voxel emitters and occlusion".
//
// Each voxel whose temperature is at or above the threshold becomes an opaque sphere at its
// centre holding the material in the voxel: S a^3 for the filled fraction S = the sum of the
// plain fraction grids (capped at 1), radius (3 S a^3 / 4 pi)^(1/3). The kernel's partition of
// unity makes the integral of S over space the particles' volume, so the hot voxels carry about
// the hot particles' volume. Its emissivity is the fraction-weighted mean over the materials
// (by name from the study, else the default: granite 0.45, the seed's ref. [27]); its group the
// material with the largest fraction. Without plain fraction grids every hot voxel is a full
// voxel of the default emissivity, group "material0". RZ runs' grids are already revolved about
// the world y axis, as the particle emitters are.
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "radiation/emitters.hpp"

namespace ejecta::coupling {

struct GridEmitterOptions {
  std::string grid = "temperature";                        // the fog grid read
  double minTemperature = radiation::kMoltenRockThreshold;  // [K]
  double defaultEmissivity = radiation::kGraniteEmissivity;
  std::map<std::string, double> emissivityByMaterial;      // by the run's material names
};

struct GridEmitterStats {
  std::size_t activeVoxels = 0;   // active voxels of the temperature grid
  std::size_t hotVoxels = 0;      // of them at or above the threshold
  std::size_t emitters = 0;       // spheres made (hot voxels with material in them)
  double voxelSize = 0.0;         // [m]
  double hotVolume = 0.0;         // the emitters' volume, sum of S a^3 [m^3]
  double time = 0.0;              // [s], from the grid's metadata
  std::string sourceGeometry;     // "3d", "rz", "2d"
  std::vector<std::string> materials;  // from the fraction grids (the emitter groups)
  bool fillWeighted = false;      // plain fraction grids gave each voxel's filled fraction
};

// The emitters of grid file `path`. Throws std::runtime_error naming the file (no such file or
// grid, a planar slab) and std::invalid_argument for a bad value (from selectVoxelEmitters).
radiation::Emitters emittersFromGridFile(const std::string& path, const GridEmitterOptions& options = {},
                                         GridEmitterStats* stats = nullptr);

// The grid file written with snapshot `snapshot` (RUN_DIR/snapshots/snap_NNNN.h5 ->
// RUN_DIR/fields/fields_NNNN.vdb), if it exists.
std::optional<std::string> gridFileForSnapshot(const std::string& snapshot);

}  // namespace ejecta::coupling
