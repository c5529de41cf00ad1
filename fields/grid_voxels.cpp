// Hot voxels of a grid file: one pass over the active values of a fog grid, with the fraction
// grids looked up at the kept voxels. The one translation unit of the reader that includes
// OpenVDB.
#include "fields/grid_voxels.hpp"
#include "core/join.hpp"
#include "fields/vdb_file.hpp"

#include <openvdb/openvdb.h>
#include <openvdb/tools/Interpolation.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <mutex>
#include <stdexcept>

namespace ejecta::fields {

namespace {

std::string metaString(const openvdb::GridBase& g, const std::string& key) {
  const auto p = g.getMetadata<openvdb::StringMetadata>(key);
  return p ? p->value() : std::string();
}

openvdb::FloatGrid::Ptr readFloat(openvdb::io::File& file, const std::string& path, const std::string& name) {
  auto grid = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid(name));
  if (!grid) throw std::runtime_error(path + ": grid '" + name + "' is not a float grid");
  return grid;
}

// The value of `g` at index coordinate c of `reference`'s lattice: exact when both share the
// transform (ejecta writes every grid of a file on one lattice), else trilinear in world space.
class LatticeLookup {
 public:
  LatticeLookup(const openvdb::FloatGrid& g, const openvdb::FloatGrid& reference)
      : same_(g.transform() == reference.transform()), accessor_(g.getConstAccessor()),
        sampler_(g.constTree(), g.transform()), reference_(reference) {}
  double operator()(const openvdb::Coord& c) {
    if (same_) return accessor_.isValueOn(c) ? static_cast<double>(accessor_.getValue(c)) : 0.0;
    return sampler_.wsSample(reference_.indexToWorld(c));
  }

 private:
  bool same_;
  openvdb::FloatGrid::ConstAccessor accessor_;
  openvdb::tools::GridSampler<openvdb::FloatTree, openvdb::tools::BoxSampler> sampler_;
  const openvdb::FloatGrid& reference_;
};

}  // namespace

GridVoxels readGridVoxels(const std::string& path, const GridVoxelOptions& options) {
  if (!std::isfinite(options.threshold))
    throw std::invalid_argument(path + ": the voxel threshold must be finite");
  openvdb::io::File file(path);
  openGridFile(file, path);
  requireGrid(file, path, options.grid);
  const std::vector<std::string> names = gridNamesIn(file);
  const openvdb::FloatGrid::Ptr grid = readFloat(file, path, options.grid);
  if (!grid->transform().isLinear() || !grid->hasUniformVoxels())
    throw std::runtime_error(path + ": grid '" + options.grid + "' does not have cubic voxels on a linear transform");

  GridVoxels out;
  out.grid = options.grid;
  out.units = metaString(*grid, "units");
  out.sourceGeometry = metaString(*grid, "source_geometry");
  if (const auto t = grid->getMetadata<openvdb::DoubleMetadata>("time")) out.time = t->value();
  out.voxelSize = grid->voxelSize()[0];
  out.voxelVolume = out.voxelSize * out.voxelSize * out.voxelSize;
  out.activeVoxels = static_cast<std::size_t>(grid->activeVoxelCount());

  std::vector<openvdb::Coord> kept;
  auto keep = [&](const openvdb::Coord& c, float v) {
    if (!(static_cast<double>(v) >= options.threshold)) return;
    const openvdb::Vec3d w = grid->indexToWorld(c);
    out.x.push_back(w[0]);
    out.y.push_back(w[1]);
    out.z.push_back(w[2]);
    out.value.push_back(v);
    kept.push_back(c);
  };
  for (auto it = grid->cbeginValueOn(); it; ++it) {
    if (it.isVoxelValue()) {
      keep(it.getCoord(), *it);
    } else {  // an active tile: all its voxels share the value
      const openvdb::CoordBBox box = it.getBoundingBox();
      for (auto c = box.begin(); c; ++c) keep(*c, *it);
    }
  }

  if (options.fractions) {
    out.fractionsAreFill = true;
    for (const std::string& name : names) {
      if (name.rfind("fraction_", 0) != 0 || name.size() == 9) continue;
      const openvdb::FloatGrid::Ptr f = readFloat(file, path, name);
      out.materials.push_back(name.substr(9));
      // "capped" (what runs write: the plain sum, divided by S only where S > 1) is a filled
      // fraction too; "shepard" is a share of what is present.
      const std::string normalisation = metaString(*f, "normalisation");
      if (normalisation != "none" && normalisation != "capped") out.fractionsAreFill = false;
      LatticeLookup lookup(*f, *grid);
      std::vector<double> values(kept.size());
      for (std::size_t i = 0; i < kept.size(); ++i) values[i] = lookup(kept[i]);
      out.fraction.push_back(std::move(values));
    }
    if (out.materials.empty()) out.fractionsAreFill = false;
    if (!out.materials.empty()) {
      const openvdb::MetaMap::Ptr meta = file.getMetadata();
      const auto count = meta->getMetadata<openvdb::Int64Metadata>("material_count");
      std::vector<std::string> listed;
      for (openvdb::Int64 m = 0; count && m < count->value(); ++m) {
        const auto name = meta->getMetadata<openvdb::StringMetadata>("material_" + std::to_string(m));
        if (!name) throw std::runtime_error(path + ": material_count is " + std::to_string(count->value()) +
                                            " but material_" + std::to_string(m) + " is missing");
        listed.push_back(name->value());
        if (std::find(out.materials.begin(), out.materials.end(), name->value()) == out.materials.end())
          out.missingFractions.push_back(name->value());
      }
      // A fraction of a material the run did not have: the file was edited or put together from
      // two runs, and its fractions no longer describe one body. (No list: a file from before it.)
      if (count)
        for (const std::string& m : out.materials)
          if (std::find(listed.begin(), listed.end(), m) == listed.end())
            throw std::runtime_error(path + ": grid 'fraction_" + m + "' is of a material the file's material list (" +
                                     (listed.empty() ? std::string("empty") : joinList(listed)) +
                                     ") does not have; was the file put together from two runs?");
    }
  }
  file.close();
  return out;
}

}  // namespace ejecta::fields
