#include "fields/fragments.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numeric>
#include <limits>
#include <stdexcept>

#include "core/csv.hpp"
#include "sim/sph/cell_grid.hpp"

namespace ejecta::fields {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Union-find over particle indices that several threads may join at once. A root is only ever
// hooked under a smaller index, so no cycle can form and each component's final root is its
// smallest index; the components themselves do not depend on the order of the joins.
class ConcurrentDisjointSets {
 public:
  explicit ConcurrentDisjointSets(std::size_t n) : parent_(n) {
    for (std::size_t i = 0; i < n; ++i) parent_[i].store(static_cast<std::uint32_t>(i), std::memory_order_relaxed);
  }
  std::uint32_t find(std::uint32_t x) {
    for (;;) {
      std::uint32_t p = parent_[x].load(std::memory_order_acquire);
      if (p == x) return x;
      const std::uint32_t gp = parent_[p].load(std::memory_order_acquire);
      // Path halving; a failed exchange only means another thread shortened it first.
      if (gp != p) parent_[x].compare_exchange_weak(p, gp, std::memory_order_acq_rel);
      x = gp;
    }
  }
  void join(std::uint32_t a, std::uint32_t b) {
    for (;;) {
      a = find(a);
      b = find(b);
      if (a == b) return;
      if (a < b) std::swap(a, b);  // hook the larger root under the smaller
      std::uint32_t expected = a;
      if (parent_[a].compare_exchange_strong(expected, b, std::memory_order_acq_rel)) return;
    }
  }

 private:
  std::vector<std::atomic<std::uint32_t>> parent_;
};

bool hasFailed(const ParticleSet& p, std::size_t i, double threshold) {
  return p.hasFracture() && p.damage(i) >= threshold;
}

// Each pair is examined once, from the particle with the larger h (ties: the smaller index):
// a query of radius linkFactor h_i from it reaches every friend, since the link length
// linkFactor (h_i + h_j) / 2 is at most that. A few particles with wide kernels (a burst's
// vapour) then widen only their own queries.
template <int D>
void linkFriends(const ParticleSet& p, const FragmentOptions& o, ConcurrentDisjointSets& sets) {
  const std::size_t n = p.numReal;
  if (n == 0) return;
  std::vector<double> sortedH(p.h.begin(), p.h.begin() + static_cast<std::ptrdiff_t>(n));
  std::nth_element(sortedH.begin(), sortedH.begin() + static_cast<std::ptrdiff_t>(n / 2), sortedH.end());
  CellGrid grid;
  grid.build(p, D, o.linkFactor * sortedH[n / 2]);
#pragma omp parallel
  {
    std::vector<std::uint32_t> near;
#pragma omp for schedule(dynamic, 256)
    for (std::size_t i = 0; i < n; ++i) {
      if (hasFailed(p, i, o.damageThreshold)) continue;
      const double hi = p.h[i];
      const double xi[3] = {p.x[0][i], D > 1 ? p.x[1][i] : 0.0, D > 2 ? p.x[2][i] : 0.0};
      near.clear();
      grid.query<D>(p, xi, o.linkFactor * hi, near);
      for (const std::uint32_t j : near) {
        if (j >= n || j == i) continue;
        const double hj = p.h[j];
        if (hj > hi || (hj == hi && j < i) || hasFailed(p, j, o.damageThreshold)) continue;
        double r2 = 0.0;
        for (int d = 0; d < D; ++d) {
          const double dx = p.x[d][j] - xi[d];
          r2 += dx * dx;
        }
        const double link = 0.5 * o.linkFactor * (hi + hj);
        if (r2 < link * link) sets.join(static_cast<std::uint32_t>(i), j);
      }
    }
  }
}

// A fragment's running sums, in particle order.
struct Accumulator {
  std::size_t particles = 0;
  std::int64_t firstId = 0;
  double mass = 0.0, volume = 0.0, section = 0.0, kinetic = 0.0, damageMass = 0.0;
  double minRadius = 0.0;
  std::array<double, 3> moment{}, momentum{};
  std::vector<std::pair<int, double>> materialMass;  // few materials: a short list
};

}  // namespace

std::size_t FragmentCensus::resolvedCount() const {
  return static_cast<std::size_t>(std::count_if(fragments.begin(), fragments.end(),
                                                [](const Fragment& f) { return f.resolved; }));
}

std::size_t FragmentCensus::failedCount() const {
  return static_cast<std::size_t>(std::count_if(fragments.begin(), fragments.end(),
                                                [](const Fragment& f) { return f.failed; }));
}

FragmentCensus identifyFragments(const ParticleSet& p, Geometry geometry, const FragmentOptions& o) {
  if (geometry == Geometry::Line)
    throw std::invalid_argument("fragments: a 1D run has no fragments to find (slabs only)");
  if (!(o.linkFactor > 0.0) || !std::isfinite(o.linkFactor))
    throw std::invalid_argument("fragments: the link factor must be positive");
  if (!(o.resolvedSpacings > 0.0) || !std::isfinite(o.resolvedSpacings))
    throw std::invalid_argument("fragments: the resolved size must be a positive number of spacings");
  const std::size_t n = p.numReal;
  if (n >= std::numeric_limits<std::uint32_t>::max())
    throw std::invalid_argument("fragments: more than 2^32 particles");
  for (std::size_t i = 0; i < n; ++i)
    if (!(p.h[i] > 0.0) || !std::isfinite(p.h[i]) || !(p.rho[i] > 0.0))
      throw std::invalid_argument("fragments: particle id " + std::to_string(p.id[i]) +
                                  " has a non-positive smoothing length or density");

  ConcurrentDisjointSets sets(n);
  if (spatialDimension(geometry) == 3) linkFriends<3>(p, o, sets);
  else linkFriends<2>(p, o, sets);

  const bool rz = geometry == Geometry::Axisymmetric;
  const int dim = spatialDimension(geometry);
  FragmentCensus census;
  census.geometry = geometry;
  census.fragmentOf.assign(n, 0);
  std::vector<std::uint32_t> root(n);
  std::vector<std::uint32_t> slot(n, std::numeric_limits<std::uint32_t>::max());
  std::vector<Accumulator> acc;
  for (std::size_t i = 0; i < n; ++i) {
    root[i] = sets.find(static_cast<std::uint32_t>(i));
    std::uint32_t& s = slot[root[i]];
    if (s == std::numeric_limits<std::uint32_t>::max()) {
      s = static_cast<std::uint32_t>(acc.size());
      acc.emplace_back();
      acc.back().firstId = p.id[i];
      acc.back().minRadius = std::numeric_limits<double>::infinity();
    }
    Accumulator& a = acc[s];
    census.fragmentOf[i] = s;
    const double m = p.mass[i];
    a.particles += 1;
    a.firstId = std::min(a.firstId, p.id[i]);
    a.mass += m;
    a.volume += m / p.rho[i];
    if (rz) a.section += m / (2.0 * kPi * std::max(p.x[0][i], 0.0) * p.rho[i]);
    double v2 = 0.0;
    for (int d = 0; d < dim; ++d) {
      a.moment[d] += m * p.x[d][i];
      a.momentum[d] += m * p.v[d][i];
      v2 += p.v[d][i] * p.v[d][i];
    }
    a.kinetic += 0.5 * m * v2;
    a.damageMass += m * (p.hasFracture() ? p.damage(i) : 0.0);
    if (rz) a.minRadius = std::min(a.minRadius, p.x[0][i]);
    auto it = std::find_if(a.materialMass.begin(), a.materialMass.end(),
                           [&](const auto& e) { return e.first == p.material[i]; });
    if (it == a.materialMass.end()) a.materialMass.emplace_back(p.material[i], m);
    else it->second += m;
    census.totalMass += m;
    for (int d = 0; d < dim; ++d) census.totalMomentum[d] += m * p.v[d][i];
  }

  census.fragments.reserve(acc.size());
  for (const Accumulator& a : acc) {
    Fragment f;
    f.particles = a.particles;
    f.firstId = a.firstId;
    f.mass = a.mass;
    f.volume = a.volume;
    for (int d = 0; d < dim; ++d) {
      f.center[d] = a.moment[d] / a.mass;
      f.velocity[d] = a.momentum[d] / a.mass;
      f.speed += f.velocity[d] * f.velocity[d];
    }
    f.speed = std::sqrt(f.speed);
    f.kineticEnergy = a.kinetic;
    f.meanDamage = a.damageMass / a.mass;
    f.material = std::max_element(a.materialMass.begin(), a.materialMass.end(),
                                  [](const auto& x, const auto& y) { return x.second < y.second; })
                     ->first;
    const double count = static_cast<double>(a.particles);
    if (geometry == Geometry::Spatial) {
      f.diameter = std::cbrt(6.0 * a.volume / kPi);
      f.spacing = std::cbrt(a.volume / count);
    } else {
      f.section = rz ? a.section : a.volume;
      f.spacing = std::sqrt(f.section / count);
      // An RZ body reaching the axis (its innermost ring within a spacing of it) is sized as a
      // body of revolution; a ring and a planar rod by their cross-section.
      f.ring = rz && a.minRadius >= f.spacing;
      f.diameter = rz && !f.ring ? std::cbrt(6.0 * a.volume / kPi) : std::sqrt(4.0 * f.section / kPi);
    }
    f.failed = a.particles == 1 && p.hasFracture() && f.meanDamage >= o.damageThreshold;
    f.resolved = f.diameter >= o.resolvedSpacings * f.spacing;
    census.fragments.push_back(f);
  }

  // Largest first; the smallest particle id breaks ties, so the order is the same on any run.
  std::vector<std::uint32_t> order(census.fragments.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    const Fragment& x = census.fragments[a];
    const Fragment& y = census.fragments[b];
    return x.mass != y.mass ? x.mass > y.mass : x.firstId < y.firstId;
  });
  std::vector<std::uint32_t> rank(order.size());
  std::vector<Fragment> sorted;
  sorted.reserve(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    rank[order[k]] = static_cast<std::uint32_t>(k);
    sorted.push_back(census.fragments[order[k]]);
  }
  census.fragments = std::move(sorted);
  for (std::uint32_t& f : census.fragmentOf) f = rank[f];
  return census;
}

std::string fragmentsCsv(const FragmentCensus& c, const std::vector<std::string>& materialNames) {
  CsvWriter csv({"index", "particles", "first_id", "material", "mass_kg", "volume_m3", "diameter_m",
                 "spacing_m", "center_x_m", "center_y_m", "center_z_m", "velocity_x_m_s",
                 "velocity_y_m_s", "velocity_z_m_s", "speed_m_s", "kinetic_energy_J", "mean_damage",
                 "failed", "ring", "resolved"});
  for (std::size_t k = 0; k < c.fragments.size(); ++k) {
    const Fragment& f = c.fragments[k];
    const bool named = f.material >= 0 && static_cast<std::size_t>(f.material) < materialNames.size();
    csv.count(k).count(f.particles).integer(f.firstId);
    if (named) csv.text(materialNames[static_cast<std::size_t>(f.material)]);
    else csv.integer(f.material);
    csv.number(f.mass).number(f.volume).number(f.diameter).number(f.spacing);
    for (double x : f.center) csv.number(x);
    for (double v : f.velocity) csv.number(v);
    csv.number(f.speed).number(f.kineticEnergy).number(f.meanDamage).flag(f.failed).flag(f.ring)
        .flag(f.resolved).endRow();
  }
  return csv.str();
}

std::vector<SizeFrequencyRow> sizeFrequency(const FragmentCensus& c) {
  std::vector<const Fragment*> order;
  for (const Fragment& f : c.fragments) order.push_back(&f);
  std::stable_sort(order.begin(), order.end(),
                   [](const Fragment* a, const Fragment* b) { return a->diameter > b->diameter; });
  std::vector<SizeFrequencyRow> rows;
  SizeFrequencyRow sum;
  for (std::size_t k = 0; k < order.size(); ++k) {
    sum.countAtLeast += 1;
    sum.massAtLeast += order[k]->mass;
    if (order[k]->resolved) sum.measuredCountAtLeast += 1, sum.measuredMassAtLeast += order[k]->mass;
    // One row per distinct diameter, after every fragment of that size is counted.
    if (k + 1 == order.size() || order[k + 1]->diameter != order[k]->diameter) {
      sum.diameter = order[k]->diameter;
      rows.push_back(sum);
    }
  }
  return rows;
}

}  // namespace ejecta::fields
