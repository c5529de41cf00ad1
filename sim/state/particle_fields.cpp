#include "sim/state/particle_fields.hpp"

#include <stdexcept>

#include "sim/state/builtin_fields.hpp"

namespace ejecta {

namespace {

// The built-in fields grids may name, with the declaration each comes from.
const std::vector<const Field*>& griddedFields() {
  static const std::vector<const Field*> fields = [] {
    std::vector<const Field*> out;
    for (const Field& f : allBuiltinFields())
      if (f.spec.grid) out.push_back(&f);
    return out;
  }();
  return fields;
}

}  // namespace

const std::vector<ParticleFieldInfo>& particleScalarFields() {
  static const std::vector<ParticleFieldInfo> fields = [] {
    std::vector<ParticleFieldInfo> out;
    for (const Field* f : griddedFields()) out.push_back({f->spec.name, f->spec.units, f->spec.description});
    return out;
  }();
  return fields;
}

const ParticleFieldInfo* findParticleScalarField(std::string_view name) {
  for (const ParticleFieldInfo& f : particleScalarFields())
    if (f.name == name) return &f;
  return nullptr;
}

std::string particleScalarFieldList() {
  std::string out;
  for (const ParticleFieldInfo& f : particleScalarFields())
    out += (out.empty() ? "'" : ", '") + std::string(f.name) + "'";
  return out;
}

std::vector<double> particleScalarField(const ParticleSet& p, std::string_view name) {
  const std::size_t n = p.numReal;
  const Field* declared = nullptr;
  for (const Field* f : griddedFields())
    if (f->spec.name == name) declared = f;
  if (!declared)
    throw std::invalid_argument("unknown particle field '" + std::string(name) +
                                "' (known: " + particleScalarFieldList() + ")");
  const Field* carried = p.field(name);
  if (!carried) return std::vector<double>(n, declared->spec.absent);
  std::vector<double> out(n);
  if (carried->spec.derive) {
    for (std::size_t i = 0; i < n; ++i) out[i] = carried->spec.derive(p, i);
    return out;
  }
  const std::vector<double>& values = p.column(*carried, 0);
  if (values.size() < n) return std::vector<double>(n, 0.0);
  std::copy(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(n), out.begin());
  return out;
}

}  // namespace ejecta
