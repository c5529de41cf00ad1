#pragma once
// The spatial setting of a run: how many coordinates a particle has and what they mean.
#include <string>
#include <string_view>

namespace ejecta {

enum class Geometry {
  Line,          // 1D slab symmetry: x only
  Planar,        // 2D plane: x, y (per unit depth)
  Axisymmetric,  // 2D RZ: r = x >= 0, z = y; each particle is a ring about the z axis
  Spatial        // 3D: x, y, z
};

// Number of coordinates integrated (1, 2 or 3).
constexpr int spatialDimension(Geometry g) {
  switch (g) {
    case Geometry::Line: return 1;
    case Geometry::Planar: return 2;
    case Geometry::Axisymmetric: return 2;
    case Geometry::Spatial: return 3;
  }
  return 3;
}

// Names as they appear in scene files and snapshot attributes: "1d", "2d", "rz", "3d".
std::string_view geometryName(Geometry g);
// The snapshot attribute `geometry`: "line", "planar", "rz", "3d".
std::string_view geometryLayoutName(Geometry g);
// Parses "1d", "2d"/"planar", "rz"/"axisymmetric", "3d"; returns false if unknown.
bool parseGeometry(std::string_view text, Geometry& out);

}  // namespace ejecta
