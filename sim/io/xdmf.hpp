#pragma once
// XDMF 3 index over a series of HDF5 snapshots, so ParaView (or VisIt) opens the whole run as
// one time-dependent data set. The XDMF file only points into the .h5 files; it holds no data.
#include <cstddef>
#include <string>
#include <vector>

#include "sim/state/geometry.hpp"
#include "sim/state/particles.hpp"

namespace ejecta {

// One per-particle dataset of /particles published to visualisation tools.
struct XdmfAttribute {
  std::string name;
  int components = 1;        // 1: Scalar, 3: Vector, 6: Tensor6, other: Matrix
  bool integer = false;
  int precision = 8;         // bytes
};

// The attributes of the fields `p` carries whose declaration lists them in the XDMF
// (FieldSpec::xdmf): the scalars, then the others, each in registry order.
std::vector<XdmfAttribute> xdmfAttributes(const ParticleSet& p);

struct XdmfEntry {
  std::string h5File;        // snapshot path relative to the directory of the .xdmf file
  double time = 0.0;         // simulation time of the snapshot [s]
  std::size_t numParticles = 0;
  Geometry geometry = Geometry::Spatial;
  std::vector<XdmfAttribute> attributes;
};

// Writes (atomically) one temporal collection of Polyvertex grids, one per entry, in the given
// order. Each grid has XYZ geometry from /particles/position and the entry's attributes.
// Throws std::runtime_error naming the file on failure.
void writeXdmfSeries(const std::string& xdmfPath, const std::vector<XdmfEntry>& entries);

}  // namespace ejecta
