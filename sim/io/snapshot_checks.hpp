#pragma once
// What a snapshot must satisfy before anything uses it (docs/robustness.md): a restart, a grid,
// an image or a thermal study from a damaged or hand-edited file refuses it with the dataset,
// the row and the reason instead of hanging in the neighbour search or running on NaNs.
#include <cstddef>
#include <string>

#include "sim/io/snapshot.hpp"

namespace ejecta {

// The run-level values: a finite, non-negative time and step; finite restart state.
// Throws std::runtime_error naming the attribute.
void checkSnapshotInfo(const SnapshotInfo& info);

// The particles read from rows [firstRow, firstRow + p.numReal) of the file: no NaN in any
// stored array, finite values in /particles, positive mass, density and smoothing length,
// non-negative material indices. Throws std::runtime_error naming the dataset, the row, the
// particle's id and the reason.
void checkSnapshotParticles(const ParticleSet& p, std::size_t firstRow);

// Material indices below the run's material count (the count comes from the stored scene, which
// the reader does not parse). Throws std::runtime_error naming `path` and the first bad row.
void checkSnapshotMaterials(const ParticleSet& p, std::size_t materialCount, const std::string& path);

}  // namespace ejecta
