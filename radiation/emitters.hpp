#pragma once
// Hot emitters: the material that radiates onto the spacecraft, as structure-of-arrays. Each
// emitter is an opaque, grey, diffuse sphere (an SPH particle's equivalent sphere, or a voxel's)
// with a temperature and an emissivity, in a group (a material, or any label) for the per-group
// view factors. The ray tracer represents each one as an exact sphere (Embree sphere points), so
// it presents the same disc of radius `radius` to every direction: docs/view_factors.md says why
// spheres and not discs.
//
// Built from arrays the caller supplies (particles or voxels), keeping only what is at least as
// hot as a threshold: by default 1500 K, the seed's molten-rock cut (chapter 4.5: "temperatures
// below 1500 K were omitted as molten rock temperatures are above 1500 K").
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "radiation/constants.hpp"

namespace ejecta::radiation {

// The seed's molten-rock threshold [K] (chapter 4.5).
inline constexpr double kMoltenRockThreshold = 1500.0;

struct Emitters {
  std::vector<double> x, y, z;        // centres [m]
  std::vector<double> radius;         // [m]
  std::vector<double> temperature;    // [K]
  std::vector<double> emissivity;     // [-], in (0, 1]
  std::vector<std::uint32_t> group;   // index into groupNames
  std::vector<std::string> groupNames;

  std::size_t size() const { return x.size(); }
  bool empty() const { return x.empty(); }
  // Appends one emitter; the group is created on first use. Throws std::invalid_argument for a
  // non-finite centre, a radius <= 0, a temperature < 0 or an emissivity outside (0, 1].
  void add(double cx, double cy, double cz, double r, double t, double eps,
           const std::string& groupName);
  // eps sigma T^4 of emitter i [W/m^2]: what it emits per unit area.
  double exitance(std::size_t i) const;
  // Appends all emitters of `other` (groups merged by name).
  void append(const Emitters& other);
};

// Particles or voxels as the caller holds them: views of equally long arrays.
struct EmitterSource {
  std::span<const double> x, y, z;
  std::span<const double> radius;       // equivalent sphere radius [m] (see the helpers below)
  std::span<const double> temperature;  // [K]
  // Material index of each element; empty: all material 0.
  std::span<const int> material;
};

struct EmitterSelection {
  double minTemperature = kMoltenRockThreshold;  // [K]; keeps T >= minTemperature
  // Emissivity of material m; a material beyond the end gets defaultEmissivity.
  std::vector<double> emissivityByMaterial;
  double defaultEmissivity = kGraniteEmissivity;
  // Group name of material m; beyond the end: "material<m>".
  std::vector<std::string> materialNames;
};

// The hot part of `source`. Throws std::invalid_argument (naming the array and the element)
// when array lengths differ, a value is not finite, a radius is <= 0 or an emissivity is not in
// (0, 1].
Emitters selectEmitters(const EmitterSource& source, const EmitterSelection& selection = {});

// Voxels of a grid as the caller holds them (fields/grid_voxels.hpp reads them from a grid
// file): centres, temperatures, one voxel volume, and optionally the fraction of each material
// in each voxel.
struct VoxelEmitterSource {
  std::span<const double> x, y, z;
  std::span<const double> temperature;   // [K]
  double voxelVolume = 0.0;              // [m^3], > 0
  // fraction[m][i]: the fraction of material m in voxel i (m indexes the selection's
  // emissivityByMaterial and materialNames). Empty: every voxel is material 0, full.
  std::vector<std::span<const double>> fraction;
  // The fractions are plain SPH sums, whose total is the filled fraction S of the voxel (1
  // inside material, 0.5 on the surface, less in the kernel's fringe beyond it): each voxel's
  // sphere then holds S times the voxel volume (S capped at 1). False (Shepard-normalised
  // shares, or none): every kept voxel is full.
  bool fractionsAreFill = false;
};

// The hot voxels of `source` as emitters: each voxel with T >= selection.minTemperature (and
// material in it) becomes an opaque grey sphere at its centre of the volume of material it holds,
// S v, radius equalVolumeRadius(S v), as a particle is a sphere of its own volume. Its
// emissivity is the fraction-weighted mean of its materials' emissivities (a material beyond
// emissivityByMaterial takes the default), its group the material with the largest fraction
// (ties: the lower index). Throws std::invalid_argument (naming the array and the voxel) for
// arrays of different lengths, a non-finite value, a negative fraction, a voxel volume <= 0 or an
// emissivity outside (0, 1].
Emitters selectVoxelEmitters(const VoxelEmitterSource& source, const EmitterSelection& selection = {});

// The radius of the sphere of volume v: (3 v / 4 pi)^(1/3). For an SPH particle, v = m / rho;
// for a voxel of edge a, v = a^3 (radius 0.62 a). Spheres of that size on a cubic lattice leave
// pinholes along the lattice axes; opaqueLatticeRadius closes them.
double equalVolumeRadius(double volume);
// sqrt(3)/2 times the spacing: every point of a filled cubic lattice region is then inside some
// sphere, so a thick region is opaque from every direction.
double opaqueLatticeRadius(double spacing);

}  // namespace ejecta::radiation
