#pragma once
// Fragment identification: friends-of-friends on a run's particles, linked by the kernel's
// support and split by damage. Two particles are friends when they are closer than
//   linkFactor * (h_i + h_j) / 2        (linkFactor = 2: the kernels' support, 2h, overlaps)
// and neither has failed (damage >= damageThreshold). A fragment is a maximal set of particles
// joined by chains of friends, so a band of failed material separates two intact pieces, and a
// failed particle is a fragment of its own (cohesionless material: granular debris below the
// resolution). Materials without fracture (fluids, explosives) have damage 0 and link by
// distance alone. Method, conventions and limits: docs/fragments.md.
//
// Geometry: in 3D a fragment is a body, its size the diameter of the sphere of its volume
// sum(m/rho). In RZ (each particle a ring) a fragment that reaches the axis is a body of
// revolution, sized the same way; one that does not is a ring (`ring`), which in reality breaks
// into pieces the 2D model cannot resolve: its size is the diameter of the circle of its
// cross-section, sum m / (2 pi r rho), and its mass the whole ring's. In 2D planar runs a
// fragment is a rod per metre of depth, sized by its cross-section sum m/rho the same way.
//
// Deterministic for any thread count: components are a property of the friendship graph, and
// each fragment's sums run in particle order.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "sim/state/geometry.hpp"
#include "sim/state/particles.hpp"

namespace ejecta::fields {

struct FragmentOptions {
  // Friends when r_ij < linkFactor (h_i + h_j) / 2; 2 = the kernel's support (ejecta's kernels
  // all reach 2h). Must be > 0.
  double linkFactor = 2.0;
  // A particle with damage at or above this has failed and links to nobody. Grady-Kipp cracks
  // and principal-stress failure reach D = 1 exactly; 0.99 also counts particles a step short
  // of it. Above 1: damage never splits.
  double damageThreshold = 0.99;
  // A fragment's size counts as measured when its equivalent diameter spans at least this many
  // particle spacings (the spacing being (V/n)^(1/dim) of its own particles): a one-spacing
  // error on the diameter is then at most 1/resolvedSpacings of it.
  double resolvedSpacings = 4.0;
};

struct Fragment {
  std::size_t particles = 0;
  std::int64_t firstId = 0;          // the smallest particle id in it (a stable name)
  double mass = 0.0;                 // [kg] (RZ: ring; planar: per metre of depth)
  double volume = 0.0;               // sum m/rho [m^3] (planar: the cross-section [m^2])
  double section = 0.0;              // cross-section area [m^2]: 2D planar and RZ; 0 in 3D
  double diameter = 0.0;             // equivalent diameter [m] (see the header's comment)
  double spacing = 0.0;              // mean particle spacing in it [m]
  std::array<double, 3> center{};    // centre of mass [m] (RZ: (r, z) of the section's centroid)
  std::array<double, 3> velocity{};  // momentum / mass [m/s]
  double speed = 0.0;                // |velocity| [m/s]
  double kineticEnergy = 0.0;        // sum 1/2 m v^2 [J] (RZ: ring; planar: per metre)
  int material = -1;                 // the material with the largest share of its mass
  double meanDamage = 0.0;           // mass-weighted
  bool failed = false;               // a single failed particle (granular debris)
  bool ring = false;                 // RZ: does not reach the axis (a ring, not a body)
  bool resolved = false;             // diameter >= resolvedSpacings spacings
};

struct FragmentCensus {
  Geometry geometry = Geometry::Spatial;
  std::vector<Fragment> fragments;   // by mass, largest first (ties: smallest firstId)
  // For each real particle (in the set's order), the index of its fragment in `fragments`.
  std::vector<std::uint32_t> fragmentOf;
  double totalMass = 0.0;
  std::array<double, 3> totalMomentum{};
  std::size_t resolvedCount() const;
  std::size_t failedCount() const;   // single failed particles
};

// The fragments of the real particles of `p` (ghosts are ignored). 1D runs are refused
// (std::invalid_argument), as are a non-positive link factor or resolution and non-positive h.
FragmentCensus identifyFragments(const ParticleSet& p, Geometry geometry,
                                 const FragmentOptions& options = {});

// One CSV row per fragment, largest first: index, particles, first_id, material (its name from
// `materialNames`), mass, volume, diameter, spacing, center, velocity, speed, kinetic energy,
// mean damage, failed, ring, resolved. Units in the header.
std::string fragmentsCsv(const FragmentCensus& census, const std::vector<std::string>& materialNames);

// The cumulative size-frequency distribution: for each distinct diameter d (largest first), the
// number and the mass of fragments at least that large, and of the measured ones among them.
struct SizeFrequencyRow {
  double diameter = 0.0;             // [m]
  std::size_t countAtLeast = 0;
  double massAtLeast = 0.0;          // [kg]
  std::size_t measuredCountAtLeast = 0;
  double measuredMassAtLeast = 0.0;  // [kg]
};
std::vector<SizeFrequencyRow> sizeFrequency(const FragmentCensus& census);

}  // namespace ejecta::fields
