#include "sim/run/simulation.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <optional>
#include <sstream>

#include "sim/parallel/thread_team.hpp"
#include "sim/run/packages/phase_fractions_package.hpp"
#include "sim/run/packages/porosity_package.hpp"
#include "sim/run/packages/programmed_burn_package.hpp"
#include "sim/run/packages/smoothing_length_cap_package.hpp"
#include "sim/run/packages/strength_package.hpp"
#include "sim/run/packages/viscosity_switch_package.hpp"
#include "sim/run/timestep_criteria.hpp"
#include "sim/setup/bodies.hpp"
#include "sim/solid/solid_state.hpp"
#include "sim/sph/density_pass.hpp"
#include "sim/sph/hydro_force.hpp"
#include "sim/sph/iad_matrix.hpp"
#include "sim/sph/velocity_gradient_refresh.hpp"

namespace ejecta {

namespace {

// Ghost layers and neighbour search reach this far beyond 2h, so the density pass may grow h by
// this factor without a second ghost build (it checks, and rebuilds if h grew more).
constexpr double kGhostMargin = 1.1;
// Particles are reordered by cell every this many steps, for memory locality of the pair loops.
constexpr long kSortInterval = 16;
// Fewest particles worth a thread of their own (see the constructor).
constexpr std::size_t kParticlesPerThread = 500;

std::string describeParticle(const ParticleSet& p, std::size_t i) {
  std::ostringstream s;
  s.precision(6);
  s << "particle id " << p.id[i] << " (material " << p.material[i] << ") at x=(" << p.x[0][i]
    << ", " << p.x[1][i] << ", " << p.x[2][i] << ") m, v=(" << p.v[0][i] << ", " << p.v[1][i]
    << ", " << p.v[2][i] << ") m/s, rho=" << p.rho[i] << " kg/m^3, u=" << p.u[i]
    << " J/kg, P=" << p.P[i] << " Pa, h=" << p.h[i] << " m";
  return s.str();
}

// Every column the leapfrog advances, and each one's rate, from the registry: a NaN in any of
// them (a package's too) stops the run at the step it appears in.
std::vector<const double*> evolvedColumns(const ParticleSet& p) {
  std::vector<const double*> out;
  auto watch = [&](const Field& f) {
    if (f.spec.type != FieldType::Float64 || f.storage.kind == FieldStorage::Kind::Derived) return;
    for (int c = 0; c < f.spec.components; ++c) out.push_back(p.column(f, c).data());
  };
  for (const Field& f : p.fields()) {
    if (f.spec.evolution == Evolution::None) continue;
    watch(f);
    if (f.spec.evolution == Evolution::Kicked)
      if (const Field* rate = p.field(f.spec.rate)) watch(*rate);
  }
  return out;
}

// The first index of a non-finite entry of x[0, n), or n. Checked on the exponent bits (all
// ones: infinity or NaN), an integer test the compiler vectorises; the scan for the index runs
// only when one is there.
std::size_t firstNonFiniteIndex(const double* x, std::size_t n) {
  constexpr std::uint64_t kExponent = 0x7ff0000000000000ull;
  std::uint64_t any = 0;
  for (std::size_t i = 0; i < n; ++i)
    any |= static_cast<std::uint64_t>((std::bit_cast<std::uint64_t>(x[i]) & kExponent) == kExponent);
  if (any == 0) return n;
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(x[i])) return i;
  return n;
}

}  // namespace

Simulation::Simulation(Scene scene, ParticleSet particles, MaterialTable materials,
                       int numThreads, std::shared_ptr<const Communicator> ranks)
    : scene_(std::move(scene)),
      domain_(std::move(ranks), spatialDimension(scene_.geometry)),
      p_(std::move(particles)),
      materials_(std::move(materials)),
      boundaries_(scene_.geometry, scene_.domain),
      ws_(scene_.sph, scene_.geometry) {
  if (domain_.comm().sum(p_.numReal) == 0)
    throw SimulationError("scene '" + scene_.name + "' has no particles");
  refuseUnbuiltSphOptions();
  // A particle with 30x the neighbours its kernel should hold (the volume of the support in
  // particle volumes: 2 kappa eta, pi (kappa eta)^2, 4/3 pi (kappa eta)^3) has an h that stopped
  // tracking its density (the seed's dh/dt or constant h in a strong expansion); its pair loop
  // would grow without bound, so the run stops with a diagnosis instead.
  const double reach = kKernelSupport * scene_.sph.eta;
  const double expected = ws_.dim == 1   ? 2.0 * reach
                          : ws_.dim == 2 ? std::numbers::pi * reach * reach
                                         : 4.0 / 3.0 * std::numbers::pi * reach * reach * reach;
  maxNeighbours_ = static_cast<std::uint32_t>(std::max(30.0 * expected, 300.0));
  // The collapse threshold comes from the scene (not the current h), so a restarted run checks
  // exactly what the uninterrupted one checks.
  double spacingMin = std::numeric_limits<double>::max();
  for (const BodySpec& b : scene_.bodies) spacingMin = std::min(spacingMin, b.spacing);
  if (scene_.bodies.empty())
    for (std::size_t i = 0; i < p_.numReal; ++i) spacingMin = std::min(spacingMin, p_.h[i]);
  spacingMin = domain_.comm().minimum(spacingMin);  // the same threshold on every rank
  hMin_ = scene_.sph.hMinFactor * scene_.sph.eta * spacingMin;
  std::string badMaterial;  // found on one rank, reported on all
  for (std::size_t i = 0; i < p_.numReal && badMaterial.empty(); ++i)
    if (p_.material[i] < 0 || static_cast<std::size_t>(p_.material[i]) >= materials_.size())
      badMaterial = "particle id " + std::to_string(p_.id[i]) + " has material index " +
                    std::to_string(p_.material[i]) + " but the scene defines " +
                    std::to_string(materials_.size());
  stopIfAnyRankFailed(badMaterial);
  // The scene's packages, each only where the scene asks for it (docs/design.md). Their order is
  // the order of their hooks, and it matters to the last bit: the burn fraction scales the
  // pressure before the damage releases tension (P f (1 - D), as the golden snapshots hold), and
  // plasticity precedes failure at the end of a step. The burn table checks the detonations
  // even where no particle can burn.
  BurnTable burn = burnTable(scene_.detonations, materials_);
  if (!scene_.detonations.empty() && !p_.hasBurn())
    throw SimulationError("scene '" + scene_.name + "' detonates an explosive but the particles "
                          "carry no lighting times (build them with buildParticles)");
  // A restart keeps the caps its snapshot holds.
  if (scene_.sph.hMaxFactor > 0.0 || p_.field(SmoothingLengthCapPackage::kCap)) {
    hCaps_ = std::make_shared<SmoothingLengthCapPackage>(scene_.sph, scene_.geometry);
    addPackage(hCaps_);
  }
  // Porosity first: the burn, strength and fracture then act on the porous pressure.
  if (materials_.anyPorosity())
    addPackage(std::make_shared<PorosityPackage>(materials_, scene_.sph.density));
  if (materials_.anyPhaseChanges()) addPackage(std::make_shared<PhaseFractionsPackage>());
  if (p_.hasBurn()) addPackage(std::make_shared<ProgrammedBurnPackage>(std::move(burn), scene_.sph.eta));
  if (materials_.anyStrength()) {
    addPackage(std::make_shared<StrengthPackage>(ws_.dim, scene_.time.stepping == Stepping::Individual));
    ws_.shearModulus.assign(materials_.size(), 0.0);
    ws_.yieldCarriesDamage.assign(materials_.size(), 0);
    for (std::size_t m = 0; m < materials_.size(); ++m)
      if (materials_[m].strength) {
        ws_.shearModulus[m] = materials_[m].strength->shearModulus;
        ws_.yieldCarriesDamage[m] = materials_[m].strength->yieldCarriesDamage() ? 1 : 0;
      }
    // Gray et al. (2001) use epsilon = 0.3 for elastic solids in tension.
    ws_.artificialStress = scene_.sph.artificialStress < 0.0 ? 0.3 : scene_.sph.artificialStress;
  }
  // A restarted run's particles may carry fracture fields its materials no longer use.
  if (materials_.anyFracture() || p_.hasFracture()) {
    fracture_ = std::make_shared<FracturePackage>();
    addPackage(fracture_);
  }
  // A delayed body deposit finds its body's particles by id (they are reordered every few steps).
  for (const EnergyDepositSpec& dep : scene_.deposits)
    if (dep.time > 0.0 && dep.body >= 0 && bodyFirstIds_.empty())
      bodyFirstIds_ = bodyFirstIds(scene_, materials_);
  // A restart keeps its snapshot's alpha (and a snapshot's alpha stays in range with the switch
  // off).
  if (scene_.sph.viscositySwitch != ViscositySwitch::None || p_.hasViscositySwitch())
    addPackage(std::make_shared<ViscositySwitchPackage>(scene_.sph));
  // Summation density sets rho in the density pass, and h tied to the density sets h: the
  // leapfrog advances them only when the scene integrates them.
  if (scene_.sph.density != DensityMethod::Continuity) leapfrog_.hold("density");
  if (scene_.sph.smoothingLength != SmoothingLengthMethod::Seed) leapfrog_.hold("smoothing_length");
  if (scene_.time.stepping == Stepping::Individual)
    bins_.emplace(scene_.time.limiterFactor, scene_.time.dtMax);
  // A distributed run: the flaws are drawn from the whole body (each rank keeps the table, found
  // by particle id, so flaws travel with their particle; such scenes are built whole on every
  // rank, bodies.hpp), then each rank keeps its share.
  if (domain_.distributed()) {
    if (fracture_) fracture_->distributeFlaws(p_, materials_);
    domain_.keepShare(p_, [this](const ParticleSet&) { return particleCosts(); });
  }
  // Below ~500 particles per thread the fork/join cost of a pass exceeds its work (a 450-particle
  // tube runs faster on one thread); results do not depend on the thread count either way.
  ws_.numThreads = std::clamp(static_cast<int>(p_.numReal / kParticlesPerThread), 1,
                              std::max(numThreads, 1));
  omp_set_num_threads(ws_.numThreads);
}

void Simulation::addPackage(std::shared_ptr<PhysicsPackage> package) {
  package->registerFields(p_);
  packages_.push_back(std::move(package));
}

void Simulation::distributeFlaws(const ParticleSet& initial) {
  if (fracture_) fracture_->distributeFlaws(initial, materials_);
}

void Simulation::initialise() {
  ++stateVersion_;
  if (fracture_ && !fracture_->flawsReady()) distributeFlaws(p_);
  stateTime_ = time_;
  if (scene_.sph.density == DensityMethod::Continuity &&
      scene_.sph.smoothingLength == SmoothingLengthMethod::Neighbours)
    smoothingLengthFromDensity();
  if (bins_) bins_->registerFields(p_, leapfrog_, scene_.sph.density == DensityMethod::Summation,
                                   densityPassSetsSmoothingLength(scene_.sph));
  evaluateDerivatives();

  computeNextTimestep();
  checkHealth(dtNext_);
  if (bins_) {
    std::vector<std::size_t> all(p_.numReal);
    std::iota(all.begin(), all.end(), std::size_t{0});
    ownTimesteps(all);
    bins_->keepEvaluation(p_, ws_.velocityGradient);
  }
}

void Simulation::resume(double time, long step, double dtNext) {
  ++stateVersion_;
  if (fracture_ && !fracture_->flawsReady()) distributeFlaws(p_);
  time_ = time;
  stateTime_ = time;
  step_ = step;
  dtNext_ = dtNext;
  if (bins_) {
    // At a synchronisation point: each particle's own limit and its last evaluation were stored.
    bins_->registerFields(p_, leapfrog_, scene_.sph.density == DensityMethod::Summation,
                          densityPassSetsSmoothingLength(scene_.sph));
    if (scene_.sph.viscosityReconstruction != ViscosityReconstruction::None)
      ws_.velocityGradient.assign(9 * p_.numReal, 0.0);
    bins_->restoreEvaluation(p_, ws_.velocityGradient);
    std::vector<double>& own = bins_->ownSteps(p_);
    for (std::size_t i = 0; i < p_.numReal; ++i)
      if (!(own[i] > 0.0)) own[i] = dtNext;  // a snapshot without them: the global step
  }
}

double Simulation::meanNeighbours() const {
  std::array<double, 2> sums{
      std::accumulate(ws_.neighbourCount.begin(), ws_.neighbourCount.end(), 0.0),
      static_cast<double>(ws_.neighbourCount.size())};
  domain_.comm().sumInRankOrder(sums);
  return sums[1] > 0.0 ? sums[0] / sums[1] : 0.0;
}

namespace {

void addTotals(const ConservedTotals& t, std::vector<double>& out) {
  out.insert(out.end(), {t.kinetic, t.internal, t.momentum[0], t.momentum[1], t.momentum[2], t.mass});
}

ConservedTotals totalsAt(const std::vector<double>& in, std::size_t k) {
  ConservedTotals t;
  t.kinetic = in[6 * k];
  t.internal = in[6 * k + 1];
  t.momentum = {in[6 * k + 2], in[6 * k + 3], in[6 * k + 4]};
  t.mass = in[6 * k + 5];
  return t;
}

}  // namespace

ConservedTotals Simulation::totals() const {
  const ConservedTotals mine = conservedTotals(p_);
  if (!domain_.distributed()) return mine;
  std::vector<double> sums;
  addTotals(mine, sums);
  domain_.comm().sumInRankOrder(sums);
  return totalsAt(sums, 0);
}

std::vector<ConservedTotals> Simulation::totalsByMaterial() const {
  std::vector<ConservedTotals> mine = conservedTotalsByMaterial(p_, materials_.size());
  if (!domain_.distributed()) return mine;
  std::vector<double> sums;
  for (const ConservedTotals& t : mine) addTotals(t, sums);
  domain_.comm().sumInRankOrder(sums);
  for (std::size_t m = 0; m < mine.size(); ++m) mine[m] = totalsAt(sums, m);
  return mine;
}

const ParticleSet& Simulation::gatheredParticles() const {
  if (!domain_.distributed()) return p_;
  if (collectedVersion_ != stateVersion_) {
    collected_ = domain_.gatherToRoot(p_);
    collectedVersion_ = stateVersion_;
  }
  return collected_;
}

ParticleSet Simulation::gatherParticlesWhere(const ParticleFilter& keep) const {
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < p_.numReal; ++i)
    if (keep(p_, i)) kept.push_back(i);
  if (domain_.distributed()) return domain_.gatherIndices(p_, kept);
  ParticleSet out = p_;
  out.permute(kept);
  out.numReal = kept.size();
  return out;
}

const ParticleSet& Simulation::particlesNear(std::span<const std::array<double, 3>> points) {
  if (!domain_.distributed()) return p_;
  near_ = domain_.gatherNear(p_, points, kKernelSupport);
  return near_;
}

std::vector<std::uint64_t> Simulation::particleCosts() const {
  // A particle's work is its pair loop: its neighbours (before the first step, when they are not
  // counted yet, the same for all), 1.5 times as much for a solid (the stress divergence and the
  // velocity gradient: README's impact bench measures the solid step at 1.48x the hydro step).
  std::vector<std::uint64_t> cost(p_.numReal);
  const bool counted = ws_.neighbourCount.size() == p_.numReal;
  for (std::size_t i = 0; i < p_.numReal; ++i) {
    const bool solid = materials_[static_cast<std::size_t>(p_.material[i])].strength.has_value();
    cost[i] = (counted ? 1 + ws_.neighbourCount[i] : 1) * (solid ? 3u : 2u);
  }
  // Individual time steps: a particle on bin b is evaluated 2^b times a block.
  if (const Field* bin = bins_ ? p_.field(TimeBins::kBinField) : nullptr) {
    const std::vector<double>& b = p_.column(*bin, 0);
    for (std::size_t i = 0; i < p_.numReal; ++i)
      cost[i] <<= std::clamp(static_cast<int>(b[i]), 0, 20);
  }
  return cost;
}

void Simulation::sortForLocality() {
  p_.clearGhosts();
  if (p_.numReal == 0) return;
  double hMean = 0.0;
  for (std::size_t i = 0; i < p_.numReal; ++i) hMean += p_.h[i];
  hMean /= std::max<std::size_t>(p_.numReal, 1);
  CellGrid grid;
  grid.build(p_, ws_.dim, kKernelSupport * hMean);
  const std::vector<std::uint64_t> keys = grid.cellKeys(p_, p_.numReal);
  std::vector<std::size_t> order(p_.numReal);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return keys[a] < keys[b]; });
  p_.permute(order);
  if (!bins_) return;
  // Individual steps: the workspace's per-particle results of the last evaluation are those the
  // particles not evaluated next keep; they follow their particles.
  const std::size_t n = p_.numReal;
  if (ws_.velocityGradient.size() >= 9 * n) {
    std::vector<double> moved(9 * n);
    for (std::size_t i = 0; i < n; ++i)
      std::copy_n(ws_.velocityGradient.begin() + static_cast<std::ptrdiff_t>(9 * order[i]), 9,
                  moved.begin() + static_cast<std::ptrdiff_t>(9 * i));
    ws_.velocityGradient = std::move(moved);
  }
  if (ws_.neighbourCount.size() == n) {
    std::vector<std::uint32_t> moved(n);
    for (std::size_t i = 0; i < n; ++i) moved[i] = ws_.neighbourCount[order[i]];
    ws_.neighbourCount = std::move(moved);
  }
}

void Simulation::evaluateEquationOfState(const ParticleMask* only) {
  if (hCaps_) hCaps_->holdToCaps(p_, only);  // the floored density is the one the EOS sees
  materialMembers_.assign(materials_.size(), {});
  for (std::size_t i = 0; i < p_.numReal; ++i)
    if (selected(only, i)) materialMembers_[static_cast<std::size_t>(p_.material[i])].push_back(i);
  for (std::size_t m = 0; m < materials_.size(); ++m) {
    const std::vector<std::size_t>& members = materialMembers_[m];
    materials_[m].eos->evaluate(p_.rho.data(), p_.u.data(), p_.P.data(), p_.cs.data(),
                                members.data(), members.size());
  }
  applyTemperature(p_, materials_, only);
  const PackageContext context = packageContext(only);
  for (const auto& package : packages_) package->updateState(p_, context);
}

void Simulation::evaluateDerivatives(const std::vector<std::size_t>* active) {
  const int dim = ws_.dim;
  const bool distributed = domain_.distributed();
  const Communicator& ranks = domain_.comm();
  double margin = kGhostMargin;
  // Generalised volumes: the weights from the densities before the pass, through all its tries.
  const bool generalised = scene_.sph.volumeElements == VolumeElements::Generalised;
  const std::vector<double> volumeWeights =
      generalised ? volumeWeightsOf(p_, scene_.sph.volumeExponent) : std::vector<double>();
  for (int attempt = 0;; ++attempt) {
    boundaries_.makeGhosts(p_, kKernelSupport * margin, distributed ? &ranks : nullptr);
    if (generalised) placeVolumeWeights(p_, volumeWeights, ws_);
    // Other ranks' particles (and their images) within reach of this rank's.
    if (distributed) domain_.buildHalos(p_, kKernelSupport * margin);
    // Cells about one (typical) kernel support across.
    std::vector<double> hs(p_.h.begin(), p_.h.begin() + static_cast<std::ptrdiff_t>(p_.numReal));
    if (hs.empty()) hs.assign(1, p_.size() > 0 ? p_.h[0] : 1.0);  // a rank left without particles
    std::nth_element(hs.begin(), hs.begin() + static_cast<std::ptrdiff_t>(hs.size() / 2), hs.end());
    ws_.grid.build(p_, dim, kKernelSupport * hs[hs.size() / 2]);
    ws_.lists.reset(p_.size(), std::max(ws_.numThreads, omp_get_max_threads()));
    std::vector<double> hBefore(p_.h.begin(), p_.h.begin() + static_cast<std::ptrdiff_t>(p_.numReal));
    ws_.hCap = SmoothingLengthCapPackage::caps(p_);  // the ghosts above may have moved it
    const std::optional<std::size_t> bad = runDensityPass(p_, ws_, active);
    stopIfAnyRankFailed(bad ? failureMessage(*bad, "no positive density from the density pass (an "
                                                   "isolated particle, or the continuity density "
                                                   "of a particle driven to zero)")
                            : std::string());
    bool covered = boundaries_.layersCover(p_, kKernelSupport);
    // The halos were chosen for supports up to margin x the h they started the pass with.
    if (distributed) {
      for (std::size_t i = 0; i < p_.numReal && covered; ++i)
        covered = p_.h[i] <= margin * hBefore[i];
      covered = ranks.allTrue(covered);
    }
    if (covered) break;
    if (attempt == 3)
      stopIfAnyRankFailed(failureMessage(0, "smoothing lengths near a boundary (or a rank's "
                                            "halo) grew past four successively wider layers "
                                            "in one step"));
    // h grew past the ghost layer: rebuild from the starting h with a wider layer.
    std::copy(hBefore.begin(), hBefore.end(), p_.h.begin());
    margin *= 1.5;
  }
  // Individual steps on one rank: the pairs come first, so that the equation of state runs only
  // for the particles this evaluation reads (a blast's quiet gas is not re-evaluated each
  // sub-step). Other ranks' reads would need the read sets sent with the halos: every particle
  // there.
  const bool restricted = active && !distributed;
  if (restricted) {
    // The density pass may have moved the real particles' h; the pairs read the images' too.
    for (std::size_t g = 0; g < boundaries_.numBoundaryGhosts(); ++g)
      p_.h[p_.numReal + g] = p_.h[p_.ghostSource[g]];
    buildEvaluatedPairs(active);
    markReadParticles(*active);
    evaluateEquationOfState(&readMask_);
  } else {
    readMask_.clear();
    evaluateEquationOfState();
  }
  if (active) {
    const PackageContext context = packageContext(restricted ? &readMask_ : nullptr);
    for (const auto& package : packages_) package->afterEquationOfState(p_, context);
  }
  // Ghosts first (their sources are here), then the halos (which include other ranks' ghosts).
  boundaries_.refreshGhosts(p_);
  const bool reconstruction = scene_.sph.viscosityReconstruction != ViscosityReconstruction::None;
  if (reconstruction) boundaries_.refreshGhostTensor(p_, ws_.velocityGradient);
  if (scene_.sph.gradients == GradientScheme::IntegralApproach) {
    // From the neighbours' densities, ghosts' included (global steps on one rank: the scene
    // reader refuses the rest).
    computeIadMatrices(p_, ws_);
    boundaries_.refreshGhostTensor(p_, ws_.iadMatrix);
  }
  const bool rz = ws_.geometry == Geometry::Axisymmetric;
  if (rz) {
    for (std::size_t g = p_.numReal; g < p_.numReal + boundaries_.numBoundaryGhosts(); ++g) {
      const std::size_t s = p_.ghostSource[g - p_.numReal];
      ws_.smoothedR[g] = ws_.smoothedR[s];
      ws_.dSmoothedR[g] = ws_.dSmoothedR[s];
    }
  }
  // The pairs are found from the halos' h: where the density pass sets it, it comes first,
  // alone (8 bytes a halo); the rest of their values travel during the force pass.
  if (distributed && densityPassSetsSmoothingLength(scene_.sph)) domain_.refreshHaloArray(p_.h, 1);
  if (!restricted) buildEvaluatedPairs(active);
  if (active && reconstruction && scene_.sph.dissipation == Dissipation::Riemann) {
    // The pairs read their inactive partners' gradients: re-evaluated at the present state
    // (sim/sph/velocity_gradient_refresh.hpp; the Riemann dissipation runs on one rank).
    refreshVelocityGradients(p_, ws_, inactivePartners(p_, ws_, *active));
    boundaries_.refreshGhostTensor(p_, ws_.velocityGradient);
  }
  if (!distributed) {
    runForcePass(p_, ws_, nullptr, active);
  } else {
    // The halos' values are sent now and arrive while the force pass sums the particles that
    // have no halo neighbour (sim/sph/hydro_force.hpp: the same sums as waiting first).
    const auto pending = domain_.startHaloRefresh(p_);
    HaloArrival arrival;
    arrival.first = p_.size() - domain_.halos().received();
    arrival.progress = [&pending] { pending->progress(); };
    arrival.arrive = [&] {
      domain_.finishHaloRefresh(p_, *pending);
      if (reconstruction) domain_.refreshHaloArray(ws_.velocityGradient, 9);
      if (rz) {
        domain_.refreshHaloArray(ws_.smoothedR, 1);
        domain_.refreshHaloArray(ws_.dSmoothedR, 1);
      }
    };
    runForcePass(p_, ws_, &arrival, active);
  }
  const PackageContext context = packageContext(active ? &activeMask_ : nullptr);
  for (const auto& package : packages_) package->evaluateDerivatives(p_, context);
  measureClosingSpeeds(active);
}

void Simulation::buildEvaluatedPairs(const std::vector<std::size_t>* active) {
  const int dim = ws_.dim;
  if (active) {
    // The pairs of the evaluated particles alone, from the widest kernels reaching each cell.
    ws_.grid.recordReach(p_, kKernelSupport);
    switch (dim) {
      case 1: ws_.lists.buildActivePairs<1>(p_, ws_.grid, kKernelSupport, *active); break;
      case 2: ws_.lists.buildActivePairs<2>(p_, ws_.grid, kKernelSupport, *active); break;
      default: ws_.lists.buildActivePairs<3>(p_, ws_.grid, kKernelSupport, *active); break;
    }
  } else switch (dim) {
    case 1: ws_.lists.findGhostGathers<1>(p_, ws_.grid, kKernelSupport);
            ws_.lists.buildPairs<1>(p_, kKernelSupport); break;
    case 2: ws_.lists.findGhostGathers<2>(p_, ws_.grid, kKernelSupport);
            ws_.lists.buildPairs<2>(p_, kKernelSupport); break;
    default: ws_.lists.findGhostGathers<3>(p_, ws_.grid, kKernelSupport);
             ws_.lists.buildPairs<3>(p_, kKernelSupport); break;
  }
}

void Simulation::markReadParticles(const std::vector<std::size_t>& active) {
  readMask_.assign(p_.numReal, 0);
  // Each active particle and its partners; an image stands for its source. A particle is the
  // partner of several, so the marks are atomic stores (of the same 1: the mask does not depend
  // on the order). Threaded from a few hundred active particles (kThreadTeamFrom / 8): each
  // visits its tens of partners, so a particle here is worth several of a simple loop's.
  unsigned char* read = readMask_.data();
  const std::size_t nReal = p_.numReal;
  const std::size_t count = active.size();
#pragma omp parallel for schedule(static) if (count >= kThreadTeamFrom / 8)
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t i = active[k];
    std::atomic_ref<unsigned char>(read[i]).store(1, std::memory_order_relaxed);
    for (std::uint32_t j : ws_.lists.pairs(i))
      std::atomic_ref<unsigned char>(read[j < nReal ? j : p_.ghostSource[j - nReal]])
          .store(1, std::memory_order_relaxed);
  }
  // The gauges read every particle whose support reaches them (sim/sources/gauges.cpp), after
  // each sub-step.
  const int dim = ws_.dim;
  for (const GaugeSpec& gauge : scene_.gauges) {
    const double reach = ws_.grid.reachInto(gauge.position.data());
    gaugeCandidates_.clear();
    switch (dim) {
      case 1: ws_.grid.queryReaching<1>(gauge.position.data(), reach, gaugeCandidates_); break;
      case 2: ws_.grid.queryReaching<2>(gauge.position.data(), reach, gaugeCandidates_); break;
      default: ws_.grid.queryReaching<3>(gauge.position.data(), reach, gaugeCandidates_); break;
    }
    for (std::uint32_t j : gaugeCandidates_) {
      if (j >= p_.numReal) continue;  // the gauges read real particles only
      double r2 = 0.0;
      for (int d = 0; d < dim; ++d) r2 += (p_.x[d][j] - gauge.position[d]) * (p_.x[d][j] - gauge.position[d]);
      const double support = kKernelSupport * p_.h[j];
      if (r2 < support * support) readMask_[j] = 1;
    }
  }
  for (const auto& package : packages_) package->markEvaluatedEverySubStep(p_, readMask_);
}

void Simulation::evaluateSkipped() {
  if (readMask_.empty()) return;
  ++stateVersion_;
  for (unsigned char& read : readMask_) read = read ? 0 : 1;  // now: the skipped ones
  evaluateEquationOfState(&readMask_);
  const PackageContext context = packageContext(&readMask_);
  for (const auto& package : packages_) package->afterEquationOfState(p_, context);
  readMask_.clear();
}

void Simulation::refuseUnbuiltSphOptions() const {
  // The scene reader refuses these with the line (sim/setup/scene_run_sections.cpp); scenes built
  // in code (benches, tests) and the rank count reach only here.
  const SphOptions& sph = scene_.sph;
  const std::string where =
      scene_.sourcePath.empty() ? "scene '" + scene_.name + "'" : scene_.sourcePath;
  // What none of the options is built for. (The materials, not the particles' stress columns: those
  // are added by the strength package after this check.)
  const bool solid = materials_.anyStrength() || materials_.anyFracture();
  auto unbuilt = [&](const std::string& oneRank, bool rzBuilt = false,
                     bool stepsBuilt = false) -> std::string {
    if (domain_.distributed()) return oneRank;
    if (!rzBuilt && scene_.geometry == Geometry::Axisymmetric)
      return "is built for 1D, 2D and 3D, not RZ";
    if (solid) return "is built for fluids (a material here has strength or fracture)";
    if (sph.form != MomentumForm::Lagrangian) return "takes the Lagrangian form";
    if (sph.density != DensityMethod::Summation) return "takes summation density";
    if (!stepsBuilt && scene_.time.stepping != Stepping::Global)
      return "runs with global time steps";
    return "";
  };
  if (sph.volumeElements == VolumeElements::Generalised) {
    std::string why = unbuilt("runs on one rank (the halos do not carry the weights)");
    if (why.empty() && sph.gradients != GradientScheme::Kernel) why = "takes the kernel gradient";
    if (!why.empty())
      throw SimulationError(where + ": key 'sph.volume_elements': \"generalised\" " + why +
                            "; use volume_elements = \"mass\"");
  }
  if (sph.dissipation == Dissipation::Riemann) {
    std::string why = unbuilt("runs on one rank (not yet compared across ranks)", true, true);
    if (why.empty() && sph.gradients != GradientScheme::Kernel) why = "takes the kernel gradient";
    if (why.empty() && sph.volumeElements != VolumeElements::Mass) why = "takes mass volumes";
    if (!why.empty())
      throw SimulationError(where + ": key 'sph.dissipation': \"riemann\" " + why +
                            "; use dissipation = \"viscosity\"");
  }
  if (sph.gradients != GradientScheme::IntegralApproach) return;
  const std::string why =
      unbuilt("runs on one rank (its matrices need the halos' densities before the force pass)");
  if (!why.empty())
    throw SimulationError(where + ": key 'sph.gradients': \"iad\" " + why +
                          "; use gradients = \"kernel\"");
}

void Simulation::smoothingLengthFromDensity() {
  ws_.hCap = SmoothingLengthCapPackage::caps(p_);
  setSmoothingFromDensity(p_, ws_);
}

void Simulation::measureClosingSpeeds(const std::vector<std::size_t>* active) {
  // At the end of the evaluation, while every copy (ghost, halo) holds the state the force pass
  // saw: after it the closing kick moves the real particles and not their copies elsewhere.
  if (!scene_.time.closingSpeed) return;
  closing_.resize(p_.numReal, 0.0);
  const std::size_t n = active ? active->size() : p_.numReal;
#pragma omp parallel for schedule(static)
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = active ? (*active)[k] : k;
    closing_[i] = closingSpeed(i, ws_.lists.pairs(i), p_.x, p_.v, ws_.dim);
  }
}

double Simulation::closingSpeedOf(std::size_t i) const {
  // Every caller follows an evaluation of i; the bound only guards a path that does not.
  return scene_.time.closingSpeed && i < closing_.size() ? closing_[i] : 0.0;
}

void Simulation::computeNextTimestep() {
  const SphOptions& sph = scene_.sph;
  double dtCourant = std::numeric_limits<double>::max();
  double dtForce = std::numeric_limits<double>::max();
  for (std::size_t i = 0; i < p_.numReal; ++i) {
    if (!isolated(i))
      dtCourant = std::min(dtCourant, courantTimestep(sph, p_.h[i], p_.cs[i], p_.divv[i],
                                                      closingSpeedOf(i)));
    double a2 = 0.0;
    for (int d = 0; d < 3; ++d) a2 += p_.a[d][i] * p_.a[d][i];
    dtForce = std::min(dtForce, forceTimestep(sph, p_.h[i], a2));
  }
  // The packages' votes (the crack-growth limit among them).
  double dt = std::min(dtCourant, dtForce);
  const PackageContext context = packageContext();
  for (const auto& package : packages_) dt = std::min(dt, package->timestep(p_, context));
  if (domain_.distributed()) dt = domain_.comm().minimum(dt);
  if (scene_.time.dtMax > 0.0 && dt > scene_.time.dtMax) dt = scene_.time.dtMax;
  if (dt == std::numeric_limits<double>::max()) dt = scene_.time.dtMax > 0 ? scene_.time.dtMax
                                                                         : scene_.time.tEnd;
  dtNext_ = dt;
}

std::string Simulation::failureMessage(std::size_t i, const std::string& reason) const {
  std::ostringstream s;
  s << "step " << step_ << ", t = " << time_ << " s: " << reason;
  if (i < p_.size()) s << ": " << describeParticle(p_, i);
  return s.str();
}

void Simulation::failAt(std::size_t i, const std::string& reason) const {
  throw SimulationError(failureMessage(i, reason));
}

void Simulation::stopIfAnyRankFailed(const std::string& local) const {
  const std::string message = domain_.comm().firstMessage(local);
  if (!message.empty()) throw SimulationError(message);
}

void Simulation::checkHealth(double dt, const std::vector<std::size_t>* only) const {
  const double dtMin = scene_.time.dtMin > 0.0 ? scene_.time.dtMin : 1e-12 * scene_.time.tEnd;
  std::vector<const double*> watched = evolvedColumns(p_);
  watched.push_back(p_.P.data());
  std::size_t firstNonFinite = p_.numReal;
  if (only) {
    for (std::size_t i : *only)
      for (const double* column : watched)
        if (!std::isfinite(column[i])) firstNonFinite = std::min(firstNonFinite, i);
  } else {
    for (const double* column : watched)
      firstNonFinite = std::min(firstNonFinite, firstNonFiniteIndex(column, p_.numReal));
  }
  // This rank's first problem; every rank then stops with the lowest rank's.
  auto problem = [&]() -> std::string {
    const std::size_t count = only ? only->size() : p_.numReal;
    for (std::size_t k = 0; k < count; ++k) {
      const std::size_t i = only ? (*only)[k] : k;
      if (i == firstNonFinite) return failureMessage(i, "non-finite state (NaN or infinity)");
      if (!(p_.rho[i] > 0.0)) return failureMessage(i, "non-positive density");
      if (p_.u[i] < 0.0 &&
          materials_[static_cast<std::size_t>(p_.material[i])].eos->requiresPositiveEnergy())
        return failureMessage(i, "negative specific internal energy");
      if (!(p_.omega[i] > 0.0))
        return failureMessage(i, "non-positive grad-h factor omega (h no longer solvable)");
      if (p_.h[i] < hMin_)
        return failureMessage(i, "smoothing length collapsed below sph.h_min_factor x eta x the "
                                 "smallest body spacing");
      if (i < ws_.neighbourCount.size() && ws_.neighbourCount[i] > maxNeighbours_)
        return failureMessage(
            i, "smoothing length grew until the particle has " +
                   std::to_string(ws_.neighbourCount[i]) + " neighbours (limit " +
                   std::to_string(maxNeighbours_) +
                   "); h no longer follows the density (the seed's dh/dt or constant h in a "
                   "strong expansion, or a particle rarefied at a contact under continuity "
                   "density): cap h with sph.h_max_factor (e.g. 4), or use "
                   "sph.smoothing_length = \"neighbours\" with summation density");
    }
    return {};
  };
  stopIfAnyRankFailed(problem());
  if (dt < dtMin) {
    // The particle whose own limit is the tightest names the problem, with the criterion that
    // set it: the rank holding it reports (dt is the same on every rank; every rank takes part
    // in the reduction, one without particles too).
    const StepLimit tightest = tightestStepLimit();
    const double anywhere = domain_.comm().minimum(tightest.dt);
    const bool mine = p_.numReal > 0 && tightest.dt <= anywhere;
    std::ostringstream s;
    s << "time step " << dt << " s fell below dt_min " << dtMin << " s; tightest limit: the "
      << tightest.criterion << " step, " << tightest.dt << " s, of";
    stopIfAnyRankFailed(mine ? failureMessage(tightest.particle, s.str()) : std::string());
  }
}

Simulation::StepLimit Simulation::tightestStepLimit() const {
  // The criteria of computeNextTimestep and ownTimesteps, particle by particle (only on the way
  // to a stop: the packages' votes are asked of every particle).
  const SphOptions& sph = scene_.sph;
  const bool individual = scene_.time.stepping == Stepping::Individual;
  const std::size_t n = p_.numReal;
  std::vector<double> limit(n, std::numeric_limits<double>::infinity());
  std::vector<std::string> criterion(n, "no");
  auto lower = [&](std::size_t i, double dt, const std::string& name) {
    if (dt < limit[i]) {
      limit[i] = dt;
      criterion[i] = name;
    }
  };
  for (std::size_t i = 0; i < n; ++i) {
    if (individual || !isolated(i))
      lower(i, courantTimestep(sph, p_.h[i], p_.cs[i], p_.divv[i], closingSpeedOf(i)), "Courant");
    double a2 = 0.0;
    for (int d = 0; d < 3; ++d) a2 += p_.a[d][i] * p_.a[d][i];
    lower(i, forceTimestep(sph, p_.h[i], a2), "force");
    if (individual) lower(i, conductionTimestepOf(i), "conduction");
  }
  std::vector<std::size_t> all(n);
  std::iota(all.begin(), all.end(), std::size_t{0});
  const PackageContext context = packageContext();
  for (const auto& package : packages_) {
    std::vector<double> vote(n, std::numeric_limits<double>::infinity());
    package->particleTimesteps(p_, context, all, vote);
    for (std::size_t i = 0; i < n; ++i) lower(i, vote[i], package->name() + " package's");
  }
  StepLimit tightest{0, std::numeric_limits<double>::infinity(), "no"};
  for (std::size_t i = 0; i < n; ++i)
    if (limit[i] < tightest.dt) tightest = {i, limit[i], criterion[i]};
  return tightest;
}

namespace {

// A deposit is due once the time has reached its own, to rounding (steps are cut to land on it).
bool depositDue(double time, double depositTime) { return time >= depositTime * (1.0 - 1e-12); }

}  // namespace

bool Simulation::fired(std::size_t deposit) const {
  return std::any_of(firings_.begin(), firings_.end(),
                     [&](const DepositFiring& f) { return f.deposit == deposit; });
}

double Simulation::nextDepositTime() const {
  double next = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < scene_.deposits.size(); ++k)
    if (scene_.deposits[k].time > 0.0 && !fired(k)) next = std::min(next, scene_.deposits[k].time);
  return next;
}

double Simulation::delayedEnergyAdded() const {
  double e = 0.0;
  for (const DepositFiring& f : firings_) e += scene_.deposits[f.deposit].energy;
  return e;
}

bool Simulation::fireDueDeposits() {
  bool any = false;
  for (std::size_t k = 0; k < scene_.deposits.size(); ++k) {
    const EnergyDepositSpec& dep = scene_.deposits[k];
    if (!(dep.time > 0.0) || fired(k) || !depositDue(time_, dep.time)) continue;
    DepositFiring f;
    f.deposit = k;
    f.time = time_;
    f.step = step_;
    for (const ConservedTotals& m : totalsByMaterial()) {
      f.kineticBefore.push_back(m.kinetic);
      f.internalBefore.push_back(m.internal);
    }
    f.point = applyDeposit(scene_, k, bodyFirstIds_, p_, time_,
                           domain_.distributed() ? &domain_.comm() : nullptr);
    firings_.push_back(std::move(f));
    any = true;
  }
  return any;
}

void Simulation::step(double limit) {
  if (bins_) return stepIndividually(limit);
  ++stateVersion_;
  globalUpdates_ += p_.numReal;
  if (step_ % kSortInterval == 0) {
    // Particles that crossed into another rank's range move there (new ranges when the work is
    // out of balance), then each rank orders its own for locality.
    if (domain_.distributed()) domain_.rebalance(p_, particleCosts());
    sortForLocality();
  }
  // The deposit raises sound speeds by orders of magnitude: pressures, forces and the time step
  // must come from the state with the energy, not from the step before it.
  if (fireDueDeposits()) {
    stateTime_ = time_;
    evaluateDerivatives();
    computeNextTimestep();
    checkHealth(dtNext_);
  }
  limit = std::min(limit, nextDepositTime());
  double dt = dtNext_;
  if (time_ + dt > limit) dt = limit - time_;
  const SphOptions& sph = scene_.sph;
  const int dim = ws_.dim;
  for (const auto& package : packages_) package->limitKicks(leapfrog_, packageContext());

  // Kick to the half step, drift positions, predict every evolved field to the full step.
  leapfrog_.predict(p_, dim, dt);
  stateTime_ = time_ + dt;
  for (const auto& package : packages_) package->afterDrift(p_, packageContext());
  boundaries_.confine(p_, &leapfrog_.velocityHalf());
  if (sph.density == DensityMethod::Continuity &&
      sph.smoothingLength == SmoothingLengthMethod::Neighbours)
    smoothingLengthFromDensity();

  evaluateDerivatives();

  // Second kick with the new derivatives.
  leapfrog_.correct(p_, dim, dt);
  // Pressure and sound speed of the final state, for the snapshot and the next time step.
  evaluateEquationOfState();
  for (const auto& package : packages_) package->finalize(p_, packageContext());
  time_ += dt;
  ++step_;
  lastDt_ = dt;
  computeNextTimestep();
  checkHealth(dtNext_);
}

}  // namespace ejecta
