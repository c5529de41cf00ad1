#pragma once
// The voxels of a grid file at or above a threshold, as plain arrays: what the radiation code
// turns into voxel emitters (hot material from the "temperature" grid), without fields/ knowing
// about radiation/. With them, the per-material fraction grids' values at those voxels, from
// which a caller gets each voxel's filled fraction and material mix. Layout: docs/fields.md.
// OpenVDB stays in grid_voxels.cpp.
#include <cstddef>
#include <string>
#include <vector>

namespace ejecta::fields {

struct GridVoxelOptions {
  std::string grid = "temperature";  // a float grid of the file
  // Keeps the active voxels with value >= threshold. The default is the seed's molten-rock cut
  // for the temperature grid, 1500 K (thesis chapter 4.5: "temperatures below 1500 K were
  // omitted as molten rock temperatures are above 1500 K").
  double threshold = 1500.0;
  bool fractions = true;             // also read every fraction_<material> grid at those voxels
};

struct GridVoxels {
  std::string grid, units;           // the grid read and its "units" metadata
  std::string sourceGeometry;        // "3d", "rz" (revolved), "2d" (slab), from the metadata
  double time = 0.0;                 // [s], from the metadata
  double voxelSize = 0.0;            // edge [m]
  double voxelVolume = 0.0;          // [m^3], every voxel's (a uniform linear transform)
  std::size_t activeVoxels = 0;      // active voxels of the grid, hot or not
  // The kept voxels, in OpenVDB's (deterministic) tree order.
  std::vector<double> x, y, z;       // world centres [m]
  std::vector<double> value;         // the grid's value there
  // fraction[m][i]: grid fraction_<materials[m]> at voxel i (0 where that grid is inactive),
  // the fraction grids in file order; empty when not asked for or the file has none.
  std::vector<std::string> materials;
  std::vector<std::vector<double>> fraction;
  // True when every fraction grid is a plain SPH sum (normalisation "none", or "capped": divided
  // by S only where S > 1, as runs write them): they then sum to the filled fraction S (1 inside
  // material, 0.5 on its surface). Shepard-normalised fractions sum to 1 wherever anything is,
  // and say only how the material is mixed.
  bool fractionsAreFill = false;
  // The run's materials that have no fraction grid in a file that has some (from the file's
  // material list; files written before it had one give none): their voxels would count as
  // empty and voxels they share as part-filled.
  std::vector<std::string> missingFractions;

  std::size_t size() const { return x.size(); }
};

// Reads `options.grid` of the OpenVDB file `path` and keeps its active voxels (active tiles
// counted voxel by voxel) at or above the threshold. Throws std::runtime_error naming the file
// when it cannot be read, has no such float grid, a fraction grid is not a float grid, or the
// grid's transform is not a uniform scale (cubic voxels); std::invalid_argument for a
// non-finite threshold.
GridVoxels readGridVoxels(const std::string& path, const GridVoxelOptions& options = {});

}  // namespace ejecta::fields
