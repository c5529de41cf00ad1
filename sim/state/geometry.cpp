#include "sim/state/geometry.hpp"

namespace ejecta {

std::string_view geometryName(Geometry g) {
  switch (g) {
    case Geometry::Line: return "1d";
    case Geometry::Planar: return "2d";
    case Geometry::Axisymmetric: return "rz";
    case Geometry::Spatial: return "3d";
  }
  return "3d";
}

std::string_view geometryLayoutName(Geometry g) {
  switch (g) {
    case Geometry::Line: return "line";
    case Geometry::Planar: return "planar";
    case Geometry::Axisymmetric: return "rz";
    case Geometry::Spatial: return "3d";
  }
  return "3d";
}

bool parseGeometry(std::string_view text, Geometry& out) {
  if (text == "1d" || text == "line") { out = Geometry::Line; return true; }
  if (text == "2d" || text == "planar") { out = Geometry::Planar; return true; }
  if (text == "rz" || text == "axisymmetric") { out = Geometry::Axisymmetric; return true; }
  if (text == "3d" || text == "spatial") { out = Geometry::Spatial; return true; }
  return false;
}

}  // namespace ejecta
