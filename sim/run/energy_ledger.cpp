#include "sim/run/energy_ledger.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

namespace ejecta {

namespace {

bool moving(const BodySpec& b) {
  return b.velocity[0] != 0.0 || b.velocity[1] != 0.0 || b.velocity[2] != 0.0;
}

bool contains(const std::vector<int>& v, int x) { return std::find(v.begin(), v.end(), x) != v.end(); }

}  // namespace

LedgerGroups ledgerGroups(const Scene& scene) {
  LedgerGroups g;
  for (const DetonationSpec& d : scene.detonations)
    if (!contains(g.explosive, d.material)) g.explosive.push_back(d.material);
  for (const EnergyDepositSpec& e : scene.deposits) {
    if (e.body < 0) continue;
    const int m = scene.bodies[static_cast<std::size_t>(e.body)].material;
    if (!contains(g.explosive, m)) g.explosive.push_back(m);
  }
  // A device flying in behind the impactor (a delayed body deposit) is the explosive, not an
  // impactor: its kinetic energy is not what the impact's share is measured against.
  for (const BodySpec& b : scene.bodies)
    if (moving(b) && !contains(g.impactor, b.material) && !contains(g.explosive, b.material))
      g.impactor.push_back(b.material);
  for (const BodySpec& b : scene.bodies)
    if (!moving(b) && !contains(g.impactor, b.material) && !contains(g.explosive, b.material) &&
        !contains(g.target, b.material))
      g.target.push_back(b.material);
  return g;
}

double sourceYield(const Scene& scene, const std::vector<double>& initialInternal) {
  double yield = 0.0;
  for (const EnergyDepositSpec& e : scene.deposits) yield += e.energy;
  std::vector<int> detonated;
  for (const DetonationSpec& d : scene.detonations)
    if (!contains(detonated, d.material)) detonated.push_back(d.material);
  for (int m : detonated)
    if (static_cast<std::size_t>(m) < initialInternal.size())
      yield += initialInternal[static_cast<std::size_t>(m)];
  return yield;
}

bool onlyDelayedSources(const Scene& scene) {
  if (!scene.detonations.empty() || scene.deposits.empty()) return false;
  for (const EnergyDepositSpec& e : scene.deposits)
    if (!(e.time > 0.0)) return false;
  return true;
}

const DepositFiring* sourceFiring(const Scene& scene, const std::vector<DepositFiring>& firings) {
  if (!onlyDelayedSources(scene) || firings.empty()) return nullptr;
  return &firings.front();
}

CouplingReference couplingReference(const Scene& scene, const std::vector<double>& initialKinetic,
                                    const std::vector<double>& initialInternal,
                                    const std::vector<DepositFiring>& firings) {
  CouplingReference ref;
  const std::size_t n = scene.materials.size();
  if (initialKinetic.size() != n || initialInternal.size() != n) return ref;
  const LedgerGroups g = ledgerGroups(scene);
  ref.target = g.target;
  // The source's gain is measured from the moment it fired: for a delayed deposit, the target's
  // energy just before it (which holds what an impactor already gave it), not at t = 0.
  const DepositFiring* first = sourceFiring(scene, firings);
  const std::vector<double>& kinetic = first ? first->kineticBefore : initialKinetic;
  const std::vector<double>& internal = first ? first->internalBefore : initialInternal;
  if (kinetic.size() != n || internal.size() != n) return ref;
  for (int m : g.target)
    ref.targetInitial += kinetic[static_cast<std::size_t>(m)] + internal[static_cast<std::size_t>(m)];
  if (g.target.empty()) return ref;
  // Before a delayed source fires there is nothing to share yet.
  if (onlyDelayedSources(scene) && !first) return ref;
  // A deposit straight into target particles has no separate device to measure against.
  bool depositInTarget = false;
  for (const EnergyDepositSpec& e : scene.deposits) depositInTarget = depositInTarget || e.body < 0;
  if (!scene.deposits.empty() || !scene.detonations.empty()) {
    if (!depositInTarget) {
      ref.reference = sourceYield(scene, initialInternal);
      ref.isYield = true;
    }
    return ref;
  }
  for (int m : g.impactor) ref.reference += initialKinetic[static_cast<std::size_t>(m)];
  return ref;
}

double couplingShare(const CouplingReference& ref, const std::vector<ConservedTotals>& now) {
  if (!(ref.reference > 0.0)) return 0.0;
  double target = 0.0;
  for (int m : ref.target)
    if (static_cast<std::size_t>(m) < now.size()) target += now[static_cast<std::size_t>(m)].total();
  return (target - ref.targetInitial) / ref.reference;
}

namespace {

// Signed depth of x inside a shape: distance to its surface, positive inside, negative outside.
double depthInside(const ShapeSpec& shape, const std::array<double, 3>& x, int dim, bool rz) {
  switch (shape.kind) {
    case ShapeKind::Sphere:
    case ShapeKind::Shell: {
      double r2 = 0.0;
      for (int d = 0; d < dim; ++d) r2 += (x[d] - shape.center[d]) * (x[d] - shape.center[d]);
      return shape.radius - std::sqrt(r2);
    }
    case ShapeKind::Box: {
      double inside = std::numeric_limits<double>::max(), outside2 = 0.0;
      for (int d = 0; d < dim; ++d) {
        // In RZ a box reaching the axis (r = 0) has no surface there.
        const bool axisFace = rz && d == 0 && shape.min[0] <= 0.0;
        inside = std::min({inside, axisFace ? inside : x[d] - shape.min[d], shape.max[d] - x[d]});
        const double gap = std::max({shape.min[d] - x[d], x[d] - shape.max[d], 0.0});
        outside2 += gap * gap;
      }
      return inside >= 0.0 ? inside : -std::sqrt(outside2);
    }
    case ShapeKind::HalfSpace: {
      double side = 0.0, n2 = 0.0;
      for (int d = 0; d < dim; ++d) {
        side += (x[d] - shape.point[d]) * shape.normal[d];
        n2 += shape.normal[d] * shape.normal[d];
      }
      return -side / std::sqrt(n2);
    }
  }
  return 0.0;
}

std::optional<std::array<double, 3>> sourcePoint(const Scene& scene,
                                                 const std::vector<DepositFiring>& firings) {
  if (!scene.detonations.empty()) return scene.detonations.front().point;
  if (scene.deposits.empty()) return std::nullopt;
  // A delayed deposit went off where its energy landed (a device that flew in, say).
  for (const DepositFiring& f : firings)
    if (f.deposit == 0) return f.point;
  const EnergyDepositSpec& e = scene.deposits.front();
  if (e.hasCenter) return e.center;
  const ShapeSpec& s = scene.bodies[static_cast<std::size_t>(e.body)].shape;
  if (s.kind == ShapeKind::Sphere || s.kind == ShapeKind::Shell) return s.center;
  if (s.kind == ShapeKind::Box) {
    std::array<double, 3> c{};
    for (int d = 0; d < 3; ++d) c[d] = 0.5 * (s.min[d] + s.max[d]);
    return c;
  }
  return std::nullopt;
}

}  // namespace

std::optional<double> depthOfBurst(const Scene& scene, const std::vector<DepositFiring>& firings) {
  const std::optional<std::array<double, 3>> x = sourcePoint(scene, firings);
  if (!x) return std::nullopt;
  const LedgerGroups g = ledgerGroups(scene);
  const int dim = spatialDimension(scene.geometry);
  std::optional<double> depth;
  for (const BodySpec& b : scene.bodies) {
    if (!contains(g.target, b.material)) continue;
    const double d = depthInside(b.shape, *x, dim, scene.geometry == Geometry::Axisymmetric);
    depth = depth ? std::max(*depth, d) : d;
  }
  return depth;
}

std::string ledgerKey(const std::string& materialName) {
  std::string out = materialName;
  for (char& c : out)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_')) c = '_';
  return out;
}

namespace {

// The source's share of the run: yield, what the target holds of it and how, what the explosive
// keeps, and where the device sat (the seed's Tables 3.4-3.6 and eq. 3.1).
void addSourceCoupling(const Scene& scene, const std::vector<double>& initialKinetic,
                       const std::vector<double>& initialInternal,
                       const std::vector<ConservedTotals>& now,
                       const std::vector<DepositFiring>& firings, RunSummary& summary) {
  const double yield = sourceYield(scene, initialInternal);
  const bool planar = scene.geometry == Geometry::Planar;
  summary.extras.push_back({planar ? "yield_J_per_m" : "yield_J", yield});
  if (!planar) summary.extras.push_back({"yield_kt", yield / kJoulesPerKilotonTnt});
  // When each deposit fired: t = 0 with the particles, a delayed one at its step (or never).
  for (std::size_t k = 0; k < scene.deposits.size(); ++k) {
    const std::string key = "deposit_" + ledgerKey(scene.deposits[k].name);
    const auto f = std::find_if(firings.begin(), firings.end(),
                                [&](const DepositFiring& x) { return x.deposit == k; });
    const bool delayed = scene.deposits[k].time > 0.0;
    summary.extras.push_back({key + "_fired", !delayed || f != firings.end()});
    if (!delayed) summary.extras.push_back({key + "_fired_time_s", 0.0});
    if (f == firings.end()) continue;
    summary.extras.push_back({key + "_fired_time_s", f->time});
    summary.extras.push_back({key + "_fired_step", static_cast<std::int64_t>(f->step)});
    const int dim = spatialDimension(scene.geometry);
    const char* axis[] = {"x", "y", "z"};
    for (int d = 0; d < dim; ++d)
      summary.extras.push_back({key + "_point_" + axis[d] + "_m", f->point[static_cast<std::size_t>(d)]});
  }
  const CouplingReference ref = couplingReference(scene, initialKinetic, initialInternal, firings);
  const DepositFiring* first = sourceFiring(scene, firings);
  const std::vector<double>& kinetic0 = first ? first->kineticBefore : initialKinetic;
  const std::vector<double>& internal0 = first ? first->internalBefore : initialInternal;
  if (first) summary.extras.push_back({"target_energy_before_source_J", ref.targetInitial});
  if (ref.isYield && ref.reference > 0.0) {
    double kinetic = 0.0, internal = 0.0;
    for (int m : ref.target) {
      const std::size_t k = static_cast<std::size_t>(m);
      kinetic += now[k].kinetic - kinetic0[k];
      internal += now[k].internal - internal0[k];
    }
    const double gain = kinetic + internal;
    summary.extras.push_back({"target_share_of_yield", gain / yield});
    if (gain != 0.0) {
      summary.extras.push_back({"target_kinetic_fraction", kinetic / gain});
      summary.extras.push_back({"target_internal_fraction", internal / gain});
    }
    double explosive = 0.0;
    for (int m : ledgerGroups(scene).explosive) explosive += now[static_cast<std::size_t>(m)].total();
    summary.extras.push_back({"explosive_share_of_yield", explosive / yield});
  }
  if (const std::optional<double> depth = depthOfBurst(scene, firings)) {
    summary.extras.push_back({"depth_of_burst_m", *depth});
    if (!planar && yield > 0.0)
      summary.extras.push_back(
          {"scaled_depth_of_burst_m_per_kt3", *depth / std::cbrt(yield / kJoulesPerKilotonTnt)});
  }
}

}  // namespace

void addEnergyPartition(const Scene& scene, const std::vector<double>& initialKinetic,
                        const std::vector<double>& initialInternal,
                        const std::vector<ConservedTotals>& now, RunSummary& summary,
                        const std::vector<DepositFiring>& firings) {
  const std::size_t n = std::min(scene.materials.size(), now.size());
  const bool haveInitial = initialKinetic.size() == n && initialInternal.size() == n;
  for (std::size_t m = 0; m < n; ++m) {
    const std::string key = "energy_" + ledgerKey(scene.materials[m].name);
    if (haveInitial) {
      summary.extras.push_back({key + "_kinetic_initial_J", initialKinetic[m]});
      summary.extras.push_back({key + "_internal_initial_J", initialInternal[m]});
    }
    summary.extras.push_back({key + "_kinetic_J", now[m].kinetic});
    summary.extras.push_back({key + "_internal_J", now[m].internal});
  }
  const LedgerGroups g = ledgerGroups(scene);
  if (haveInitial && (!scene.deposits.empty() || !scene.detonations.empty()))
    addSourceCoupling(scene, initialKinetic, initialInternal, now, firings, summary);
  if (!haveInitial || g.impactor.empty() || g.target.empty()) return;
  double impactorKinetic = 0.0, targetKinetic = 0.0, targetInternalGain = 0.0;
  for (int m : g.impactor) impactorKinetic += initialKinetic[static_cast<std::size_t>(m)];
  for (int m : g.target) {
    const std::size_t k = static_cast<std::size_t>(m);
    targetKinetic += now[k].kinetic - initialKinetic[k];
    targetInternalGain += now[k].internal - initialInternal[k];
  }
  summary.extras.push_back({"impactor_kinetic_energy_J", impactorKinetic});
  summary.extras.push_back({"target_kinetic_gain_J", targetKinetic});
  summary.extras.push_back({"target_internal_gain_J", targetInternalGain});
  if (impactorKinetic > 0.0)
    summary.extras.push_back(
        {"target_share_of_impactor_energy", (targetKinetic + targetInternalGain) / impactorKinetic});
}

}  // namespace ejecta
