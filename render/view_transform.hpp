#pragma once
// From a View and the extent of what is drawn to the matrices that place it in the picture:
// orthographic for Plane and Axisymmetric views, perspective for 3D, auto-fitted when the view
// does not say where to look.
#include <array>

#include "render/scene.hpp"

namespace ejecta::render {

// An axis-aligned box [m]; empty until something is added.
struct Bounds {
  Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  bool empty() const { return lo[0] > hi[0]; }
  void add(const Vec3& p, double radius = 0.0);
  void add(const Bounds& other);
  Vec3 center() const;
};

// The outer corners of a slice's cells: (i, j) = (-1/2, -1/2), (nx - 1/2, -1/2), (-1/2, ny - 1/2),
// (nx - 1/2, ny - 1/2) in sample units.
std::array<Vec3, 4> sliceCorners(const SliceLayer& slice);

// Everything the scene draws (particles padded by their disc radius; in an Axisymmetric view
// mirrored about the axis), and the radius of the sphere about bounds.center() holding it.
struct PictureExtent {
  Bounds bounds;
  double radius = 0.0;
};
// The scene must be valid (validatePicture).
PictureExtent measurePicture(const Picture& scene, bool mirror);

using Mat4 = std::array<double, 16>;  // column-major, as OpenGL takes it

struct Framing {
  int plotWidth = 0, plotHeight = 0;  // pixels of the picture (without the strip)
  bool perspective = false;
  bool mirror = false;  // Axisymmetric: draw every layer also at x -> -x
  // Positions are sent to OpenGL in single precision relative to this point, so that a scene
  // far from the world's origin keeps its detail.
  Vec3 origin{};
  Mat4 view{};        // (world - origin) -> eye (looking along -z)
  Mat4 projection{};  // eye -> clip
  // Pixels per metre: exact for orthographic views, at the target's distance in perspective.
  double pixelsPerMetre = 0.0;
  // A sphere of radius r at clip-space w covers 2 r sizeScale / w pixels.
  double sizeScale = 0.0;

  // Where a world point lands: pixel coordinates in the picture (x from the left, y from the
  // top, continuous: the centre of pixel (i, j) is (i + 0.5, j + 0.5)), and its clip w.
  std::array<double, 3> project(const Vec3& world) const;
};

// Throws std::invalid_argument for a non-positive plot size or view width, a degenerate camera
// (position at target, up along the line of sight) or a field of view outside (0, 180).
Framing frameView(const View& view, const PictureExtent& extent, int plotWidth, int plotHeight);

}  // namespace ejecta::render
