#pragma once
// Spacecraft geometry: primitives with named faces, and the pose that places a body-frame mesh
// in the scene.
//
// Body frame: +x is forward (the flight direction; the face that leads, `side0`, is the seed's
// side facing the crater, chapter 4, Figure 4.2), +y is up, +z = x cross y. Primitives are built
// centred on the body origin with outward normals.
//   box:      `side0` (+x, front), `aft` (-x), `side1` (+y), `side2` (-y), `side3` (+z),
//             `side4` (-z); the seed's 2D square cross-section has side0, side1, side2 and aft.
//   cylinder: axis along x; `front` cap (+x), `aft` cap (-x), the mantle `side` (or `side0`..
//             `sideN-1` in N sectors, sector k centred on the direction at angle 2 pi k / N from
//             +y towards +z).
// Plates for tests and geometry files: a rectangle (one patch, normal edge1 x edge2), a disc (a
// polygon fan), a sphere (a subdivided icosahedron) and an enclosure box (inward normals).
#include <string>

#include "radiation/mesh.hpp"

namespace ejecta::radiation {

// A rotation as a 3x3 matrix, rows of the matrix R with world = R * body.
struct Rotation {
  std::array<Vec3, 3> row{Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
  Vec3 apply(const Vec3& b) const {
    return {vec3::dot(row[0], b), vec3::dot(row[1], b), vec3::dot(row[2], b)};
  }
  // Body x, y, z axes in the world frame (the columns of R).
  Vec3 axis(int k) const { return {row[0][k], row[1][k], row[2][k]}; }

  // Body +x along `forward`, body +y along the part of `up` perpendicular to it. Throws
  // std::invalid_argument when either is zero, not finite or they are parallel.
  static Rotation fromForwardUp(const Vec3& forward, const Vec3& up);
  // Right-handed rotation by `angle` [rad] about `axis` (Rodrigues). Throws for a zero axis.
  static Rotation fromAxisAngle(const Vec3& axis, double angle);
};

// Where the spacecraft is: body origin position [m], attitude (body to world) and velocity
// [m/s]. The velocity only moves the pose in time (at(t)); at 10 km/s, v/c = 3e-5, so the
// aberration and Doppler shift of the incident radiation are neglected.
struct Pose {
  Vec3 position{};
  Rotation attitude;
  Vec3 velocity{};

  Vec3 toWorld(const Vec3& body) const { return vec3::add(position, attitude.apply(body)); }
  Vec3 directionToWorld(const Vec3& body) const { return attitude.apply(body); }
  // The pose after flying for `dt` seconds at constant velocity.
  Pose at(double dt) const;
};

// The mesh moved from the body frame into the world by `pose` (patches and winding kept).
TriangleMesh placeMesh(const TriangleMesh& body, const Pose& pose);

// A box of `depth` along x, `height` along y and `width` along z [m], centred on the origin,
// faces named as above. Throws std::invalid_argument for non-positive sizes.
TriangleMesh makeBox(double depth, double height, double width);
// A cylinder of `radius` and `length` along x with `segments` sides (>= 3) and `sectors`
// mantle patches (1: one patch `side`). The polygon radius is enlarged so that each cap's area
// is exactly pi r^2 (and the mantle's 2 pi r L to second order), keeping a faceted cylinder's
// view factors close to the smooth one's.
TriangleMesh makeCylinder(double radius, double length, int segments, int sectors = 1);

// A parallelogram corner + s edge1 + t edge2 (s, t in [0, 1]), one patch, two triangles.
TriangleMesh makeRectangle(const std::string& patch, const Vec3& corner, const Vec3& edge1,
                           const Vec3& edge2);
// A disc of `radius` about `center` facing `normal`, a fan of `segments` triangles whose
// polygon has the disc's exact area.
TriangleMesh makeDisc(const std::string& patch, const Vec3& center, const Vec3& normal,
                      double radius, int segments);
// A sphere as an icosahedron subdivided `subdivisions` times (20 * 4^n triangles), vertices on
// the sphere, outward normals, one patch.
TriangleMesh makeSphere(const std::string& patch, const Vec3& center, double radius,
                        int subdivisions);
// The inside of an axis-aligned box [lo, hi]: six patches `x-`, `x+`, `y-`, `y+`, `z-`, `z+`
// (the wall at the low/high end of each axis), normals pointing inwards.
TriangleMesh makeEnclosure(const Vec3& lo, const Vec3& hi);

}  // namespace ejecta::radiation
