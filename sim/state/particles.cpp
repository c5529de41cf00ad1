#include "sim/state/particles.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

#include "sim/parallel/thread_team.hpp"
#include "sim/state/builtin_fields.hpp"

namespace ejecta {

namespace {

template <typename T>
void permuteArray(std::vector<T>& data, const std::vector<std::size_t>& order) {
  std::vector<T> out(order.size());
  // Every column is permuted every 16 sub-steps of individual time steps.
  const std::size_t n = order.size();
#pragma omp parallel for schedule(static) if (n >= kThreadTeamFrom)
  for (std::size_t i = 0; i < n; ++i) out[i] = data[order[i]];
  data.swap(out);
}

}  // namespace

ParticleSet::ParticleSet() { addGroup(FieldGroup::Core); }

// Applies f(column, fill) to every stored column of every field this set carries.
template <typename F>
void ParticleSet::forEachColumn(F&& f) {
  for (const Field& field : fields_) {
    const FieldStorage& s = field.storage;
    const double fill = field.spec.fill;
    switch (s.kind) {
      case FieldStorage::Kind::Scalar: f(this->*s.scalar, fill); break;
      case FieldStorage::Kind::Vector:
        for (auto& c : this->*s.vector) f(c, fill);
        break;
      case FieldStorage::Kind::Stress:
        for (int c = 0; c < field.spec.components; ++c) f((this->*s.stress)[c], fill);
        break;
      case FieldStorage::Kind::Int32: f(this->*s.int32, 0); break;
      case FieldStorage::Kind::Int64: f(this->*s.int64, 0); break;
      case FieldStorage::Kind::Extra:
        for (int c = 0; c < field.spec.components; ++c) f(extra_[s.extra + c], fill);
        break;
      case FieldStorage::Kind::Derived: break;
    }
  }
}

void ParticleSet::addGroup(FieldGroup group) {
  if (std::find(fieldGroups_.begin(), fieldGroups_.end(), group) != fieldGroups_.end()) return;
  // Groups keep their registry rank whatever order they are enabled in (FieldGroup's order).
  std::size_t at = 0;
  while (at < fieldGroups_.size() && fieldGroups_[at] <= group) ++at;
  const std::vector<Field> added = builtinFields(group, stressComponents_ > 0 ? stressComponents_ : 6);
  fields_.insert(fields_.begin() + static_cast<std::ptrdiff_t>(at), added.begin(), added.end());
  fieldGroups_.insert(fieldGroups_.begin() + static_cast<std::ptrdiff_t>(at), added.size(), group);
}

const Field* ParticleSet::field(std::string_view name) const {
  for (const Field& f : fields_)
    if (f.spec.name == name) return &f;
  return nullptr;
}

std::vector<double>& ParticleSet::column(const Field& f, int c) {
  const FieldStorage& s = f.storage;
  switch (s.kind) {
    case FieldStorage::Kind::Scalar: return this->*s.scalar;
    case FieldStorage::Kind::Vector: return (this->*s.vector)[static_cast<std::size_t>(c)];
    case FieldStorage::Kind::Stress: return (this->*s.stress)[static_cast<std::size_t>(c)];
    case FieldStorage::Kind::Extra: return extra_[s.extra + static_cast<std::size_t>(c)];
    default: break;
  }
  throw std::logic_error("field '" + f.spec.name + "' has no floating-point column");
}

const std::vector<double>& ParticleSet::column(const Field& f, int c) const {
  return const_cast<ParticleSet*>(this)->column(f, c);
}

void ParticleSet::declare(const FieldSpec& spec) {
  for (std::size_t k = 0; k < fields_.size(); ++k) {
    Field& existing = fields_[k];
    if (existing.spec.name != spec.name) continue;
    if (existing.spec.components != spec.components || existing.spec.type != FieldType::Float64)
      throw std::invalid_argument("field '" + spec.name + "' is carried with " +
                                  std::to_string(existing.spec.components) +
                                  " components; its declaration has " +
                                  std::to_string(spec.components));
    existing.spec = spec;
    return;
  }
  if (spec.type != FieldType::Float64 || spec.derive != nullptr || spec.components < 1)
    throw std::invalid_argument("field '" + spec.name +
                                "': a package declares stored floating-point fields only");
  Field f{spec, {}};
  f.storage.kind = FieldStorage::Kind::Extra;
  f.storage.extra = extra_.size();
  for (int c = 0; c < spec.components; ++c) extra_.emplace_back(size(), spec.fill);
  fields_.push_back(std::move(f));
  fieldGroups_.push_back(FieldGroup::Package);
}

void ParticleSet::setClampRange(std::string_view name, double lo, double hi) {
  for (Field& f : fields_)
    if (f.spec.name == name) {
      f.spec.lo = lo;
      f.spec.hi = hi;
      return;
    }
  throw std::logic_error("setClampRange: no field '" + std::string(name) + "'");
}

ParticleSet ParticleSet::withSameFields() const {
  ParticleSet out;
  out.fields_ = fields_;
  out.fieldGroups_ = fieldGroups_;
  out.extra_.assign(extra_.size(), {});
  out.stressComponents_ = stressComponents_;
  out.fracture_ = fracture_;
  out.burn_ = burn_;
  out.viscositySwitch_ = viscositySwitch_;
  return out;
}

void ParticleSet::resize(std::size_t n) {
  forEachColumn([n](auto& arr, double fill) {
    using T = typename std::decay_t<decltype(arr)>::value_type;
    arr.resize(n, static_cast<T>(fill));
  });
}

void ParticleSet::enableStrength(int components) {
  stressComponents_ = components;
  addGroup(FieldGroup::Strength);
  const std::size_t n = size();
  for (int c = 0; c < components; ++c) {
    stress[c].assign(n, 0.0);
    dstress_dt[c].assign(n, 0.0);
  }
  plasticStrain.assign(n, 0.0);
  totalStrain.assign(n, 0.0);
  strainRate.assign(n, 0.0);
}

void ParticleSet::enableFracture() {
  fracture_ = true;
  addGroup(FieldGroup::Fracture);
  crack.assign(size(), 0.0);
  dcrack_dt.assign(size(), 0.0);
}

void ParticleSet::enableBurn() {
  burn_ = true;
  addGroup(FieldGroup::Burn);
  lightingTime.assign(size(), -std::numeric_limits<double>::infinity());
  burnFraction.assign(size(), 1.0);
}

void ParticleSet::enableViscositySwitch(double initial) {
  viscositySwitch_ = true;
  addGroup(FieldGroup::ViscositySwitch);
  alpha.assign(size(), initial);
  dalpha_dt.assign(size(), 0.0);
}

void ParticleSet::append(const std::array<double, 3>& pos, const std::array<double, 3>& vel,
                         double m, double density, double specificEnergy,
                         double smoothingLength, int mat) {
  const std::size_t i = size();
  resize(i + 1);
  for (int d = 0; d < 3; ++d) { x[d][i] = pos[d]; v[d][i] = vel[d]; }
  mass[i] = m;
  rho[i] = density;
  u[i] = specificEnergy;
  h[i] = smoothingLength;
  material[i] = mat;
  id[i] = static_cast<std::int64_t>(i);
  numReal = size();
}

void ParticleSet::clearGhosts() {
  forEachColumn([this](auto& arr, double) { arr.resize(numReal); });
  ghostSource.clear();
}

void ParticleSet::permute(const std::vector<std::size_t>& order) {
  clearGhosts();
  forEachColumn([&order](auto& arr, double) { permuteArray(arr, order); });
}

}  // namespace ejecta
