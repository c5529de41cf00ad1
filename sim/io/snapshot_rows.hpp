#pragma once
// The two halves of a snapshot write, for writers that fill one file from several places (a
// distributed run's ranks, sim/io/distributed_snapshot.cpp). Internal to sim/io/; errors are
// std::runtime_error with HDF5's reason, without the file's name (the caller adds it).
#include <cstddef>
#include <filesystem>

#include "sim/io/snapshot.hpp"

namespace ejecta {

// Creates `tempPath` (which must not exist) with the root and restart attributes of `info`,
// every dataset sized for `totalRows` particles, and p's real particles as rows [0, p.numReal).
void createSnapshotFile(const std::filesystem::path& tempPath, const ParticleSet& p,
                        const SnapshotInfo& info, std::size_t totalRows);

// Writes p's real particles as rows [first, first + p.numReal) of the file createSnapshotFile
// made (p carries the same fields as the set it was made from). Nothing to do for no particles.
void writeSnapshotRows(const std::filesystem::path& tempPath, const ParticleSet& p, Geometry geometry,
                       std::size_t first, std::size_t totalRows);

}  // namespace ejecta
