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
  std::string units;         // SI ("1": dimensionless), written as an Information key
  int components = 1;        // 1: Scalar; 3: Vector (unless `tensor`); other: Matrix (N, k),
                             // its column names in an Information key
  bool tensor = false;       // a symmetric tensor (the deviatoric stress)
  bool integer = false;
  int precision = 8;         // bytes
};

// Every dataset a snapshot of `p` writes to /particles except the positions (the grid's
// geometry): the scalars, then the others, each in registry order.
std::vector<XdmfAttribute> xdmfAttributes(const ParticleSet& p);

// The names of a multi-component attribute's columns in `geometry`, as the XDMF's
// "components" Information key gives them ("xx", "rr", ...; vectors "x", "y", "z" or RZ's "r",
// "z", "phi").
std::vector<std::string> xdmfComponentNames(const XdmfAttribute& attribute, Geometry geometry);

// The bytes of each entry of a snapshot's /xdmf/vertices (the Polyvertex connectivity): 4 while
// the indices fit in 32 bits, 8 beyond.
inline int xdmfVertexPrecision(std::size_t numParticles) {
  return numParticles <= 2147483647u ? 4 : 8;
}

struct XdmfEntry {
  std::string h5File;        // snapshot path relative to the directory of the .xdmf file
  double time = 0.0;         // simulation time of the snapshot [s]
  std::size_t numParticles = 0;
  Geometry geometry = Geometry::Spatial;
  std::vector<XdmfAttribute> attributes;
  std::vector<std::string> materials;  // names by material id (the snapshot's /materials)
  bool vertices = true;      // the snapshot has /xdmf/vertices (older files do not)
};

// Writes (atomically) one temporal collection of Polyvertex grids, one per entry, in the given
// order. Each grid has its connectivity from /xdmf/vertices, XYZ geometry from
// /particles/position and the entry's attributes, each with its units as an Information key;
// the grid's Information keys give the geometry and the material names by id. Throws std::runtime_error naming the file on failure.
void writeXdmfSeries(const std::string& xdmfPath, const std::vector<XdmfEntry>& entries);

}  // namespace ejecta
