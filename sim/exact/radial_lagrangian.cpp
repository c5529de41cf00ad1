// One-dimensional Lagrangian hydrocode for radially symmetric explosions; see
// radial_lagrangian.hpp for the method and its sources.
//
// One step from t^n to t^{n+1} = t^n + dt (a predictor-corrector in the manner of Caramana,
// Burton, Shashkov & Whalen 1998, sec. 5), with sigma = p + q the zone's stress, A(r) = r^(j-1)
// the node's area and m the zone's mass per unit measure:
//   predictor  r^{n+1/2} = r^n + dt/2 u^n,
//              e^{n+1/2} = e^n - dt/2 sigma^n (A u)|_k^{k+1} / m   (the same work, half a step),
//              p^{n+1/2}, c^{n+1/2} from the EOS and the burn at t^{n+1/2}; q^{n+1/2} from u^n;
//   corrector  node force F_i = A(r_i^{n+1/2}) (sigma_{i-1} - sigma_i)^{n+1/2} (the outer
//              pressure for sigma_N), u^{n+1} = u^n + dt F_i / M_i, ubar = (u^n + u^{n+1}) / 2,
//              e^{n+1} = e^n - dt sigma_k^{n+1/2} (A^{n+1/2} ubar)|_k^{k+1} / m_k,
//              r^{n+1} = r^n + dt ubar.
// The kinetic energy of node i changes by M_i (u^{n+1} - u^n) ubar_i = dt F_i ubar_i, and the
// zones' internal energies by minus the same forces times the same velocities, so the sum changes
// only by the outer pressure's work: the compatible update, exact to round-off whatever the EOS.
#include "sim/exact/radial_lagrangian.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace ejecta::exact {

namespace {

// Ramp of the burn fraction in zone widths: LS-DYNA's 3/2, as sim/sources/programmed_burn.cpp.
constexpr double kBurnWidthInZones = 1.5;
// The time step may grow by at most this factor per step (the start, and after a burn lights).
constexpr double kMaxStepGrowth = 1.2;
// Velocity, in units of the local sound speed, below which a quiet zone's inner node is held at
// rest (step(), "the zones reached now").
constexpr double kQuietVelocity = 1e-12;

// Node area over the measure: 1, r, r^2.
inline double area(int j, double r) { return j == 1 ? 1.0 : (j == 2 ? r : r * r); }

// Volume between radii a < b over the measure (r^j / j differences), factored so that thin
// shells far out lose no digits to cancellation.
inline double shellVolume(int j, double a, double b) {
  if (j == 1) return b - a;
  if (j == 2) return 0.5 * (b - a) * (b + a);
  return (b - a) * (a * a + a * b + b * b) / 3.0;
}

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("RadialLagrangian: " + what);
}

}  // namespace

RadialLagrangian::RadialLagrangian(RadialSetup setup)
    : j_(setup.geometry), setup_(std::move(setup)) {
  require(j_ >= 1 && j_ <= 3, "geometry j must be 1, 2 or 3 (got " + std::to_string(j_) + ")");
  require(!setup_.regions.empty(), "no regions");
  require(std::isfinite(setup_.zoneWidth) && setup_.zoneWidth > 0.0, "zone width must be positive");
  require(std::isfinite(setup_.courant) && setup_.courant > 0.0 && setup_.courant <= 1.0,
          "Courant number must be in (0, 1]");
  require(std::isfinite(setup_.quadraticViscosity) && setup_.quadraticViscosity >= 0.0 &&
              std::isfinite(setup_.linearViscosity) && setup_.linearViscosity >= 0.0,
          "viscosity coefficients must be finite and >= 0");
  require(std::isfinite(setup_.outerPressure) && setup_.outerPressure >= 0.0,
          "outer pressure must be finite and >= 0");
  measure_ = j_ == 1 ? 1.0 : (j_ == 2 ? 2.0 * std::numbers::pi : 4.0 * std::numbers::pi);

  double inner = 0.0;
  r_.push_back(0.0);
  regionZones_.resize(setup_.regions.size());
  for (std::size_t g = 0; g < setup_.regions.size(); ++g) {
    const RadialRegion& region = setup_.regions[g];
    const std::string name = "region " + std::to_string(g) + " '" + region.name + "': ";
    require(std::isfinite(region.outerRadius) && region.outerRadius > inner,
            name + "outer radius must be finite and beyond the previous region's");
    require(region.eos != nullptr, name + "no equation of state");
    require(std::isfinite(region.density) && region.density > 0.0,
            name + "density must be positive");
    require(std::isfinite(region.specificEnergy), name + "specific energy must be finite");
    require(std::isfinite(region.velocity), name + "velocity must be finite");
    require(std::isfinite(region.burn.velocity) && region.burn.velocity >= 0.0 &&
                std::isfinite(region.burn.initiationTime),
            name + "detonation velocity must be finite and >= 0");
    const double thickness = region.outerRadius - inner;
    const auto zones =
        static_cast<std::size_t>(std::max(1.0, std::round(thickness / setup_.zoneWidth)));
    const double dr = thickness / static_cast<double>(zones);
    for (std::size_t z = 0; z < zones; ++z) {
      const double a = r_.back();
      const double b =
          z + 1 == zones ? region.outerRadius : inner + static_cast<double>(z + 1) * dr;
      r_.push_back(b);
      regionZones_[g].push_back(mass_.size());
      zoneRegion_.push_back(g);
      mass_.push_back(region.density * shellVolume(j_, a, b));
      rho_.push_back(region.density);
      e_.push_back(region.specificEnergy);
      burnWidth_.push_back(kBurnWidthInZones * (b - a));
      const bool lit = region.burn.velocity > 0.0;
      lightingTime_.push_back(
          lit ? region.burn.initiationTime + 0.5 * (a + b) / region.burn.velocity : 0.0);
      burnFraction_.push_back(lit ? 0.0 : 1.0);
    }
    inner = region.outerRadius;
  }

  // Node masses and velocities: half of each neighbouring zone; a node between two regions takes
  // the momentum of its two halves. r = 0 is the centre (a wall for j = 1): it never moves.
  const std::size_t n = mass_.size();
  nodeMass_.assign(n + 1, 0.0);
  u_.assign(n + 1, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    const double half = 0.5 * mass_[k];
    const double v = setup_.regions[zoneRegion_[k]].velocity;
    nodeMass_[k] += half;
    nodeMass_[k + 1] += half;
    u_[k] += half * v;
    u_[k + 1] += half * v;
  }
  for (std::size_t i = 0; i <= n; ++i) u_[i] /= nodeMass_[i];
  u_[0] = 0.0;
  if (setup_.outer == RadialOuterBoundary::Fixed) u_[n] = 0.0;

  for (auto* v : {&p_, &cs_, &q_, &rhoHalf_, &eHalf_, &pHalf_, &csHalf_, &qHalf_})
    v->assign(n, 0.0);
  for (auto* v : {&rHalf_, &uNew_}) v->assign(n + 1, 0.0);
  updateZones(n, rho_, e_, u_, 0.0, true, p_, cs_, q_);
  quiet_ = setup_.skipQuietZones ? initialQuietZone() : n;
  quietBound_.assign(n + 1, std::numeric_limits<double>::infinity());
  for (std::size_t k = n; k-- > 0;) quietBound_[k] = std::min(quietBound_[k + 1], zoneStepBound(k));
}

std::size_t RadialLagrangian::initialQuietZone() const {
  const std::size_t n = mass_.size();
  // A free outer node under a pressure other than the last zone's moves at once: no quiet zone.
  const double last = p_[n - 1] + q_[n - 1];
  if (setup_.outer == RadialOuterBoundary::Free && last != setup_.outerPressure) return n;
  // Zones of an explosive (they light without moving) are never quiet.
  std::size_t firstQuiet = 0;
  for (std::size_t k = 0; k < n; ++k)
    if (setup_.regions[zoneRegion_[k]].burn.velocity > 0.0) firstQuiet = k + 1;
  std::size_t k = n;
  while (k > firstQuiet && p_[k - 1] + q_[k - 1] == last && u_[k - 1] == 0.0 && u_[k] == 0.0) --k;
  return k;
}

double RadialLagrangian::zoneStepBound(std::size_t k) const {
  const double du = std::min(0.0, u_[k + 1] - u_[k]);
  const double speed =
      cs_[k] + 2.0 * (setup_.linearViscosity * cs_[k] - setup_.quadraticViscosity * du);
  return speed > 0.0 ? (r_[k + 1] - r_[k]) / speed : std::numeric_limits<double>::infinity();
}

void RadialLagrangian::addGauge(std::string name, double radius) {
  require(std::isfinite(radius) && radius >= 0.0,
          "gauge '" + name + "': radius must be finite and >= 0");
  gauges_.push_back({std::move(name), radius, {}, {}, {}, {}});
  const RadialSample s = at(radius);
  RadialGauge& g = gauges_.back();
  g.time.push_back(time_);
  g.pressure.push_back(s.pressure);
  g.density.push_back(s.density);
  g.velocity.push_back(s.velocity);
}

void RadialLagrangian::updateZones(std::size_t count, const std::vector<double>& rho,
                                   const std::vector<double>& e, const std::vector<double>& u,
                                   double t, bool commit, std::vector<double>& p,
                                   std::vector<double>& cs, std::vector<double>& q) {
  for (std::size_t g = 0; g < regionZones_.size(); ++g) {
    // A region's zones are consecutive: those below `count` are a prefix of its list.
    const std::vector<std::size_t>& zones = regionZones_[g];
    if (zones.empty() || zones.front() >= count) continue;
    const std::size_t m = std::min(zones.size(), count - zones.front());
    setup_.regions[g].eos->evaluate(rho.data(), e.data(), p.data(), cs.data(), zones.data(), m);
    const RadialBurn& burn = setup_.regions[g].burn;
    if (!(burn.velocity > 0.0)) continue;
    const double D = burn.velocity;
    const bool compression =
        burn.rho0 > 0.0 && burn.cjRelativeVolume > 0.0 && burn.cjRelativeVolume < 1.0;
    for (std::size_t z = 0; z < m; ++z) {
      const std::size_t k = zones[z];
      double f = burnFraction_[k];
      if (f < 1.0) {
        const double width = burnWidth_[k];
        if (t > lightingTime_[k]) f = std::max(f, (t - lightingTime_[k]) * D / width);
        // As in sim/sources/programmed_burn.cpp: the compression burn only within one ramp width ahead
        // of the programmed front.
        if (compression && rho[k] > burn.rho0 && (lightingTime_[k] - t) * D < width)
          f = std::max(f, (1.0 - burn.rho0 / rho[k]) / (1.0 - burn.cjRelativeVolume));
        f = std::min(1.0, f);
        if (commit) burnFraction_[k] = f;
      }
      p[k] *= f;
    }
  }
  const double cq = setup_.quadraticViscosity, cl = setup_.linearViscosity;
  for (std::size_t k = 0; k < count; ++k) {
    const double du = u[k + 1] - u[k];
    q[k] = du < 0.0 ? rho[k] * (cq * du * du - cl * cs[k] * du) : 0.0;
  }
}

double RadialLagrangian::stableStep() const {
  double dt = quietBound_[quiet_];  // the quiet zones are as they started
  for (std::size_t k = 0; k < quiet_; ++k) dt = std::min(dt, zoneStepBound(k));
  dt *= setup_.courant;
  if (lastDt_ > 0.0) dt = std::min(dt, kMaxStepGrowth * lastDt_);
  return dt;
}

void RadialLagrangian::step(double dt) {
  const std::size_t n = mass_.size();
  const int j = j_;
  const bool freeOuter = setup_.outer == RadialOuterBoundary::Free;
  const double pOuter = freeOuter ? setup_.outerPressure : 0.0;
  // The active part: zones [0, quiet_) and the first quiet zone, whose stress the node between
  // them feels; nodes [1, lastNode] accelerate (nodes beyond feel two equal stresses).
  const std::size_t zones = std::min(n, quiet_ + 1);
  const std::size_t lastNode = std::min(n, quiet_);

  // Predictor: half a step with the forces and velocities of t^n.
  for (std::size_t i = 0; i <= zones; ++i) rHalf_[i] = r_[i] + 0.5 * dt * u_[i];
  for (std::size_t k = 0; k < zones; ++k) {
    const double work = (p_[k] + q_[k]) * (area(j, r_[k + 1]) * u_[k + 1] - area(j, r_[k]) * u_[k]);
    eHalf_[k] = e_[k] - 0.5 * dt * work / mass_[k];
    rhoHalf_[k] = mass_[k] / shellVolume(j, rHalf_[k], rHalf_[k + 1]);
  }
  updateZones(zones, rhoHalf_, eHalf_, u_, time_ + 0.5 * dt, false, pHalf_, csHalf_, qHalf_);

  // Corrector: node accelerations from the half-step stresses.
  uNew_[0] = 0.0;
  for (std::size_t i = 1; i <= lastNode; ++i) {
    const double outside = i < n ? pHalf_[i] + qHalf_[i] : pOuter;
    const double force = area(j, rHalf_[i]) * (pHalf_[i - 1] + qHalf_[i - 1] - outside);
    uNew_[i] = u_[i] + dt * force / nodeMass_[i];
  }
  if (!freeOuter && lastNode == n) uNew_[n] = 0.0;
  if (lastNode < n) uNew_[lastNode + 1] = u_[lastNode + 1];  // at rest
  // The zones reached now: the first quiet zone too once its inner node moves. A velocity below
  // 1e-12 c there is no signal but the scheme's round-off and underflow precursor, which runs one
  // zone per step ahead of everything (far faster than sound where the zones are thin): the node
  // is held, so the quiet zones stay quiet (the pressure this drops is below 1e-12 rho c^2).
  std::size_t reached = quiet_;
  if (lastNode == n) {
    reached = n;
  } else if (lastNode == quiet_ && lastNode > 0 && uNew_[lastNode] != 0.0) {
    if (std::abs(uNew_[lastNode]) > kQuietVelocity * cs_[lastNode])
      reached = quiet_ + 1;
    else
      uNew_[lastNode] = 0.0;
  }
  // The zones' energies: minus the work of the same forces with the time-centred velocities.
  for (std::size_t k = 0; k < reached; ++k) {
    const double inner = 0.5 * (u_[k] + uNew_[k]), outer = 0.5 * (u_[k + 1] + uNew_[k + 1]);
    const double work =
        (pHalf_[k] + qHalf_[k]) * (area(j, rHalf_[k + 1]) * outer - area(j, rHalf_[k]) * inner);
    e_[k] -= dt * work / mass_[k];
  }
  if (lastNode == n)
    boundaryWork_ -= dt * pOuter * area(j, rHalf_[n]) * 0.5 * (u_[n] + uNew_[n]) * measure_;
  for (std::size_t i = 0; i <= lastNode; ++i) {
    r_[i] += dt * 0.5 * (u_[i] + uNew_[i]);
    u_[i] = uNew_[i];
  }
  for (std::size_t k = 0; k < reached; ++k) {
    const double volume = shellVolume(j, r_[k], r_[k + 1]);
    if (!(r_[k + 1] > r_[k]) || !(volume > 0.0)) fail(k, "inverted");
    rho_[k] = mass_[k] / volume;
  }
  quiet_ = reached;
  time_ += dt;
  updateZones(quiet_, rho_, e_, u_, time_, true, p_, cs_, q_);
  for (std::size_t k = 0; k < quiet_; ++k)
    if (!std::isfinite(p_[k]) || !std::isfinite(e_[k]) || !std::isfinite(u_[k + 1]))
      fail(k, "non-finite");
  ++steps_;
  lastDt_ = dt;
}

void RadialLagrangian::advanceTo(double t) {
  require(std::isfinite(t) && t >= time_, "cannot advance backwards (to " + std::to_string(t) +
                                              " s from " + std::to_string(time_) + " s)");
  while (time_ < t) {
    double dt = stableStep();
    if (!(dt > 0.0)) fail(0, "time step " + std::to_string(dt) + " s");
    // Land on t exactly, without a sliver of a last step.
    const bool last = time_ + dt >= t;
    if (last)
      dt = t - time_;
    else if (time_ + 1.5 * dt > t)
      dt = 0.5 * (t - time_);
    step(dt);
    if (last) time_ = t;
    recordGauges();
  }
}

void RadialLagrangian::recordGauges() {
  for (std::size_t g = 0; g < gauges_.size(); ++g) {
    RadialGauge& gauge = gauges_[g];
    const RadialSample s = at(gauge.radius);
    gauge.time.push_back(time_);
    gauge.pressure.push_back(s.pressure);
    gauge.density.push_back(s.density);
    gauge.velocity.push_back(s.velocity);
  }
}

RadialSample RadialLagrangian::at(double radius) const {
  const std::size_t n = mass_.size();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (!(radius >= 0.0) || radius > r_[n]) return {nan, nan, nan};
  // Zone i holds the radius (r_i <= radius < r_{i+1}); the velocity is between its nodes.
  const auto above = std::upper_bound(r_.begin(), r_.end(), radius);
  const std::size_t i = std::min(n - 1, static_cast<std::size_t>(above - r_.begin()) - 1);
  const double fu = (radius - r_[i]) / (r_[i + 1] - r_[i]);
  const double velocity = u_[i] + fu * (u_[i + 1] - u_[i]);
  // Pressure and density between the two zone centres around it: zone i's and a neighbour's.
  auto centre = [&](std::size_t k) { return 0.5 * (r_[k] + r_[k + 1]); };
  if (radius <= centre(0)) return {p_[0], rho_[0], velocity};
  if (radius >= centre(n - 1)) return {p_[n - 1], rho_[n - 1], velocity};
  const std::size_t k = radius < centre(i) ? i - 1 : i;
  const double f = (radius - centre(k)) / (centre(k + 1) - centre(k));
  return {p_[k] + f * (p_[k + 1] - p_[k]), rho_[k] + f * (rho_[k + 1] - rho_[k]), velocity};
}

double RadialLagrangian::totalMass() const {
  double m = 0.0;
  for (double mk : mass_) m += mk;
  return m * measure_;
}

double RadialLagrangian::regionMass(std::size_t region) const {
  require(region < regionZones_.size(), "no region " + std::to_string(region));
  double m = 0.0;
  for (std::size_t k : regionZones_[region]) m += mass_[k];
  return m * measure_;
}

double RadialLagrangian::regionInternalEnergy(std::size_t region) const {
  require(region < regionZones_.size(), "no region " + std::to_string(region));
  double sum = 0.0;
  for (std::size_t k : regionZones_[region]) sum += mass_[k] * e_[k];
  return sum * measure_;
}

double RadialLagrangian::regionKineticEnergy(std::size_t region) const {
  require(region < regionZones_.size(), "no region " + std::to_string(region));
  double sum = 0.0;
  for (std::size_t k : regionZones_[region])
    sum += 0.25 * mass_[k] * (u_[k] * u_[k] + u_[k + 1] * u_[k + 1]);
  return sum * measure_;
}

double RadialLagrangian::internalEnergy() const {
  double sum = 0.0;
  for (std::size_t k = 0; k < mass_.size(); ++k) sum += mass_[k] * e_[k];
  return sum * measure_;
}

double RadialLagrangian::kineticEnergy() const {
  double sum = 0.0;
  for (std::size_t i = 0; i < u_.size(); ++i) sum += 0.5 * nodeMass_[i] * u_[i] * u_[i];
  return sum * measure_;
}

void RadialLagrangian::fail(std::size_t zone, const std::string& what) const {
  const std::size_t g = zone < zoneRegion_.size() ? zoneRegion_[zone] : 0;
  throw std::runtime_error("RadialLagrangian: zone " + std::to_string(zone) + " (region '" +
                           setup_.regions[g].name + "') " + what + " at t = " +
                           std::to_string(time_) + " s after " + std::to_string(steps_) + " steps");
}

}  // namespace ejecta::exact
