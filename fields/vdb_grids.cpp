#include "fields/vdb_grids.hpp"
#include "fields/vdb_file.hpp"

#include <openvdb/openvdb.h>
#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/LevelSetRebuild.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <mutex>
#include <sstream>
#include <stdexcept>

#include "core/atomic_file.hpp"
#include "sim/io/snapshot.hpp"

namespace fs = std::filesystem;

namespace ejecta::fields {

namespace {

openvdb::Vec3d vec(const Point& p) { return {p[0], p[1], p[2]}; }
Point point(const openvdb::Vec3d& v) { return {v[0], v[1], v[2]}; }

void tagGrid(openvdb::GridBase& grid, const std::string& units, const GridSet& set,
             const GridFileMeta& meta) {
  grid.insertMeta("units", openvdb::StringMetadata(units));
  grid.insertMeta("time", openvdb::DoubleMetadata(meta.time));
  grid.insertMeta("step", openvdb::Int64Metadata(meta.step));
  grid.insertMeta("scene", openvdb::StringMetadata(meta.scene));
  grid.insertMeta("voxel_size", openvdb::DoubleMetadata(set.lattice.voxel()));
  grid.insertMeta("source_geometry", openvdb::StringMetadata(std::string(geometryName(set.source))));
}

// A FloatGrid from the lattice, one leaf per block; `value(b, v, active)` gives each voxel.
template <typename Value>
openvdb::FloatGrid::Ptr gridFromLattice(const SparseLattice& lat, float background, Value value) {
  auto grid = openvdb::FloatGrid::create(background);
  grid->setTransform(openvdb::math::Transform::createLinearTransform(lat.voxel()));
  using Leaf = openvdb::FloatTree::LeafNodeType;
  std::vector<Leaf*> leaves(lat.blockCount(), nullptr);
#pragma omp parallel for schedule(dynamic, 16)
  for (std::size_t b = 0; b < lat.blockCount(); ++b) {
    const Index3& o = lat.blockOrigin(b);
    auto* leaf = new Leaf(openvdb::Coord(o[0], o[1], o[2]), background, false);
    const float* filled = lat.data(b, 0);
    for (int v = 0; v < lat.blockVolume(); ++v)
      if (filled[v] > 0.0f) leaf->setValueOn(static_cast<openvdb::Index>(v), value(b, v));
    leaves[b] = leaf;
  }
  for (Leaf* leaf : leaves) grid->tree().addLeaf(leaf);
  return grid;
}

std::string metaString(const openvdb::MetaMap& m, const std::string& key) {
  const auto p = m.getMetadata<openvdb::StringMetadata>(key);
  return p ? p->value() : std::string();
}
double metaDouble(const openvdb::MetaMap& m, const std::string& key) {
  const auto p = m.getMetadata<openvdb::DoubleMetadata>(key);
  return p ? p->value() : 0.0;
}

std::shared_ptr<openvdb::io::File> openFile(const std::string& path) {
  auto file = std::make_shared<openvdb::io::File>(path);
  openGridFile(*file, path);
  return file;
}

}  // namespace

void writeGridFile(const std::string& path, const GridSet& set, const GridFileMeta& meta) {
  initialiseOpenVdb();
  const SparseLattice& lat = set.lattice;
  openvdb::GridPtrVec grids;
  for (std::size_t g = 0; g < set.grids.size(); ++g) {
    auto grid = gridFromLattice(lat, 0.0f, [&](std::size_t b, int v) { return set.value(g, b, v); });
    grid->setName(set.grids[g].name);
    grid->setGridClass(openvdb::GRID_FOG_VOLUME);
    tagGrid(*grid, set.grids[g].units, set, meta);
    grid->insertMeta("normalisation",
                     openvdb::StringMetadata(set.grids[g].shepard    ? "shepard"
                                             : set.grids[g].fraction ? "capped"
                                                                     : "none"));
    grids.push_back(grid);
  }
  // The material surface: the 0.5 contour of the filled fraction (channel 0), rebuilt as a
  // narrow-band signed distance field by OpenVDB (inside negative). A one-voxel slab has no
  // meaningful surface: planar runs get one only when extruded over several voxels.
  const bool thick = set.source != Geometry::Planar || [&] {
    int maxK = 0;
    for (std::size_t b = 0; b < lat.blockCount(); ++b) maxK = std::max(maxK, lat.blockOrigin(b)[2]);
    return maxK > 0 || lat.blockCount() == 0;
  }();
  if (meta.levelSet && thick && lat.blockCount() > 0) {
    // `surface`: all material (channel 0); `surface_<material>`: each body material whose plain
    // fraction grid is written.
    auto addSurface = [&](int channel, const std::string& name) {
      auto inverted = gridFromLattice(lat, 0.5f, [&](std::size_t b, int v) {
        return 0.5f - lat.data(b, channel)[v];
      });
      auto surface = openvdb::tools::levelSetRebuild(*inverted, 0.0f, 3.0f);
      surface->setName(name);
      surface->setGridClass(openvdb::GRID_LEVEL_SET);
      tagGrid(*surface, "m", set, meta);
      grids.push_back(surface);
    };
    addSurface(0, "surface");
    for (const GridSpec& g : set.grids)
      if (g.name.rfind("fraction_", 0) == 0 && !g.shepard)
        addSurface(g.channel, "surface_" + g.name.substr(9));
  }

  openvdb::MetaMap fileMeta;
  fileMeta.insertMeta("creator", openvdb::StringMetadata("ejecta " + std::string(kEjectaVersion)));
  fileMeta.insertMeta("scene", openvdb::StringMetadata(meta.scene));
  fileMeta.insertMeta("time", openvdb::DoubleMetadata(meta.time));
  fileMeta.insertMeta("step", openvdb::Int64Metadata(meta.step));
  fileMeta.insertMeta("source_geometry", openvdb::StringMetadata(std::string(geometryName(set.source))));
  fileMeta.insertMeta("particles", openvdb::Int64Metadata(static_cast<openvdb::Int64>(set.particles)));
  // One entry per material (a name may hold any character, so no joined list); none for a set
  // built without the run's materials, which reads as a file from before the list.
  if (!set.materials.empty()) {
    fileMeta.insertMeta("material_count", openvdb::Int64Metadata(static_cast<openvdb::Int64>(set.materials.size())));
    for (std::size_t m = 0; m < set.materials.size(); ++m)
      fileMeta.insertMeta("material_" + std::to_string(m), openvdb::StringMetadata(set.materials[m]));
  }
  if (meta.crater) {
    const CraterSetup& c = *meta.crater;
    const bool sphere = c.surface.kind == ReferenceSurface::Kind::Sphere;
    fileMeta.insertMeta("crater_surface", openvdb::StringMetadata(sphere ? "sphere" : "plane"));
    fileMeta.insertMeta("crater_center", openvdb::Vec3DMetadata(vec(c.surface.center)));
    fileMeta.insertMeta("crater_radius", openvdb::DoubleMetadata(c.surface.radius));
    fileMeta.insertMeta("crater_plane_point", openvdb::Vec3DMetadata(vec(c.surface.point)));
    fileMeta.insertMeta("crater_plane_normal", openvdb::Vec3DMetadata(vec(c.surface.normal)));
    fileMeta.insertMeta("crater_impact_point", openvdb::Vec3DMetadata(vec(c.impactPoint)));
    fileMeta.insertMeta("crater_along_track", openvdb::Vec3DMetadata(vec(c.alongTrack)));
    fileMeta.insertMeta("crater_planar", openvdb::BoolMetadata(c.planar));
    fileMeta.insertMeta("crater_target_density", openvdb::DoubleMetadata(c.targetDensity));
    fileMeta.insertMeta("crater_search_limit", openvdb::DoubleMetadata(c.searchLimit));
    std::string names;
    for (const std::string& n : c.targetNames) names += (names.empty() ? "" : ",") + n;
    fileMeta.insertMeta("crater_target_materials", openvdb::StringMetadata(names));
  }

  const fs::path target(path);
  if (target.has_parent_path()) fs::create_directories(target.parent_path());
  // A unique temporary beside the target, synced and renamed over it (core/atomic_file.hpp):
  // a reader or a crash sees the old file or the new one, never half of one.
  try {
    AtomicFileTarget out(target);
    openvdb::io::File file(out.tempPath().string());
    fileMeta.insertMeta(kSealKey, openvdb::StringMetadata(kSealFormat));
    file.write(grids, fileMeta);
    file.close();
    sealGridFile(out.tempPath());
    out.commit();
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": cannot write the VDB file: " + e.what());
  }
}

std::vector<StoredGrid> readGridFileInfo(const std::string& path) {
  auto file = openFile(path);
  std::vector<StoredGrid> out;
  openvdb::GridPtrVecPtr grids = file->getGrids();
  for (const openvdb::GridBase::Ptr& base : *grids) {
    StoredGrid s;
    s.name = base->getName();
    s.gridClass = openvdb::GridBase::gridClassToString(base->getGridClass());
    s.units = metaString(*base, "units");
    s.voxelSize = base->voxelSize()[0];
    s.activeVoxels = static_cast<std::size_t>(base->activeVoxelCount());
    s.time = metaDouble(*base, "time");
    if (const auto step = base->getMetadata<openvdb::Int64Metadata>("step")) s.step = static_cast<long>(step->value());
    s.scene = metaString(*base, "scene");
    s.sourceGeometry = metaString(*base, "source_geometry");
    s.normalisation = metaString(*base, "normalisation");
    if (auto grid = openvdb::gridPtrCast<openvdb::FloatGrid>(base)) {
      bool first = true;
      for (auto it = grid->cbeginValueOn(); it; ++it) {
        const float v = *it;
        if (first || v < s.minValue) s.minValue = v;
        if (first || v > s.maxValue) s.maxValue = v;
        first = false;
      }
    }
    out.push_back(s);
  }
  file->close();
  return out;
}

namespace {

openvdb::FloatGrid::Ptr readFloatGrid(openvdb::io::File& file, const std::string& path,
                                      const std::string& name) {
  if (!file.hasGrid(name)) throw std::runtime_error(path + ": no grid named '" + name + "'");
  auto grid = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid(name));
  if (!grid) throw std::runtime_error(path + ": grid '" + name + "' is not a float grid");
  return grid;
}

}  // namespace

double sampleGridFile(const std::string& path, const std::string& name, const Point& x) {
  auto file = openFile(path);
  auto grid = readFloatGrid(*file, path, name);
  file->close();
  openvdb::tools::GridSampler<openvdb::FloatTree, openvdb::tools::BoxSampler> sampler(
      grid->constTree(), grid->transform());
  return sampler.wsSample(vec(x));
}

GridFileCraterInput craterInputFromGridFile(const std::string& path) {
  auto file = openFile(path);
  const openvdb::MetaMap::Ptr meta = file->getMetadata();
  const std::string surface = metaString(*meta, "crater_surface");
  if (surface.empty())
    throw std::runtime_error(path + ": no crater metadata (the file was not written from an "
                             "impact run); measure the snapshot instead, or give --sphere/--plane");
  GridFileCraterInput in;
  CraterSetup& c = in.setup;
  auto v3 = [&](const std::string& key) {
    const auto p = meta->getMetadata<openvdb::Vec3DMetadata>(key);
    return p ? point(p->value()) : Point{};
  };
  c.surface.kind = surface == "sphere" ? ReferenceSurface::Kind::Sphere : ReferenceSurface::Kind::Plane;
  c.surface.center = v3("crater_center");
  c.surface.radius = metaDouble(*meta, "crater_radius");
  c.surface.point = v3("crater_plane_point");
  c.surface.normal = v3("crater_plane_normal");
  c.impactPoint = v3("crater_impact_point");
  c.alongTrack = v3("crater_along_track");
  if (const auto p = meta->getMetadata<openvdb::BoolMetadata>("crater_planar")) c.planar = p->value();
  c.targetDensity = metaDouble(*meta, "crater_target_density");
  c.searchLimit = metaDouble(*meta, "crater_search_limit");
  std::stringstream names(metaString(*meta, "crater_target_materials"));
  for (std::string n; std::getline(names, n, ',');) c.targetNames.push_back(n);

  std::vector<openvdb::FloatGrid::Ptr> grids;
  for (const std::string& n : c.targetNames) {
    const std::string name = "fraction_" + n;
    if (!file->hasGrid(name))
      throw std::runtime_error(path + ": no grid '" + name + "': crater measurement needs the "
                               "target's fraction grids (write them with grids = [\"fractions\"])");
    auto grid = readFloatGrid(*file, path, name);
    if (metaString(*grid, "normalisation") == "shepard")
      throw std::runtime_error(path + ": grid '" + name + "' is Shepard-normalised; crater "
                               "measurement needs plain sums (normalise = \"auto\" or \"none\")");
    in.voxel = grid->voxelSize()[0];
    grids.push_back(grid);
  }
  file->close();
  if (grids.empty()) throw std::runtime_error(path + ": the crater metadata names no target material");
  // A grid clipped to a region ends at its sides: measure no further than they are from the
  // impact point, less two voxels, across the crater axis.
  openvdb::CoordBBox box;
  for (const auto& g : grids) box.expand(g->evalActiveVoxelBoundingBox());
  const Point axis = c.surface.kind == ReferenceSurface::Kind::Sphere
                         ? Point{c.impactPoint[0] - c.surface.center[0], c.impactPoint[1] - c.surface.center[1],
                                 c.impactPoint[2] - c.surface.center[2]}
                         : c.surface.normal;
  const double axisNorm = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  double limit = c.searchLimit > 0.0 ? c.searchLimit : INFINITY;
  const int dims = c.planar ? 2 : 3;
  for (int d = 0; d < dims; ++d) {
    if (axisNorm > 0.0 && std::abs(axis[d]) / axisNorm > 0.5) continue;  // along the axis
    const double lo = box.min()[d] * in.voxel, hi = box.max()[d] * in.voxel;
    limit = std::min({limit, c.impactPoint[d] - lo - 2 * in.voxel, hi - c.impactPoint[d] - 2 * in.voxel});
  }
  if (std::isfinite(limit)) c.searchLimit = std::max(limit, in.voxel);
  // The samplers read the trees without accessors: safe from several threads at once.
  in.field = [grids](const Point& x) {
    double sum = 0.0;
    for (const auto& g : grids) {
      openvdb::tools::GridSampler<openvdb::FloatTree, openvdb::tools::BoxSampler> s(
          g->constTree(), g->transform());
      sum += s.wsSample(vec(x));
    }
    return sum;
  };
  return in;
}

}  // namespace ejecta::fields
