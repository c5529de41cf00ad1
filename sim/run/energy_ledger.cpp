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

LedgerSummary::Source sourceCoupling(const Scene& scene, const std::vector<double>& initialKinetic,
                                     const std::vector<double>& initialInternal,
                                     const std::vector<ConservedTotals>& now,
                                     const std::vector<DepositFiring>& firings) {
  LedgerSummary::Source out;
  const double yield = sourceYield(scene, initialInternal);
  out.yield = yield;
  out.planar = scene.geometry == Geometry::Planar;
  if (!out.planar) out.yieldKt = yield / kJoulesPerKilotonTnt;
  out.dimension = spatialDimension(scene.geometry);
  for (std::size_t k = 0; k < scene.deposits.size(); ++k) {
    LedgerSummary::Deposit d;
    d.key = "deposit_" + ledgerKey(scene.deposits[k].name);
    d.delayed = scene.deposits[k].time > 0.0;
    const auto f = std::find_if(firings.begin(), firings.end(),
                                [&](const DepositFiring& x) { return x.deposit == k; });
    if (f != firings.end()) d.firing = *f;
    out.deposits.push_back(std::move(d));
  }
  const CouplingReference ref = couplingReference(scene, initialKinetic, initialInternal, firings);
  const DepositFiring* first = sourceFiring(scene, firings);
  const std::vector<double>& kinetic0 = first ? first->kineticBefore : initialKinetic;
  const std::vector<double>& internal0 = first ? first->internalBefore : initialInternal;
  if (first) out.targetEnergyBeforeSource = ref.targetInitial;
  if (ref.isYield && ref.reference > 0.0) {
    double kinetic = 0.0, internal = 0.0;
    for (int m : ref.target) {
      const std::size_t k = static_cast<std::size_t>(m);
      kinetic += now[k].kinetic - kinetic0[k];
      internal += now[k].internal - internal0[k];
    }
    const double gain = kinetic + internal;
    out.targetShareOfYield = gain / yield;
    if (gain != 0.0) {
      out.targetKineticFraction = kinetic / gain;
      out.targetInternalFraction = internal / gain;
    }
    double explosive = 0.0;
    for (int m : ledgerGroups(scene).explosive) explosive += now[static_cast<std::size_t>(m)].total();
    out.explosiveShareOfYield = explosive / yield;
  }
  out.depthOfBurst = depthOfBurst(scene, firings);
  if (out.depthOfBurst && !out.planar && yield > 0.0)
    out.scaledDepthOfBurst = *out.depthOfBurst / std::cbrt(yield / kJoulesPerKilotonTnt);
  return out;
}

void addToSummary(const LedgerSummary::Source& s, RunSummary& summary) {
  auto& x = summary.extras;
  x.push_back({s.planar ? "yield_J_per_m" : "yield_J", s.yield});
  if (s.yieldKt) x.push_back({"yield_kt", *s.yieldKt});
  for (const LedgerSummary::Deposit& d : s.deposits) {
    x.push_back({d.key + "_fired", !d.delayed || d.firing.has_value()});
    if (!d.delayed) x.push_back({d.key + "_fired_time_s", 0.0});
    if (!d.firing) continue;
    x.push_back({d.key + "_fired_time_s", d.firing->time});
    x.push_back({d.key + "_fired_step", static_cast<std::int64_t>(d.firing->step)});
    const char* axis[] = {"x", "y", "z"};
    for (int k = 0; k < s.dimension; ++k)
      x.push_back({d.key + "_point_" + axis[k] + "_m", d.firing->point[static_cast<std::size_t>(k)]});
  }
  if (s.targetEnergyBeforeSource)
    x.push_back({"target_energy_before_source_J", *s.targetEnergyBeforeSource});
  if (s.targetShareOfYield) x.push_back({"target_share_of_yield", *s.targetShareOfYield});
  if (s.targetKineticFraction) x.push_back({"target_kinetic_fraction", *s.targetKineticFraction});
  if (s.targetInternalFraction)
    x.push_back({"target_internal_fraction", *s.targetInternalFraction});
  if (s.explosiveShareOfYield) x.push_back({"explosive_share_of_yield", *s.explosiveShareOfYield});
  if (s.depthOfBurst) x.push_back({"depth_of_burst_m", *s.depthOfBurst});
  if (s.scaledDepthOfBurst) x.push_back({"scaled_depth_of_burst_m_per_kt3", *s.scaledDepthOfBurst});
}

}  // namespace

LedgerSummary ledgerSummary(const Scene& scene, const std::vector<double>& initialKinetic,
                            const std::vector<double>& initialInternal,
                            const std::vector<ConservedTotals>& now,
                            const std::vector<DepositFiring>& firings) {
  LedgerSummary out;
  const std::size_t n = std::min(scene.materials.size(), now.size());
  const bool haveInitial = initialKinetic.size() == n && initialInternal.size() == n;
  for (std::size_t m = 0; m < n; ++m) {
    LedgerSummary::Material e;
    e.key = ledgerKey(scene.materials[m].name);
    if (haveInitial) {
      e.initialKinetic = initialKinetic[m];
      e.initialInternal = initialInternal[m];
    }
    e.kinetic = now[m].kinetic;
    e.internal = now[m].internal;
    out.materials.push_back(std::move(e));
  }
  const LedgerGroups g = ledgerGroups(scene);
  if (haveInitial && (!scene.deposits.empty() || !scene.detonations.empty()))
    out.source = sourceCoupling(scene, initialKinetic, initialInternal, now, firings);
  if (!haveInitial || g.impactor.empty() || g.target.empty()) return out;
  LedgerSummary::Impact impact;
  for (int m : g.impactor) impact.impactorKinetic += initialKinetic[static_cast<std::size_t>(m)];
  for (int m : g.target) {
    const std::size_t k = static_cast<std::size_t>(m);
    impact.targetKineticGain += now[k].kinetic - initialKinetic[k];
    impact.targetInternalGain += now[k].internal - initialInternal[k];
  }
  if (impact.impactorKinetic > 0.0)
    impact.targetShareOfImpactorEnergy =
        (impact.targetKineticGain + impact.targetInternalGain) / impact.impactorKinetic;
  out.impact = impact;
  return out;
}

void addToSummary(const LedgerSummary& ledger, RunSummary& summary) {
  auto& x = summary.extras;
  for (const LedgerSummary::Material& m : ledger.materials) {
    const std::string key = "energy_" + m.key;
    if (m.initialKinetic) x.push_back({key + "_kinetic_initial_J", *m.initialKinetic});
    if (m.initialInternal) x.push_back({key + "_internal_initial_J", *m.initialInternal});
    x.push_back({key + "_kinetic_J", m.kinetic});
    x.push_back({key + "_internal_J", m.internal});
  }
  if (ledger.source) addToSummary(*ledger.source, summary);
  if (!ledger.impact) return;
  const LedgerSummary::Impact& i = *ledger.impact;
  x.push_back({"impactor_kinetic_energy_J", i.impactorKinetic});
  x.push_back({"target_kinetic_gain_J", i.targetKineticGain});
  x.push_back({"target_internal_gain_J", i.targetInternalGain});
  if (i.targetShareOfImpactorEnergy)
    x.push_back({"target_share_of_impactor_energy", *i.targetShareOfImpactorEnergy});
}

void addEnergyPartition(const Scene& scene, const std::vector<double>& initialKinetic,
                        const std::vector<double>& initialInternal,
                        const std::vector<ConservedTotals>& now, RunSummary& summary,
                        const std::vector<DepositFiring>& firings) {
  addToSummary(ledgerSummary(scene, initialKinetic, initialInternal, now, firings), summary);
}

}  // namespace ejecta
