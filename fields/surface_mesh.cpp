// Level set -> triangles with OpenVDB's volumeToMesh. The one translation unit of the surface
// mesher that includes OpenVDB.
#include "fields/surface_mesh.hpp"
#include "fields/vdb_file.hpp"

#include <openvdb/openvdb.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <cmath>
#include <filesystem>
#include <mutex>
#include <stdexcept>

namespace ejecta::fields {

namespace {

using Vec3 = std::array<double, 3>;

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }

openvdb::FloatGrid::Ptr readFloatGrid(const std::string& path, const std::string& name) {
  openvdb::io::File file(path);
  openGridFile(file, path);
  requireGrid(file, path, name);
  auto grid = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid(name));
  file.close();
  if (!grid) throw std::runtime_error(path + ": grid '" + name + "' is not a float grid");
  return grid;
}

openvdb::FloatGrid::Ptr readLevelSet(const std::string& path, const std::string& name) {
  auto grid = readFloatGrid(path, name);
  if (grid->getGridClass() != openvdb::GRID_LEVEL_SET)
    throw std::runtime_error(path + ": grid '" + name + "' is not a level set (class '" +
                             openvdb::GridBase::gridClassToString(grid->getGridClass()) + "')");
  return grid;
}

void checkOptions(const std::string& path, const SurfaceMeshOptions& options) {
  if (!(options.adaptivity >= 0.0 && options.adaptivity <= 1.0))
    throw std::invalid_argument(path + ": surface mesh adaptivity must be in [0, 1]");
  if (!std::isfinite(options.isovalue))
    throw std::invalid_argument(path + ": surface mesh isovalue must be finite");
}

// The narrow band's half width is the background value (world units for ejecta's level sets).
void checkInsideBand(const std::string& path, const openvdb::FloatGrid& grid, const SurfaceMeshOptions& options) {
  const double voxel = grid.voxelSize()[0];
  const double band = std::abs(static_cast<double>(grid.background()));
  if (std::abs(options.isovalue) > band - voxel)
    throw std::invalid_argument(path + ": isovalue " + std::to_string(options.isovalue) + " m of grid '" +
                                options.grid + "' lies outside its narrow band (half width " +
                                std::to_string(band) + " m, less one voxel " + std::to_string(voxel) +
                                " m, is the most it can be)");
}

// volumeToMesh on `grid`, its quads split into triangles. volumeToMesh winds its polygons
// clockwise seen from outside (the right-hand normal points inwards) for level sets and fog
// volumes alike (it knows which side is inside from the grid's class): reversed, so the mesh
// follows the radiation code's convention (counter-clockwise from the front). The sphere tests
// (test_fields_surface, test_fields_slice) check the sign.
SurfaceMesh meshGrid(const std::string& path, const openvdb::FloatGrid& grid, const SurfaceMeshOptions& options) {
  SurfaceMesh mesh;
  mesh.voxelSize = grid.voxelSize()[0];
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(grid, points, triangles, quads, options.isovalue, options.adaptivity);
  if (points.size() > UINT32_MAX) throw std::runtime_error(path + ": surface mesh too large for 32-bit indices");

  mesh.vertices.reserve(points.size());
  for (const openvdb::Vec3s& p : points) mesh.vertices.push_back({p[0], p[1], p[2]});
  mesh.quads = quads.size();
  mesh.triangles.reserve(triangles.size() + 2 * quads.size());
  auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) { mesh.triangles.push_back({a, c, b}); };
  for (const openvdb::Vec3I& t : triangles) add(t[0], t[1], t[2]);
  for (const openvdb::Vec4I& q : quads) {
    // Split along the shorter diagonal: better-shaped triangles on a curved surface.
    const double d02 = norm(sub(mesh.vertices[q[0]], mesh.vertices[q[2]]));
    const double d13 = norm(sub(mesh.vertices[q[1]], mesh.vertices[q[3]]));
    if (d02 <= d13) {
      add(q[0], q[1], q[2]);
      add(q[0], q[2], q[3]);
    } else {
      add(q[0], q[1], q[3]);
      add(q[1], q[2], q[3]);
    }
  }
  return mesh;
}

}  // namespace

double SurfaceMesh::area() const {
  double a = 0.0;
  for (const auto& t : triangles)
    a += 0.5 * norm(cross(sub(vertices[t[1]], vertices[t[0]]), sub(vertices[t[2]], vertices[t[0]])));
  return a;
}

double SurfaceMesh::enclosedVolume() const {
  // Sum of the signed tetrahedra (origin, v0, v1, v2); relative to the first vertex, so that a
  // mesh far from the origin does not lose digits.
  if (vertices.empty()) return 0.0;
  const Vec3& o = vertices.front();
  double v = 0.0;
  for (const auto& t : triangles)
    v += dot(sub(vertices[t[0]], o), cross(sub(vertices[t[1]], o), sub(vertices[t[2]], o)));
  return v / 6.0;
}

SurfaceMesh meshSurfaceFile(const std::string& path, const SurfaceMeshOptions& options) {
  checkOptions(path, options);
  const openvdb::FloatGrid::Ptr grid = readLevelSet(path, options.grid);
  checkInsideBand(path, *grid, options);
  return meshGrid(path, *grid, options);
}

SurfaceMesh meshIsoSurfaceFile(const std::string& path, const SurfaceMeshOptions& options) {
  checkOptions(path, options);
  const openvdb::FloatGrid::Ptr grid = readFloatGrid(path, options.grid);
  if (grid->getGridClass() == openvdb::GRID_LEVEL_SET) {
    checkInsideBand(path, *grid, options);
    return meshGrid(path, *grid, options);
  }
  const double background = grid->background();
  if (!(options.isovalue > background))
    throw std::invalid_argument(path + ": isovalue " + std::to_string(options.isovalue) + " of grid '" + options.grid +
                                "' must exceed its background value " + std::to_string(background) +
                                " (the value outside its active voxels), or the surface cannot close");
  return meshGrid(path, *grid, options);
}

std::optional<double> gridVoxelSize(const std::string& path, const std::string& grid) {
  initialiseOpenVdb();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
  try {
    verifyGridFile(path);
    openvdb::io::File file(path);
    file.open();
    if (!file.hasGrid(grid)) return std::nullopt;
    const double voxel = file.readGridMetadata(grid)->voxelSize()[0];
    file.close();
    return voxel;
  } catch (const openvdb::Exception&) {
    return std::nullopt;
  }
}

}  // namespace ejecta::fields
