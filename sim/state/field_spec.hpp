#pragma once
// The declaration of one per-particle field: what it is (name, units, components), how the
// integrator advances it, and where it goes (snapshot, restart, XDMF index, grids, halos). Every
// field a ParticleSet carries is declared once, as a FieldSpec: the built-in ones in
// sim/state/builtin_fields.cpp, a package's own where the package is. Storage, reordering,
// snapshots and restarts, the XDMF list, the named fields of grids and images and the leapfrog
// all iterate over these declarations (docs/design.md, "Fields declared once").
#include <cstddef>
#include <string>
#include <utility>

namespace ejecta {

struct ParticleSet;

enum class FieldType { Float64, Int32, Int64 };

// Where a snapshot stores the field: /particles (science output, read by users' tools),
// /restart (only what resuming needs), or nowhere (recomputed every step).
enum class FieldOutput { None, Particles, Restart };

// How the leapfrog (sim/run/leapfrog.hpp) advances a field each step.
enum class Evolution {
  None,     // set by a pass, the equation of state or a package's update; or constant
  Kicked,   // two half kicks y += dt/2 * rate, the rate evaluated at the start and at the end
  Drifted,  // x += dt * v_half, v the Kicked field named by FieldSpec::rate (positions)
};

// A bound on each half kick of a Kicked field.
enum class KickLimit {
  None,
  Clamp,  // into [lo, hi]
  Cap,    // advanceCrack's bound: min(y + dt rate, max(y, cap_i), 1), caps from the package
};

// How a mirror image (a wall, the RZ axis) transforms the field: a scalar is copied, a vector's
// component along a reflected axis changes sign, a symmetric tensor's off-diagonal components
// that pair a reflected axis with one that is not change sign.
enum class MirrorParity { Scalar, Vector, SymmetricTensor };

struct FieldSpec {
  std::string name;          // the snapshot dataset and the name users see
  std::string units;         // SI, "1" when dimensionless
  std::string description;   // the dataset's description attribute
  FieldType type = FieldType::Float64;
  int components = 1;        // 1; 3 for vectors; 4 (1D, 2D, RZ) or 6 (3D) for stress
  FieldOutput output = FieldOutput::None;
  bool required = true;      // a snapshot without it is refused (false: older files may lack it)
  bool grid = false;         // a named scalar for grids and images (sim/state/particle_fields.hpp)
  double absent = 0.0;       // what grids see when the run does not carry the field
  bool halo = false;         // read from neighbours by the pair passes: ghosts and halos carry it
  MirrorParity parity = MirrorParity::Scalar;
  Evolution evolution = Evolution::None;
  std::string rate;          // Kicked: the field holding the time derivative; Drifted: the
                             // Kicked field whose half-step value moves it (position: velocity)
  KickLimit limit = KickLimit::None;
  double lo = 0.0, hi = 0.0; // Clamp: the range
  bool spatial = false;      // a vector in space: evolved over the geometry's dimension only
  bool writeDimensionOnly = false;  // components beyond the geometry's dimension written as 0
  double fill = 0.0;         // value of entries added by a resize
  // Derived fields have no storage: their value is computed from others when written or
  // gridded (damage = crack^3). Never read back, never evolved.
  double (*derive)(const ParticleSet&, std::size_t) = nullptr;
};

// Where every declaration starts: a one-component Float64 field stored where `output` says; the
// declaring code then sets what differs (evolution, grids, halos, components).
inline FieldSpec scalarField(std::string name, std::string units, std::string description,
                             FieldOutput output) {
  FieldSpec f;
  f.name = std::move(name);
  f.units = std::move(units);
  f.description = std::move(description);
  f.output = output;
  return f;
}

}  // namespace ejecta
