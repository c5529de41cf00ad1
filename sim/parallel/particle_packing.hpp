#pragma once
// Particles as bytes, through the field registry (sim/state/field_spec.hpp): a rank packs,
// sends and unpacks a particle without knowing the physics. Every rank of a run carries the
// same declarations in the same order (the scene assembles them), so a record is the values of
// the chosen fields one after another, in registry order, for each particle.
#include <cstddef>
#include <span>
#include <vector>

#include "sim/parallel/communicator.hpp"
#include "sim/state/particles.hpp"

namespace ejecta {

// Which fields a record carries.
enum class PackedFields {
  All,   // every stored field: a particle that moves to another rank (or to rank 0's output)
  Halo,  // the fields neighbours read (FieldSpec::halo, positions included): a halo copy
  HaloValues,  // Halo without positions: the refresh of a halo after a pass changed its values
};

class ParticlePacker {
 public:
  ParticlePacker(const ParticleSet& p, PackedFields which);
  std::size_t recordBytes() const { return recordBytes_; }
  // Appends the records of particles `indices` (any of real and ghost) to `out`.
  void pack(const ParticleSet& p, std::span<const std::size_t> indices, Bytes& out) const;
  // Writes the records in `in` to particles first, first + 1, ... (which must exist).
  void unpack(ParticleSet& p, const Bytes& in, std::size_t first) const;
  std::size_t count(const Bytes& in) const { return recordBytes_ ? in.size() / recordBytes_ : 0; }

 private:
  std::vector<const Field*> fields_;
  std::size_t recordBytes_ = 0;
};

}  // namespace ejecta
