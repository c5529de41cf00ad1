#include "sim/exact/taylor_wave.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ejecta::exact {

namespace {

// Steps in log(rho) along the isentrope: the wall state lies at about 0.6 rho_CJ for TNT, and
// 4000 RK4 steps over that range converge the tabulated states to ~1e-10 relative.
constexpr int kSteps = 4000;
constexpr double kLowestDensityRatio = 0.05;  // safety stop, far below any wall state

}  // namespace

TaylorWave::TaylorWave(const JwlParams& explosive) : D_(explosive.dCJ) {
  const Jwl eos(explosive);
  const ChapmanJouguetState cj = chapmanJouguetState(explosive);
  cj_ = {cj.rho, cj.up, eos.pressure(cj.rho, cj.u), cj.u};
  ahead_ = {explosive.rho0, 0.0, 0.0, explosive.specificDetonationEnergy()};
  // Along the isentrope in s = ln(rho): de/ds = P / rho, and the invariant
  // u = u_CJ - integral_{rho}^{rho_CJ} c / rho drho, i.e. du/ds = c.
  auto slope = [&](double s, double e) { return eos.pressure(std::exp(s), e) / std::exp(s); };
  const double s0 = std::log(cj.rho), s1 = std::log(kLowestDensityRatio * cj.rho);
  const double ds = (s1 - s0) / kSteps;
  double s = s0, e = cj.u, u = cj.up;
  table_.push_back({cj_, eos.soundSpeed(cj.rho, cj.u)});
  for (int k = 0; k < kSteps; ++k) {
    const double c0 = eos.soundSpeed(std::exp(s), e);
    const double k1 = slope(s, e);
    const double k2 = slope(s + 0.5 * ds, e + 0.5 * ds * k1);
    const double k3 = slope(s + 0.5 * ds, e + 0.5 * ds * k2);
    const double k4 = slope(s + ds, e + ds * k3);
    const double eNext = e + ds * (k1 + 2 * k2 + 2 * k3 + k4) / 6.0;
    const double c1 = eos.soundSpeed(std::exp(s + ds), eNext);
    const double uNext = u + 0.5 * ds * (c0 + c1);  // trapezoid; c is smooth along the path
    if (uNext <= 0.0) {
      // The wall state: interpolate to u = 0.
      const double f = u / (u - uNext);
      const double sw = s + f * ds, ew = e + f * (eNext - e);
      const double rw = std::exp(sw);
      table_.push_back({{rw, 0.0, eos.pressure(rw, ew), ew}, eos.soundSpeed(rw, ew)});
      return;
    }
    s += ds;
    e = eNext;
    u = uNext;
    const double r = std::exp(s);
    table_.push_back({{r, u, eos.pressure(r, e), e}, c1});
  }
  throw std::runtime_error("Taylor wave: the isentrope from the C-J point never brought the "
                           "products to rest (inconsistent JWL parameters?)");
}

DetonationState TaylorWave::sample(double xi) const {
  if (xi > D_) return ahead_;
  // The fan's speed u + c decreases monotonically from the C-J point to the wall.
  const double front = table_.front().state.u + table_.front().c;
  if (xi >= front) return cj_;  // between u_CJ + c_CJ and D (equal for a consistent C-J state)
  const double back = table_.back().state.u + table_.back().c;
  if (xi <= back) return table_.back().state;
  auto speed = [](const Node& n) { return n.state.u + n.c; };
  const auto it = std::lower_bound(table_.begin(), table_.end(), xi,
                                   [&](const Node& n, double v) { return speed(n) > v; });
  const Node& b = *it;
  const Node& a = *(it - 1);
  const double f = (speed(a) - xi) / (speed(a) - speed(b));
  auto mix = [f](double p, double q) { return p + f * (q - p); };
  return {mix(a.state.rho, b.state.rho), mix(a.state.u, b.state.u), mix(a.state.p, b.state.p),
          mix(a.state.e, b.state.e)};
}

}  // namespace ejecta::exact
