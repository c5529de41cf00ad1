#pragma once
// The grids of one output time, built from particles: which fields, how normalised, on what
// lattice, in 3D grid coordinates (RZ revolved, planar as a slab). fields/vdb_grids.hpp writes
// them as OpenVDB FloatGrids. docs/fields.md.
#include <optional>
#include <string>
#include <vector>

#include "fields/sparse_lattice.hpp"
#include "fields/splat.hpp"
#include "sim/parallel/communicator.hpp"
#include "sim/state/geometry.hpp"
#include "sim/state/particles.hpp"
#include "sim/setup/scene.hpp"

namespace ejecta::fields {

// What to grid. Mirrors the scene's [fields] table (sim/setup/scene.hpp: FieldsOutputOptions).
struct GridRequest {
  std::vector<std::string> grids{"density", "temperature", "pressure", "damage", "fractions"};
  double voxel = 0.0;            // [m]; 0 = the median smoothing length
  FieldNormalisation normalise = FieldNormalisation::Auto;
  double extrude = 0.0;          // planar: slab depth [m]; 0 = one voxel
  bool clip = false;
  std::array<double, 3> regionMin{}, regionMax{};

  static GridRequest fromScene(const FieldsOutputOptions& f);
};

// What the particles are: the parts of a Scene the grids need.
struct ParticleContext {
  Geometry geometry = Geometry::Spatial;
  KernelKind kernel = KernelKind::CubicSpline;
  std::vector<std::string> materialNames;  // by material index

  static ParticleContext fromScene(const Scene& scene);
};

struct GridSpec {
  std::string name;     // "density", "fraction_granite", ...
  std::string units;    // SI ("1": dimensionless)
  int channel = 0;      // lattice channel of the plain SPH sum
  bool shepard = false; // value = channel / channel 0
  // A material's volume fraction: where the plain kernel sum over-fills (sum_j V_j W > 1 in
  // compressed or disordered material) it is divided by that sum, so no fraction, nor their
  // total, exceeds 1; at free surfaces (sum < 1) it keeps the plain sum's fall-off.
  bool fraction = false;
};

struct GridSet {
  SparseLattice lattice;          // 3D; channel 0 = the filled fraction sum_j V_j W
  std::vector<GridSpec> grids;    // in request order
  Geometry source = Geometry::Spatial;
  std::size_t particles = 0;
  // Every material of the run, whether or not its fraction grid is asked for: a reader of the
  // file can then tell a voxel's fill from only some materials' fractions (grid_voxels.hpp).
  std::vector<std::string> materials;
  // The value of grid g at block b, voxel v (0 where nothing is).
  float value(std::size_t g, std::size_t b, int v) const;
};

// The median smoothing length of the real particles [m].
double medianSmoothingLength(const ParticleSet& p);

// Expands "fractions" and validates names; throws std::invalid_argument naming an unknown grid.
std::vector<std::string> expandGridNames(const std::vector<std::string>& grids,
                                         const std::vector<std::string>& materialNames);

// Splats the particles in the run's own geometry (2D for planar and RZ, 3D for 3D), with
// channel 0 = sum V W and channel c+1 = values[c]. RZ sums include the mirror across the axis.
SparseLattice splatParticles(const ParticleSet& p, const ParticleContext& ctx,
                             const std::vector<std::vector<double>>& values, double voxel,
                             const std::optional<VoxelBox>& clip = std::nullopt);

// The grids of `request` for the particles. Throws std::invalid_argument for a 1D run, an
// unknown grid name, or a particle set without particles. With `ranks` (a distributed run, a
// collective): the grids of every rank's particles, at rank 0 (elsewhere the set's lattice is
// empty), each rank having splatted its own (fields/lattice_merge.hpp).
GridSet buildGridSet(const ParticleSet& p, const ParticleContext& ctx, const GridRequest& request,
                     const Communicator* ranks = nullptr);

}  // namespace ejecta::fields
