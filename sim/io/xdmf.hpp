#pragma once
// XDMF 3 index over a series of HDF5 snapshots, so ParaView (or VisIt) opens the whole run as
// one time-dependent data set. The XDMF file only points into the .h5 files; it holds no data.
#include <cstddef>
#include <string>
#include <vector>

#include "sim/state/geometry.hpp"

namespace ejecta {

struct XdmfEntry {
  std::string h5File;        // snapshot path relative to the directory of the .xdmf file
  double time = 0.0;         // simulation time of the snapshot [s]
  std::size_t numParticles = 0;
  Geometry geometry = Geometry::Spatial;
};

// Writes (atomically) one temporal collection of Polyvertex grids, one per entry, in the given
// order. Each grid has XYZ geometry from /particles/position, the scalar attributes density,
// pressure, internal_energy, smoothing_length, sound_speed, mass, material, id and the vector
// attribute velocity. Throws std::runtime_error naming the file on failure.
void writeXdmfSeries(const std::string& xdmfPath, const std::vector<XdmfEntry>& entries);

}  // namespace ejecta
