#include "sim/io/particle_difference.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace ejecta {

namespace {

// Indices of p's real particles in id order.
std::vector<std::size_t> byId(const ParticleSet& p) {
  std::vector<std::size_t> order(p.numReal);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return p.id[x] < p.id[y]; });
  return order;
}

}  // namespace

std::vector<FieldDifference> particleDifferences(const ParticleSet& a, const ParticleSet& b) {
  const std::vector<std::size_t> ia = byId(a), ib = byId(b);
  for (std::size_t k = 0; k < std::max(ia.size(), ib.size()); ++k) {
    const bool inA = k < ia.size(), inB = k < ib.size();
    if (inA && inB && a.id[ia[k]] == b.id[ib[k]]) continue;
    const std::int64_t id = !inB || (inA && a.id[ia[k]] < b.id[ib[k]]) ? a.id[ia[k]] : b.id[ib[k]];
    throw std::invalid_argument("the particle sets differ: particle id " + std::to_string(id) +
                                " is in one of them only (" + std::to_string(a.numReal) + " and " +
                                std::to_string(b.numReal) + " particles)");
  }
  std::vector<FieldDifference> out;
  for (const Field& f : a.fields()) {
    if (f.storage.kind == FieldStorage::Kind::Derived || f.spec.output == FieldOutput::None) continue;
    const Field* g = b.field(f.spec.name);
    if (!g || g->storage.kind != f.storage.kind) continue;
    if (f.storage.kind == FieldStorage::Kind::Int32 || f.storage.kind == FieldStorage::Kind::Int64) {
      double diff = 0.0;
      for (std::size_t k = 0; k < ia.size(); ++k) {
        const bool same = f.storage.kind == FieldStorage::Kind::Int32
                              ? (a.*f.storage.int32)[ia[k]] == (b.*g->storage.int32)[ib[k]]
                              : (a.*f.storage.int64)[ia[k]] == (b.*g->storage.int64)[ib[k]];
        if (!same) diff = 1.0;
      }
      out.push_back({f.spec.name, diff, diff});
      continue;
    }
    for (int c = 0; c < std::min(f.spec.components, g->spec.components); ++c) {
      const std::vector<double>& x = a.column(f, c);
      const std::vector<double>& y = b.column(*g, c);
      double scale = 0.0, diff = 0.0;
      for (std::size_t k = 0; k < ia.size(); ++k) {
        const double u = x[ia[k]], v = y[ib[k]];
        if (std::isinf(u) && u == v) continue;
        scale = std::max(scale, std::abs(u));
        // NaN in either compares as a difference that no tolerance passes.
        diff = std::isnan(u) || std::isnan(v) ? INFINITY : std::max(diff, std::abs(u - v));
      }
      const std::string name = f.spec.components > 1 ? f.spec.name + "[" + std::to_string(c) + "]" : f.spec.name;
      out.push_back({name, scale > 0.0 ? diff / scale : diff, diff});
    }
  }
  return out;
}

FieldDifference largestDifference(const std::vector<FieldDifference>& differences) {
  FieldDifference worst;
  for (const FieldDifference& d : differences)
    if (d.relative > worst.relative || (worst.field.empty() && d.relative >= worst.relative)) worst = d;
  return worst;
}

}  // namespace ejecta
