#pragma once
// The seed's geometric estimate of the radiation reaching a spacecraft side (thesis chapter 4.2),
// kept to compare with the ray-cast flux on the same emitters and patch:
//   eq. 4.7:  Omega_i = l / r_i^2
//   eq. 4.8:  alpha_r sum_i Omega_i eps_e sigma T_i^4 = eps_r sigma T_r^4
// In the seed's Figure 4.3, H is a hot particle, B and C the ends of the spacecraft side (the
// "1 m height assumed for the spacecraft"), HB = HC, D the midpoint of BC; r = HD and l = BC.
// So Omega_i is the angle the side subtends at the particle, in a 2D cross-section, written
// l / r^2 (dimensionally 1/m: the plane angle is l / r, the small-angle solid angle of an l x l
// side l^2 / r^2; with l = 1 m both read as l / r^2). This function returns the sum
//   q_seed = sum_i Omega_i eps_i sigma T_i^4
// over the emitters in front of the patch, with no occlusion, no cosine factor at the receiver,
// no division by pi and no dependence on the emitter's size: each particle adds the same amount
// whatever its size, so q_seed grows with the particle count. docs/view_factors.md compares it
// with the view-factor flux q = sum_i eps_i sigma T_i^4 F_i.
//
// The alternative reading, l = the emitter's size across the line of sight, is available as
// BaselineLength::EmitterDiameter (l = 2 radius).
#include <cstddef>

#include "radiation/emitters.hpp"
#include "radiation/mesh.hpp"

namespace ejecta::radiation {

enum class BaselineLength {
  ReceiverSide,     // l = the side's size (the seed's 1 m)
  EmitterDiameter,  // l = 2 x the emitter's radius
};

struct BaselineOptions {
  BaselineLength length = BaselineLength::ReceiverSide;
  // l for ReceiverSide [m]; 0: the square root of the patch area (1 m for the seed's 1 m side).
  double receiverSide = 0.0;
  // Count only emitters strictly in front of the patch plane, (x_i - centre) . normal > 0 (the
  // seed assigns each side the particles it "sees"; with no occlusion test, that is the half
  // space in front of it).
  bool frontOnly = true;
};

struct BaselineResult {
  double flux = 0.0;           // q_seed = sum Omega_i eps_i sigma T_i^4 [W/m^2 as the seed uses it]
  double solidAngleSum = 0.0;  // sum Omega_i [the seed's sr; 1/m strictly]
  std::size_t counted = 0;     // emitters included
};

// Omega = l / r^2 (eq. 4.7). Throws std::invalid_argument for r <= 0.
double seedSolidAngle(double l, double r);

// q_seed for a receiver at `centre` with unit `normal` (r = |x_i - centre|); `side` is l for
// ReceiverSide when options.receiverSide is 0. An emitter at the centre is an error.
BaselineResult seedBaseline(const Emitters& emitters, const Vec3& centre, const Vec3& normal,
                            double side, const BaselineOptions& options = {});
// For a mesh patch: centre = area-weighted centroid, normal = mean normal, side = sqrt(area).
BaselineResult seedBaseline(const Emitters& emitters, const TriangleMesh& mesh, std::size_t patch,
                            const BaselineOptions& options = {});

}  // namespace ejecta::radiation
