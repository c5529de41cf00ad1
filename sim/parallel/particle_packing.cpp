#include "sim/parallel/particle_packing.hpp"

#include <cstring>
#include <stdexcept>

namespace ejecta {

namespace {

std::size_t fieldBytes(const Field& f) {
  switch (f.storage.kind) {
    case FieldStorage::Kind::Int32: return sizeof(int);
    case FieldStorage::Kind::Int64: return sizeof(std::int64_t);
    default: return sizeof(double) * static_cast<std::size_t>(f.spec.components);
  }
}

}  // namespace

ParticlePacker::ParticlePacker(const ParticleSet& p, PackedFields which) {
  for (const Field& f : p.fields()) {
    if (f.storage.kind == FieldStorage::Kind::Derived) continue;
    if (which != PackedFields::All && !f.spec.halo && f.spec.name != "position") continue;
    if (which == PackedFields::HaloValues && f.spec.name == "position") continue;
    fields_.push_back(&f);
    recordBytes_ += fieldBytes(f);
  }
}

void ParticlePacker::pack(const ParticleSet& p, std::span<const std::size_t> indices, Bytes& out) const {
  const std::size_t start = out.size();
  out.resize(start + indices.size() * recordBytes_);
  std::byte* base = out.data() + start;
  std::size_t offset = 0;  // of the field within a record
  for (const Field* f : fields_) {
    const FieldStorage& s = f->storage;
    for (std::size_t k = 0; k < indices.size(); ++k) {
      std::byte* at = base + k * recordBytes_ + offset;
      const std::size_t i = indices[k];
      if (s.kind == FieldStorage::Kind::Int32) std::memcpy(at, &(p.*s.int32)[i], sizeof(int));
      else if (s.kind == FieldStorage::Kind::Int64) std::memcpy(at, &(p.*s.int64)[i], sizeof(std::int64_t));
      else
        for (int c = 0; c < f->spec.components; ++c)
          std::memcpy(at + c * sizeof(double), &p.column(*f, c)[i], sizeof(double));
    }
    offset += fieldBytes(*f);
  }
}

void ParticlePacker::unpack(ParticleSet& p, const Bytes& in, std::size_t first) const {
  if (recordBytes_ == 0) return;
  if (in.size() % recordBytes_ != 0)
    throw std::logic_error("a particle message of " + std::to_string(in.size()) +
                           " bytes is not whole records of " + std::to_string(recordBytes_));
  const std::size_t n = in.size() / recordBytes_;
  if (first + n > p.size()) throw std::logic_error("unpacking particles past the end of the set");
  std::size_t offset = 0;
  for (const Field* f : fields_) {
    const FieldStorage& s = f->storage;
    for (std::size_t k = 0; k < n; ++k) {
      const std::byte* at = in.data() + k * recordBytes_ + offset;
      const std::size_t i = first + k;
      if (s.kind == FieldStorage::Kind::Int32) std::memcpy(&(p.*s.int32)[i], at, sizeof(int));
      else if (s.kind == FieldStorage::Kind::Int64) std::memcpy(&(p.*s.int64)[i], at, sizeof(std::int64_t));
      else
        for (int c = 0; c < f->spec.components; ++c)
          std::memcpy(&p.column(*f, c)[i], at + c * sizeof(double), sizeof(double));
    }
    offset += fieldBytes(*f);
  }
}

}  // namespace ejecta
