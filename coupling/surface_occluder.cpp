// Grid file -> occluder mesh: fields::meshSurfaceFile at an inward isovalue, copied into a
// radiation::TriangleMesh.
#include "coupling/surface_occluder.hpp"

#include <cmath>
#include <stdexcept>

#include "fields/surface_mesh.hpp"

namespace ejecta::coupling {

radiation::TriangleMesh occluderFromGridFile(const std::string& path, const SurfaceOccluderOptions& options,
                                             SurfaceOccluderStats* stats) {
  if (!(options.insetVoxels >= 0.0 && options.insetVoxels <= 2.0))
    throw std::invalid_argument(path + ": the occluder inset must be in [0, 2] voxels (the level set's "
                                "narrow band is 3 voxels each side)");
  const std::optional<double> voxel = fields::gridVoxelSize(path, options.grid);
  if (!voxel)
    throw std::runtime_error(path + ": no level set '" + options.grid + "' (or not a readable grid file)");
  fields::SurfaceMeshOptions mo;
  mo.grid = options.grid;
  mo.adaptivity = options.adaptivity;
  mo.isovalue = -options.insetVoxels * *voxel;  // the level set is negative inside
  const fields::SurfaceMesh m = fields::meshSurfaceFile(path, mo);
  if (m.empty())
    throw std::invalid_argument(path + ": level set '" + options.grid + "' has no surface " +
                                std::to_string(options.insetVoxels) + " voxels inside its zero");

  radiation::TriangleMesh mesh;
  mesh.vertices.reserve(m.vertices.size());
  for (const auto& v : m.vertices) mesh.vertices.push_back({v[0], v[1], v[2]});
  const std::uint32_t patch = mesh.patchIndex("asteroid");
  mesh.triangles = m.triangles;
  mesh.patchOf.assign(mesh.triangles.size(), patch);
  if (stats) {
    stats->triangles = mesh.triangleCount();
    stats->voxelSize = m.voxelSize;
    stats->inset = -mo.isovalue;
    stats->area = m.area();
  }
  return mesh;
}

bool gridFileHasSurface(const std::string& path, const std::string& grid) {
  return fields::gridVoxelSize(path, grid).has_value();
}

}  // namespace ejecta::coupling
