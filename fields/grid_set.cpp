#include "fields/grid_set.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "fields/grid_memory.hpp"
#include "fields/lattice_merge.hpp"
#include "fields/revolve.hpp"
#include "sim/state/particle_fields.hpp"

namespace ejecta::fields {

constexpr std::string_view kDimensionless = "1";  // units of a fraction

GridRequest GridRequest::fromScene(const FieldsOutputOptions& f) {
  GridRequest r;
  r.grids = f.grids;
  r.voxel = f.voxel;
  r.normalise = f.normalise;
  r.extrude = f.extrude;
  r.clip = f.clip;
  r.regionMin = f.regionMin;
  r.regionMax = f.regionMax;
  return r;
}

ParticleContext ParticleContext::fromScene(const Scene& scene) {
  ParticleContext c;
  c.geometry = scene.geometry;
  c.kernel = scene.sph.kernel;
  for (const MaterialSpec& m : scene.materials) c.materialNames.push_back(m.name);
  return c;
}

float GridSet::value(std::size_t g, std::size_t b, int v) const {
  const GridSpec& s = grids[g];
  const float x = lattice.data(b, s.channel)[v];
  const float w = lattice.data(b, 0)[v];
  if (s.shepard) return w > 0.0f ? x / w : 0.0f;
  if (s.fraction && w > 1.0f) return x / w;
  return x;
}

double medianSmoothingLength(const ParticleSet& p) {
  if (p.numReal == 0) throw std::invalid_argument("fields: the particle set is empty");
  std::vector<double> h(p.h.begin(), p.h.begin() + static_cast<long>(p.numReal));
  std::nth_element(h.begin(), h.begin() + static_cast<long>(h.size() / 2), h.end());
  return h[h.size() / 2];
}

std::vector<std::string> expandGridNames(const std::vector<std::string>& grids,
                                         const std::vector<std::string>& materialNames) {
  std::vector<std::string> out;
  auto add = [&](const std::string& n) {
    if (std::find(out.begin(), out.end(), n) == out.end()) out.push_back(n);
  };
  for (const std::string& g : grids) {
    if (g == "fractions") {
      for (const std::string& m : materialNames) add("fraction_" + m);
      continue;
    }
    if (g.rfind("fraction_", 0) == 0) {
      const std::string m = g.substr(9);
      if (std::find(materialNames.begin(), materialNames.end(), m) == materialNames.end())
        throw std::invalid_argument("fields: grid '" + g + "': no material named '" + m + "'");
      add(g);
      continue;
    }
    if (!findParticleScalarField(g))
      throw std::invalid_argument("fields: unknown grid '" + g + "'; known: " +
                                  particleScalarFieldList() + ", 'fractions', 'fraction_<material>'");
    add(g);
  }
  return out;
}

namespace {

// V_j of fields/splat.hpp: volume, area per metre depth (planar) or ring area (RZ).
std::vector<double> particleVolumes(const ParticleSet& p, Geometry g) {
  std::vector<double> v(p.numReal);
  for (std::size_t i = 0; i < p.numReal; ++i) {
    double denom = p.rho[i];
    if (g == Geometry::Axisymmetric) denom *= 2.0 * std::numbers::pi * std::max(p.x[0][i], 1e-300);
    v[i] = p.mass[i] / denom;
  }
  return v;
}

std::optional<VoxelBox> voxelBox(const GridRequest& r, double voxel) {
  if (!r.clip) return std::nullopt;
  VoxelBox b;
  for (int d = 0; d < 3; ++d) {
    b.lo[d] = static_cast<int>(std::ceil(r.regionMin[d] / voxel));
    b.hi[d] = static_cast<int>(std::floor(r.regionMax[d] / voxel));
  }
  return b;
}

}  // namespace

SparseLattice splatParticles(const ParticleSet& p, const ParticleContext& ctx,
                             const std::vector<std::vector<double>>& values, double voxel,
                             const std::optional<VoxelBox>& clip) {
  if (ctx.geometry == Geometry::Line)
    throw std::invalid_argument("fields: 1D runs have no grids; their snapshots are the profiles");
  if (p.numReal == 0) throw std::invalid_argument("fields: the particle set is empty");
  const std::vector<double> volume = particleVolumes(p, ctx.geometry);
  SplatSource src;
  src.dims = spatialDimension(ctx.geometry);
  src.kernel = ctx.kernel;
  src.count = p.numReal;
  src.x = {p.x[0].data(), p.x[1].data(), p.x[2].data()};
  src.h = p.h.data();
  src.volume = volume.data();
  src.mirrorAxis = ctx.geometry == Geometry::Axisymmetric;
  std::vector<const double*> ptrs;
  for (const std::vector<double>& v : values) ptrs.push_back(v.data());
  return splat(src, ptrs, voxel, clip);
}

GridSet buildGridSet(const ParticleSet& p, const ParticleContext& ctx, const GridRequest& request,
                     const Communicator* ranks) {
  const double voxel = request.voxel > 0.0 ? request.voxel
                       : ranks               ? medianSmoothingLength(p, *ranks)
                                             : medianSmoothingLength(p);
  const std::vector<std::string> names = expandGridNames(request.grids, ctx.materialNames);
  GridSet set;
  set.source = ctx.geometry;
  set.materials = ctx.materialNames;
  set.particles = ranks ? ranks->sum(p.numReal) : p.numReal;

  std::vector<std::vector<double>> values;
  for (const std::string& name : names) {
    GridSpec spec;
    spec.name = name;
    spec.channel = static_cast<int>(values.size()) + 1;
    const bool fraction = name.rfind("fraction_", 0) == 0;
    if (fraction) {
      const std::string m = name.substr(9);
      const int mat = static_cast<int>(
          std::find(ctx.materialNames.begin(), ctx.materialNames.end(), m) - ctx.materialNames.begin());
      std::vector<double> indicator(p.numReal);
      for (std::size_t i = 0; i < p.numReal; ++i) indicator[i] = p.material[i] == mat ? 1.0 : 0.0;
      values.push_back(std::move(indicator));
      spec.units = std::string(kDimensionless);
      spec.shepard = request.normalise == FieldNormalisation::Shepard;
      spec.fraction = true;
    } else {
      values.push_back(particleScalarField(p, name));
      spec.units = std::string(findParticleScalarField(name)->units);
      spec.shepard = request.normalise == FieldNormalisation::Shepard ||
                     (request.normalise == FieldNormalisation::Auto && name != "density");
    }
    set.grids.push_back(spec);
  }

  if (!(voxel > 0.0) || !std::isfinite(voxel))
    throw std::invalid_argument("fields: the voxel size is " + std::to_string(voxel) + " m; it must be positive");
  requireGridMemory(p, ctx, request, voxel, set.grids.size());
  const std::optional<VoxelBox> clip3 = voxelBox(request, voxel);
  // Every rank's particles, summed at rank 0 of a distributed run (fields/lattice_merge.hpp),
  // which alone goes on to the 3D grids.
  auto splat = [&](const std::optional<VoxelBox>& clip) {
    return ranks ? splatEveryRank(p, ctx, values, voxel, clip, *ranks)
                 : splatParticles(p, ctx, values, voxel, clip);
  };
  const bool merged = !ranks || ranks->isRoot();
  switch (ctx.geometry) {
    case Geometry::Spatial:
      set.lattice = splat(clip3);
      break;
    case Geometry::Planar: {
      std::optional<VoxelBox> clip2 = clip3;
      if (clip2) clip2->lo[2] = clip2->hi[2] = 0;
      const SparseLattice plane = splat(clip2);
      if (!merged) break;
      const int layers = request.extrude > 0.0
                             ? std::max(1, static_cast<int>(std::lround(request.extrude / voxel)))
                             : 1;
      set.lattice = extrudeSlab(plane, layers, clip3);
      break;
    }
    case Geometry::Axisymmetric: {
      // Clip the (r, z) splat to the radii and heights the 3D region can reach.
      std::optional<VoxelBox> clip2;
      if (clip3) {
        VoxelBox b;
        const double rmax = std::hypot(std::max(std::abs(request.regionMin[0]), std::abs(request.regionMax[0])),
                                       std::max(std::abs(request.regionMin[2]), std::abs(request.regionMax[2])));
        b.lo = {-2, clip3->lo[1] - 1, 0};
        b.hi = {static_cast<int>(std::ceil(rmax / voxel)) + 1, clip3->hi[1] + 1, 0};
        clip2 = b;
      }
      const SparseLattice rz = splat(clip2);
      if (!merged) break;
      set.lattice = revolveAboutAxis(rz, clip3);
      break;
    }
    case Geometry::Line:
      throw std::invalid_argument("fields: 1D runs have no grids; their snapshots are the profiles");
  }
  return set;
}

}  // namespace ejecta::fields
