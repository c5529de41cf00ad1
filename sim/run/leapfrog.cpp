#include "sim/run/leapfrog.hpp"

#include <algorithm>
#include <stdexcept>

#include "sim/solid/fracture.hpp"

namespace ejecta {

namespace {

// The components the integrator advances: a spatial vector's first `dimension` only.
int evolvedComponents(const Field& f, int dimension) {
  return f.spec.spatial ? std::min(dimension, f.spec.components) : f.spec.components;
}

// The Kicked field that drifts the positions (the Drifted fields' FieldSpec::rate).
std::string driftingField(const ParticleSet& p) {
  std::string name;
  for (const Field& x : p.fields()) {
    if (x.spec.evolution != Evolution::Drifted) continue;
    const Field* v = p.field(x.spec.rate);
    if (!v || v->spec.evolution != Evolution::Kicked || v->spec.components > 3)
      throw std::logic_error("field '" + x.spec.name + "' drifts by '" + x.spec.rate +
                             "', which is not a kicked vector the particles carry");
    if (!name.empty() && name != x.spec.rate)
      throw std::logic_error("the drifted fields drift by different fields ('" + name + "', '" +
                             x.spec.rate + "')");
    name = x.spec.rate;
  }
  return name;
}

}  // namespace

std::vector<double>& Leapfrog::halfOf(const Field& f, int component) {
  if (f.spec.name == drifting_) return velocityHalf_[static_cast<std::size_t>(component)];
  std::vector<std::vector<double>>& halves = halves_[f.spec.name];
  if (halves.size() < static_cast<std::size_t>(f.spec.components))
    halves.resize(static_cast<std::size_t>(f.spec.components));
  return halves[static_cast<std::size_t>(component)];
}

void Leapfrog::kick(ParticleSet& p, const Field& f, int dimension, double half, bool predict) {
  const Field* rateField = p.field(f.spec.rate);
  if (!rateField)
    throw std::logic_error("field '" + f.spec.name + "' is kicked by '" + f.spec.rate +
                           "', which the particles do not carry");
  const std::size_t n = p.numReal;
  const KickLimit limit = f.spec.limit;
  const double lo = f.spec.lo, hi = f.spec.hi;
  std::vector<double> caps;
  if (limit == KickLimit::Cap) {
    const auto source = caps_.find(f.spec.name);
    if (source == caps_.end())
      throw std::logic_error("field '" + f.spec.name + "' is Cap-limited but has no cap source");
    caps = source->second(p);
  }
  for (int c = 0; c < evolvedComponents(f, dimension); ++c) {
    std::vector<double>& y = p.column(f, c);
    const std::vector<double>& rate = p.column(*rateField, c);
    std::vector<double>& yHalf = halfOf(f, c);
    if (predict) yHalf.resize(n);
    double* yp = y.data();
    double* hp = yHalf.data();
    const double* rp = rate.data();
    switch (limit) {
      case KickLimit::None:
#pragma omp parallel for schedule(static)
        for (std::size_t i = 0; i < n; ++i) {
          if (predict) hp[i] = yp[i] + half * rp[i];
          yp[i] = hp[i] + half * rp[i];
        }
        break;
      case KickLimit::Clamp:
#pragma omp parallel for schedule(static)
        for (std::size_t i = 0; i < n; ++i) {
          if (predict) hp[i] = std::clamp(yp[i] + half * rp[i], lo, hi);
          yp[i] = std::clamp(hp[i] + half * rp[i], lo, hi);
        }
        break;
      case KickLimit::Cap:  // bounded by the cap, which an explicit update could overshoot
#pragma omp parallel for schedule(static)
        for (std::size_t i = 0; i < n; ++i) {
          if (predict) hp[i] = advanceCrack(yp[i], rp[i], half, caps[i]);
          yp[i] = advanceCrack(hp[i], rp[i], half, caps[i]);
        }
        break;
    }
  }
}

void Leapfrog::predict(ParticleSet& p, int dimension, double dt) {
  const double half = 0.5 * dt;
  drifting_ = driftingField(p);
  for (const Field& f : p.fields()) {
    if (f.spec.evolution != Evolution::Kicked || held_.count(f.spec.name)) continue;
    kick(p, f, dimension, half, true);
    // Positions drift by the half-step velocity as soon as it is known.
    if (f.spec.name == drifting_)
      for (const Field& x : p.fields())
        if (x.spec.evolution == Evolution::Drifted) drift(p, x, dimension, dt);
  }
}

void Leapfrog::drift(ParticleSet& p, const Field& f, int dimension, double dt) {
  const std::size_t n = p.numReal;
  for (int c = 0; c < evolvedComponents(f, dimension); ++c) {
    double* x = p.column(f, c).data();
    const double* vHalf = velocityHalf_[static_cast<std::size_t>(c)].data();
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) x[i] += dt * vHalf[i];
  }
}

void Leapfrog::correct(ParticleSet& p, int dimension, double dt) {
  for (const Field& f : p.fields())
    if (f.spec.evolution == Evolution::Kicked && !held_.count(f.spec.name))
      kick(p, f, dimension, 0.5 * dt, false);
}

}  // namespace ejecta
