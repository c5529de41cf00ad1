#pragma once
// A Whipple shield measured on a run's particles: whether the rear wall is perforated, how far
// its rear face has bulged, the hole, and the debris cloud between the bumper and the wall.
//
// Coordinates: s is the distance along the wall's normal in the projectile's direction of
// travel (s = direction * x[normalAxis]); the lateral coordinates are the other axes (RZ: r).
// The rear wall is perforated (the ballistic-limit equations' failure: perforation or detached
// spall, Christiansen 1993) when either
//   - a through-thickness path of failed material opens: a column through the wall, at least
//     a smoothing length wide, holds no intact wall material (damage below the threshold), or
//   - material lies behind the wall: particles more than 2h behind the rear envelope of the
//     intact wall in their columns (the original rear face where a column is open), at least
//     a resolved piece's worth of them: a section of (2 spacings)^2 (3D: a volume of
//     (2 spacings)^3). A particle or two shed from a bulging rear face is below what the run
//     resolves; it is reported (massBehind) but does not make the verdict.
// Both are measured inside the wall's lateral extent, two spacings clear of its edges. A hole
// narrower than about 2h is below the resolution. Method and limits: docs/whipple.md.
#include <array>
#include <optional>
#include <string>

#include "sim/setup/scene.hpp"

namespace ejecta::fields {

// Where the shield is, worked out from the scene's [shield] table.
struct ShieldFrame {
  Geometry geometry = Geometry::Axisymmetric;
  int normalAxis = 1;                   // the wall's thin axis (RZ: 1, z)
  double direction = -1.0;              // the projectile moves along direction * e_normalAxis
  int wallMaterial = -1;
  int bumperMaterial = -1;                 // -1: no bumper
  std::string wallName, bumperName;
  double wallFront = 0.0, wallRear = 0.0;  // s of the wall's faces, front < rear [m]
  std::optional<double> bumperRear;        // s of the bumper's rear face [m]
  std::array<double, 3> wallMin{}, wallMax{};  // the wall box [m]
  double spacing = 0.0;                    // the wall's lattice spacing [m]
  std::array<double, 3> shotPoint{};       // where the projectile's path meets the first plate [m]
  double damageThreshold = 0.99;
  // Lateral sides of the wall that lie on a mirror plane (a domain wall at the box's face: a
  // 3D scene modelling half or a quarter of a symmetric shot). The columns reach up to them,
  // and areas, masses and momenta are those of the whole shield (mirrorCopies() times the
  // modelled part's).
  std::array<bool, 3> mirrorLow{}, mirrorHigh{};
  int mirrorCopies() const;

  double s(const ParticleSet& p, std::size_t i) const { return direction * p.x[normalAxis][i]; }
};

// The frame of a scene with a [shield] table; nothing without one. Throws SceneError (naming
// the scene) when the projectile does not travel towards the wall's plane.
std::optional<ShieldFrame> shieldFrameFromScene(const Scene& scene);

struct WallState {
  bool hole = false;               // a through-thickness path of failed material
  double holeArea = 0.0;           // [m^2] of the open columns (2D planar: the slot's width [m])
  double holeDiameter = 0.0;       // [m] the circle of that area (2D planar: the slot's width)
  double massBehind = 0.0;         // [kg] behind the wall (RZ: rings; planar: per metre)
  double wallMassBehind = 0.0;     // [kg] of it, the wall's own: detached spall
  // The size of what is behind: its section [m^2] (RZ: sum m / (2 pi r rho); planar: sum m/rho)
  // or, in 3D, its volume [m^3]; and whether that is at least a resolved piece (see above).
  double sizeBehind = 0.0;
  bool resolvedBehind = false;
  // [m] how far the wall's body (its largest piece of particles joined by overlapping kernels)
  // reaches with intact material beyond the rear face's first layer: the bulge, not a plug
  // or a spall layer flying off.
  double deflection = 0.0;
  bool perforated() const { return hole || resolvedBehind; }
};

struct DebrisCloud {
  // Everything but the wall and the bumper's own body (its largest piece joined by overlapping
  // kernels, which may bend back) that lies more than h beyond the bumper's rear face.
  double mass = 0.0;               // [kg]
  double momentum = 0.0;           // [kg m/s] along the direction of travel
  double lateralMomentum = 0.0;    // [kg m/s] |sideways| (3D, planar); 0 in RZ by symmetry
  double leadingEdge = 0.0;        // [m] of its furthest particle beyond the bumper's rear face
  double leadingSpeed = 0.0;       // [m/s] the fastest normal velocity in it
  double radius = 0.0;             // [m] its widest lateral distance from the shot line
  double halfAngle = 0.0;          // [rad] atan(radius / leadingEdge): the cone holding it
  double massOnWall = 0.0;         // [kg] of it, what has reached the wall's front face
};

// The wall now. `p` holds every particle of the run (a distributed run: gathered).
WallState measureWall(const ParticleSet& p, const ShieldFrame& frame);
// The rear face's deflection alone (as WallState::deflection).
double rearFaceDeflection(const ParticleSet& p, const ShieldFrame& frame);
DebrisCloud measureDebrisCloud(const ParticleSet& p, const ShieldFrame& frame);

}  // namespace ejecta::fields
