#include "sim/state/conservation.hpp"

namespace ejecta {

namespace {

// Adds particle i to the totals.
inline void accumulate(ConservedTotals& t, const ParticleSet& p, std::size_t i) {
  const double m = p.mass[i];
  double v2 = 0.0;
  for (int d = 0; d < 3; ++d) {
    v2 += p.v[d][i] * p.v[d][i];
    t.momentum[d] += m * p.v[d][i];
  }
  t.kinetic += 0.5 * m * v2;
  t.internal += m * p.u[i];
  t.mass += m;
}

}  // namespace

ConservedTotals conservedTotals(const ParticleSet& p) {
  ConservedTotals t;
  for (std::size_t i = 0; i < p.numReal; ++i) accumulate(t, p, i);
  return t;
}

std::vector<ConservedTotals> conservedTotalsByMaterial(const ParticleSet& p, std::size_t materials) {
  std::vector<ConservedTotals> out(materials);
  for (std::size_t i = 0; i < p.numReal; ++i) {
    const std::size_t k = static_cast<std::size_t>(p.material[i]);
    if (k < materials) accumulate(out[k], p, i);
  }
  return out;
}

}  // namespace ejecta
