// Sedov-Taylor-von Neumann similarity solution; see sedov.hpp for conventions.
//
// Derivation (Sedov ch. IV; Kamm & Timmes 2007 sec. 2 in other variables). With
// R(t) = A t^delta, delta = 2/(j+2), lambda = r/R, s = ln(lambda) and
//   v = (r/t) V(s),  c^2 = gamma p / rho = (r/t)^2 Z(s),  rho = rho0 G(s),
// mass, momentum and entropy conservation for radial flow in geometry j become (' = d/ds,
// W = V - delta)
//   W (ln G)' + V' + j V = 0
//   W V' + V (V - 1) + (Z' + Z (ln G)' + 2 Z) / gamma = 0
//   W ((1 - gamma) (ln G)' + (ln Z)') + 2 (V - 1) = 0.
// Energy inside any sphere lambda = const is constant in time (R^(j+2)/t^2 is), so the energy
// flux through it vanishes; that is the algebraic energy integral
//   Z = gamma (gamma - 1) V^2 (delta - V) / (2 (gamma V - delta)),
// singular at the origin where V -> V0 = delta/gamma. With e = V - V0 (gamma V - delta = gamma e)
// the system reduces to
//   V' = N / D,  N = V (delta - V) (j (gamma - 1) V / 2 + V - 1),  D = (V - delta)^2 - Z,
//   (ln G)' = -(j V + V') / W.
// Integrating x = ln(e) instead of V keeps the approach to the origin (e -> 0 like a power of
// lambda) well conditioned; integrating V and Z as independent unknowns is not: the direction
// off the energy integral grows like lambda^-j toward the origin and spoils the centre.
// Strong-shock conditions at lambda = 1 (shock speed U = delta R / t):
//   V = 2 delta / (gamma + 1),  G = (gamma + 1)/(gamma - 1)  (Z then follows from the integral).
// Energy with R = t = rho0 = 1: E = sigma_j int_0^1 G lambda^2 (V^2/2 + Z/(gamma (gamma-1)))
// lambda^(j-1) dlambda = alpha, sigma_j = 2, 2 pi, 4 pi (see the header for what E is per j).
#include "sim/exact/sedov.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace ejecta::exact {
namespace {

// Table layout in u = -ln(lambda). Near the shock the profile is steepest (a thin dense shell
// for gamma -> 1); toward the origin x and ln G approach linear functions of u, so coarse steps
// suffice there. At u = 40 the omitted energy tail is below e^-40 relative.
constexpr double kNearShockSpan = 3.0;
constexpr double kInteriorEnd = 40.0;
constexpr double kInteriorStep = 1e-2;
constexpr int kSubsteps = 8;  // RK4 steps per table interval: integration error << table error

// Integration state: x = ln(V - V0), ln G, and the running energy integral.
using State = std::array<double, 3>;

struct SimilarityOde {
  int j;
  double gamma;
  double delta;
  double v0;

  double velocity(double x) const { return v0 + std::exp(x); }

  // ln Z from the energy integral, written with e = V - V0 so that it stays accurate as e -> 0.
  double lnZ(double x) const {
    const double v = velocity(x);
    return std::log(0.5 * (gamma - 1.0) * v * v * (delta - v)) - x;
  }

  // d/du of the state at u = -ln(lambda) (minus the d/ds of the file comment).
  State rate(double u, const State& y) const {
    const double e = std::exp(y[0]);
    const double v = v0 + e;
    const double w = v - delta;
    const double zTimesE = 0.5 * (gamma - 1.0) * v * v * (delta - v);  // finite as e -> 0
    const double n = v * (delta - v) * (0.5 * j * (gamma - 1.0) * v + v - 1.0);
    const double dTimesE = w * w * e - zTimesE;
    const double dxds = n / dTimesE;  // (1/e) dV/ds
    const double dvds = dxds * e;
    const double dlnGds = -(j * v + dvds) / w;
    // Energy density (rho v^2/2 + p/(gamma-1)) in units rho0 = R = t = 1, times lambda^(j+1)
    // dlambda = lambda^(j+2) ds; in logs so that G -> 0, Z -> inf stay finite.
    const double jacobian = -(j + 2.0) * u;
    const double energyRate = 0.5 * v * v * std::exp(y[1] + jacobian) +
                              std::exp(y[1] + lnZ(y[0]) + jacobian) / (gamma * (gamma - 1.0));
    return {-dxds, -dlnGds, energyRate};
  }

  State rk4Step(double u, const State& y, double h) const {
    auto axpy = [](const State& a, double s, const State& b) {
      return State{a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]};
    };
    const State k1 = rate(u, y);
    const State k2 = rate(u + 0.5 * h, axpy(y, 0.5 * h, k1));
    const State k3 = rate(u + 0.5 * h, axpy(y, 0.5 * h, k2));
    const State k4 = rate(u + h, axpy(y, h, k3));
    State next = y;
    for (std::size_t i = 0; i < next.size(); ++i) {
      next[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    }
    return next;
  }
};

// Measure factor sigma_j of the energy integral (slab counted on both sides for j = 1).
double geometricFactor(int j) {
  switch (j) {
    case 1:
      return 2.0;
    case 2:
      return 2.0 * std::numbers::pi;
    default:
      return 4.0 * std::numbers::pi;
  }
}

void requirePositiveFinite(double value, const char* message) {
  if (!(std::isfinite(value) && value > 0.0)) throw std::invalid_argument(message);
}

}  // namespace

double SedovState::e() const { return p / ((gamma - 1.0) * rho); }

SedovSolution::SedovSolution(int j, double gamma, double energy, double rho0)
    : j_(j), gamma_(gamma), energy_(energy), rho0_(rho0) {
  if (j < 1 || j > 3) throw std::invalid_argument("SedovSolution: j must be 1, 2 or 3");
  if (!(std::isfinite(gamma) && gamma > 1.0)) {
    throw std::invalid_argument("SedovSolution: gamma must be finite and > 1");
  }
  // For j = 3, gamma >= 7 the standard solution does not exist: N vanishes between the shock
  // and the origin (Kamm & Timmes 2007 treat those cases separately).
  if (j == 3 && gamma >= 7.0) {
    throw std::invalid_argument("SedovSolution: spherical case needs gamma < 7");
  }
  requirePositiveFinite(energy, "SedovSolution: energy must be finite and > 0");
  requirePositiveFinite(rho0, "SedovSolution: rho0 must be finite and > 0");
  delta_ = 2.0 / (j + 2.0);
  v0_ = delta_ / gamma;
  buildProfile();
}

void SedovSolution::buildProfile() {
  const SimilarityOde ode{j_, gamma_, delta_, v0_};
  const double g = gamma_;
  const double shockV = 2.0 * delta_ / (g + 1.0);
  State y{std::log(shockV - v0_), std::log((g + 1.0) / (g - 1.0)), 0.0};

  // The post-shock shell thins like (gamma - 1): refine the near-shock step with it (measured:
  // profile errors <= 1e-8 relative for gamma >= 1.05, see docs/exact_solutions.md).
  const double fineStep = std::min(1e-3, 0.005 * (g - 1.0));
  auto fill = [&](Segment& seg, double start, double step, int intervals) {
    seg.u0 = start;
    seg.step = step;
    seg.nodes.clear();
    seg.nodes.reserve(intervals + 1);
    for (int i = 0; i <= intervals; ++i) {
      const double u = start + i * step;
      const State d = ode.rate(u, y);
      if (!(std::isfinite(y[0]) && std::isfinite(y[1]) && std::isfinite(d[0]))) {
        throw std::domain_error("SedovSolution: similarity integration failed");
      }
      seg.nodes.push_back(Node{y[0], y[1], d[0], d[1]});
      if (i == intervals) break;
      const double h = step / kSubsteps;
      for (int k = 0; k < kSubsteps; ++k) y = ode.rk4Step(u + k * h, y, h);
    }
  };
  const int fineIntervals = static_cast<int>(std::ceil(kNearShockSpan / fineStep));
  fill(nearShock_, 0.0, kNearShockSpan / fineIntervals, fineIntervals);
  const int coarseIntervals =
      static_cast<int>(std::ceil((kInteriorEnd - kNearShockSpan) / kInteriorStep));
  fill(interior_, kNearShockSpan, (kInteriorEnd - kNearShockSpan) / coarseIntervals,
       coarseIntervals);
  alpha_ = geometricFactor(j_) * y[2];
}

SedovSolution::Node SedovSolution::interpolate(double u) const {
  const Segment& seg = (u <= interior_.u0) ? nearShock_ : interior_;
  const auto last = seg.nodes.size() - 1;
  const double pos = (u - seg.u0) / seg.step;
  if (pos >= static_cast<double>(last)) {
    // Beyond the table (lambda < e^-40): continue the asymptotically linear profile.
    const Node& n = seg.nodes[last];
    const double du = u - (seg.u0 + seg.step * static_cast<double>(last));
    return Node{n.x + du * n.dx, n.lnG + du * n.dlnG, n.dx, n.dlnG};
  }
  const auto i = static_cast<std::size_t>(pos);
  const double t = pos - static_cast<double>(i);
  const Node& a = seg.nodes[i];
  const Node& b = seg.nodes[i + 1];
  // Cubic Hermite basis on [0, 1], derivatives scaled by the step.
  const double t2 = t * t;
  const double h00 = (1.0 + 2.0 * t) * (1.0 - t) * (1.0 - t);
  const double h10 = t * (1.0 - t) * (1.0 - t) * seg.step;
  const double h01 = t2 * (3.0 - 2.0 * t);
  const double h11 = t2 * (t - 1.0) * seg.step;
  return Node{h00 * a.x + h10 * a.dx + h01 * b.x + h11 * b.dx,
              h00 * a.lnG + h10 * a.dlnG + h01 * b.lnG + h11 * b.dlnG, 0.0, 0.0};
}

SedovSolution::Profile SedovSolution::profileAt(double u) const {
  const Node n = interpolate(u);
  const double v = v0_ + std::exp(n.x);
  const double lnZ = std::log(0.5 * (gamma_ - 1.0) * v * v * (delta_ - v)) - n.x;
  return Profile{v, n.lnG, lnZ};
}

double SedovSolution::shockRadius(double t) const {
  requirePositiveFinite(t, "SedovSolution: t must be finite and > 0");
  return std::pow(energy_ * t * t / (alpha_ * rho0_), 1.0 / (j_ + 2.0));
}

double SedovSolution::shockSpeed(double t) const { return delta_ * shockRadius(t) / t; }

double SedovSolution::timeOfShockRadius(double radius) const {
  requirePositiveFinite(radius, "SedovSolution: radius must be finite and > 0");
  return std::sqrt(alpha_ * rho0_ * std::pow(radius, j_ + 2.0) / energy_);
}

double SedovSolution::postShockDensity() const { return rho0_ * (gamma_ + 1.0) / (gamma_ - 1.0); }

double SedovSolution::postShockVelocity(double t) const {
  return 2.0 * shockSpeed(t) / (gamma_ + 1.0);
}

double SedovSolution::postShockPressure(double t) const {
  const double speed = shockSpeed(t);
  return 2.0 * rho0_ * speed * speed / (gamma_ + 1.0);
}

SedovState SedovSolution::at(double r, double t) const {
  if (!(std::isfinite(r) && r >= 0.0)) {
    throw std::invalid_argument("SedovSolution::at: r must be finite and >= 0");
  }
  const double radius = shockRadius(t);
  if (r > radius) return SedovState{rho0_, 0.0, 0.0, gamma_};
  const double scale = radius / t;  // r/t at the shock
  // p = rho0 (r/t)^2 G Z / gamma = rho0 (R/t)^2 exp(ln G + ln Z - 2u) / gamma, u = -ln(lambda).
  if (r == 0.0) {
    // Limit lambda -> 0: G -> 0, v = (r/t) V -> 0, and ln G + ln Z - 2u tends to a constant:
    // evaluate it at the end of the table, where it has converged to round-off.
    const Profile q = profileAt(kInteriorEnd);
    return SedovState{0.0, 0.0,
                      rho0_ * scale * scale * std::exp(q.lnG + q.lnZ - 2.0 * kInteriorEnd) / gamma_,
                      gamma_};
  }
  const double lambda = r / radius;
  const double u = -std::log(lambda);
  const Profile q = profileAt(u);
  return SedovState{rho0_ * std::exp(q.lnG), scale * lambda * q.v,
                    rho0_ * scale * scale * std::exp(q.lnG + q.lnZ - 2.0 * u) / gamma_, gamma_};
}

}  // namespace ejecta::exact
