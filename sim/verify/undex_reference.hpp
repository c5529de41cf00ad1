#pragma once
// The converged 1D reference of a centred charge in an inert medium (docs/undex.md, "The
// converged 1D reference"; `ejecta undex-reference`): an UNDEX scene mapped onto the 1D
// Lagrangian hydrocode of sim/exact/radial_lagrangian.hpp. The scene's geometry maps to the 1D
// symmetry (RZ and 3D: a sphere; 2D planar: a cylinder; 1D: a slab), its explosive body to the
// inner region (radius, density, energy, programmed burn from the detonation point), its one inert
// body to the outer region (out to its nearest face that is not a symmetry plane, the outer node
// free at the medium's initial pressure), and its gauges to their distances from the charge's
// centre.
#include <array>
#include <string>
#include <vector>

#include "sim/exact/radial_lagrangian.hpp"
#include "sim/setup/scene.hpp"

namespace ejecta::verify {

struct UndexReference {
  int symmetry = 3;                  // j: 1 planar, 2 cylindrical, 3 spherical
  std::array<double, 3> centre{};    // the detonation point [m]
  int side = 0;                      // 1D: +1 / -1 the charge and medium lie on that side only; 0 both
  double chargeRadius = 0.0;         // [m] (a slab lit at its walled end: its thickness)
  double extent = 0.0;               // the medium's outer radius [m]
  double ambient = 0.0;              // the medium's initial pressure [Pa]
  double chargeDetonationEnergy = 0.0;  // a JWL charge's e0 [J/kg]; 0 for another equation of state
  // Per scene gauge, in the scene's order: its distance from the centre [m] and the unit vector
  // towards it (zero at the centre).
  std::vector<double> gaugeRadius;
  std::vector<std::array<double, 3>> gaugeDirection;
  // Region 0 the charge, region 1 the medium; `zones` zones out to the medium's edge.
  exact::RadialSetup setup;
};

// Maps the scene with `zones` (at least 4) zones from the centre to the medium's edge. Throws
// SceneError "FILE[:LINE]: key 'KEY': reason" for a scene that is not one centred charge (lit at
// a point: its centre, or a 1D slab's walled end) in one inert medium at rest, and
// std::invalid_argument for too few zones.
UndexReference buildUndexReference(const Scene& scene, int zones);

// gauges_reference.csv: the layout of the SPH run's gauges.csv (sim/sources/gauges.hpp), the
// velocity along each gauge's direction from the centre, rows at least t_end / 20000 apart (and
// the last step). `gauges`: the hydrocode's, added in the scene's order.
std::string undexReferenceGaugeCsv(const Scene& scene, const UndexReference& reference,
                                   const std::vector<exact::RadialGauge>& gauges);

}  // namespace ejecta::verify
