#include "sim/exact/impedance_match.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

namespace ejecta::exact {

namespace {

// RK4 steps per unit of ln(rho) along the isentrope: the local error per step is ~ds^5, so 2000
// steps per e-fold converge (e, u) to ~1e-13 relative (the Taylor-wave table uses the same
// integrand and reaches 1e-10 with fewer).
constexpr double kStepsPerLogDensity = 2000.0;
constexpr int kMaxBisections = 200;
// Largest expansion searched for the rarefaction's foot: rho_CJ * 2^-60, far past any target.
constexpr int kMaxHalvings = 60;

// The products' C-J state and equation of state, and the two branches of the reflected wave.
class ReflectedWave {
 public:
  explicit ReflectedWave(const JwlParams& explosive) : eos_(explosive) {
    const ChapmanJouguetState cj = chapmanJouguetState(explosive);
    // The C-J pressure the EOS gives at (rho_CJ, e_CJ): 1.8e-4 from the published P_CJ for TNT
    // (docs/eos_shock_jwl.md); starting both branches there keeps them on one EOS surface.
    cj_ = {cj.rho, cj.up, eos_.pressure(cj.rho, cj.u), cj.u};
  }

  const ProductsState& chapmanJouguet() const { return cj_; }

  // On the isentrope through C-J at density exp(s): de/ds = P/rho and, for the wave facing back
  // into the products, du/ds = -c (u + Phi constant), integrated by RK4 from ln rho_CJ.
  ProductsState isentrope(double s) const {
    ProductsState last = cj_;
    walkIsentrope(s, [&](const ProductsState& state, double) { last = state; });
    return last;
  }

  // The same walk, calling visit(state, c) at C-J and after every step.
  template <typename Visit>
  void walkIsentrope(double s, Visit&& visit) const {
    const double s0 = std::log(cj_.rho);
    const int n = std::max(8, static_cast<int>(std::ceil(std::abs(s - s0) * kStepsPerLogDensity)));
    const double ds = (s - s0) / n;
    auto slope = [&](double sk, double e, double& de, double& du) {
      const double rho = std::exp(sk);
      de = eos_.pressure(rho, e) / rho;
      du = -eos_.soundSpeed(rho, e);
    };
    visit(cj_, eos_.soundSpeed(cj_.rho, cj_.e));
    double e = cj_.e, u = cj_.u;
    for (int k = 0; k < n; ++k) {
      const double sk = s0 + k * ds;
      double e1, u1, e2, u2, e3, u3, e4, u4;
      slope(sk, e, e1, u1);
      slope(sk + 0.5 * ds, e + 0.5 * ds * e1, e2, u2);
      slope(sk + 0.5 * ds, e + 0.5 * ds * e2, e3, u3);
      slope(sk + ds, e + ds * e3, e4, u4);
      e += ds * (e1 + 2 * e2 + 2 * e3 + e4) / 6.0;
      u += ds * (u1 + 2 * u2 + 2 * u3 + u4) / 6.0;
      // The last step lands on s exactly, not on s0 + n ds with its round-off.
      const double rho = std::exp(k + 1 == n ? s : s0 + (k + 1) * ds);
      visit(ProductsState{rho, u, eos_.pressure(rho, e), e}, eos_.soundSpeed(rho, e));
    }
  }

  // On the products' Hugoniot centred on C-J at density rho >= rho_CJ. P = P_cold(rho) + w rho e
  // is linear in e, so the energy jump condition solves for e in closed form.
  ProductsState hugoniot(double rho) const {
    const double dv = 1.0 / cj_.rho - 1.0 / rho;
    const double cold = eos_.pressure(rho, 0.0);
    const double w = eos_.params().omega;
    const double e = (cj_.e + 0.5 * (cold + cj_.p) * dv) / (1.0 - 0.5 * w * rho * dv);
    const double p = cold + w * rho * e;
    return {rho, cj_.u - std::sqrt(std::max(0.0, (p - cj_.p) * dv)), p, e};
  }

  // The products' Hugoniot from C-J ends where 1 - w rho dv / 2 = 0: rho = rho_CJ (1 + 2/w).
  double limitingDensity() const { return cj_.rho * (1.0 + 2.0 / eos_.params().omega); }

 private:
  Jwl eos_;
  ProductsState cj_{};
};

// Bisection for the root of f on [lo, hi] where f(lo) and f(hi) have opposite signs; stops at
// round-off.
double bisect(const std::function<double(double)>& f, double lo, double hi) {
  const bool rising = f(hi) > 0.0;
  for (int k = 0; k < kMaxBisections; ++k) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    ((f(mid) > 0.0) == rising ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

using StateFunction = std::function<double(const ProductsState&)>;

// The ln(rho) on the isentrope where g(state) changes sign from positive at C-J to negative.
double isentropeRoot(const ReflectedWave& wave, const StateFunction& g, const char* what) {
  const double sCJ = std::log(wave.chapmanJouguet().rho);
  double sLow = sCJ;
  for (int k = 0; k < kMaxHalvings; ++k) {
    sLow -= std::log(2.0);
    if (g(wave.isentrope(sLow)) < 0.0)
      return bisect([&](double s) { return g(wave.isentrope(s)); }, sLow, sCJ);
  }
  throw std::invalid_argument(std::string("impedance match: ") + what +
                              " not reached on the products' isentrope");
}

// The density on the products' Hugoniot where g(state) changes sign from negative at C-J.
double hugoniotRoot(const ReflectedWave& wave, const StateFunction& g, const char* what) {
  const double rhoCJ = wave.chapmanJouguet().rho;
  const double rhoMax = wave.limitingDensity() * (1.0 - 1e-12);
  if (!(g(wave.hugoniot(rhoMax)) > 0.0))
    throw std::invalid_argument(std::string("impedance match: ") + what +
                                " beyond the products' limiting compression");
  return bisect([&](double rho) { return g(wave.hugoniot(rho)); }, rhoCJ, rhoMax);
}

}  // namespace

ProductsState reflectedProductsState(const JwlParams& explosive, double pressure) {
  if (!(pressure > 0.0) || !std::isfinite(pressure))
    throw std::invalid_argument("impedance match: pressure must be positive and finite");
  const ReflectedWave wave(explosive);
  const ProductsState& cj = wave.chapmanJouguet();
  if (pressure == cj.p) return cj;
  auto excess = [pressure](const ProductsState& s) { return s.p - pressure; };
  if (pressure < cj.p) return wave.isentrope(isentropeRoot(wave, excess, "the pressure"));
  return wave.hugoniot(hugoniotRoot(wave, excess, "the pressure"));
}

namespace {

ImpedanceMatch solveMatch(const ReflectedWave& wave, const ShockMaterial& target) {
  const ProductsState& cj = wave.chapmanJouguet();
  // The target's Hugoniot pressure at particle velocity u (it can only be pushed, u > 0).
  auto targetPressure = [&](double u) { return u > 0.0 ? hugoniotState(target, u).P : 0.0; };
  // Products' pressure minus the target's at the products' velocity: positive at C-J for a
  // softer target, and it falls along the isentrope (p down, u up); negative at C-J for a
  // stiffer one, and it rises along the Hugoniot (p up, u down).
  auto mismatch = [&](const ProductsState& s) { return s.p - targetPressure(s.u); };
  const double atCJ = mismatch(cj);
  ImpedanceMatch m{};
  if (atCJ == 0.0) {
    m.products = cj;
  } else if (atCJ > 0.0) {
    m.products = wave.isentrope(isentropeRoot(wave, mismatch, "the target's Hugoniot"));
  } else {
    m.products = wave.hugoniot(hugoniotRoot(wave, mismatch, "the target's Hugoniot"));
    m.reflectedShock = true;
  }
  m.target = hugoniotState(target, m.products.u);
  return m;
}

}  // namespace

ImpedanceMatch detonationImpedanceMatch(const JwlParams& explosive, const ShockMaterial& target) {
  return solveMatch(ReflectedWave(explosive), target);
}

InterfaceRiemannSolution::InterfaceRiemannSolution(const JwlParams& explosive,
                                                   const ShockMaterial& target)
    : targetDensity_(target.rho0) {
  const ReflectedWave wave(explosive);
  const Jwl eos(explosive);
  match_ = solveMatch(wave, target);
  cj_ = wave.chapmanJouguet();
  headSpeed_ = cj_.u - eos.soundSpeed(cj_.rho, cj_.e);
  if (match_.reflectedShock) {
    // Mass conservation across the shock: rho_CJ (u_CJ - S) = rho* (u* - S).
    const ProductsState& s = match_.products;
    headSpeed_ = tailSpeed_ = (s.rho * s.u - cj_.rho * cj_.u) / (s.rho - cj_.rho);
    return;
  }
  // Tabulate the fan from C-J to the star state; inside it x/t = u - c (the C- characteristics).
  wave.walkIsentrope(std::log(match_.products.rho), [&](const ProductsState& state, double c) {
    fan_.push_back(state);
    fanSpeed_.push_back(state.u - c);
  });
  fan_.back() = match_.products;  // the bisection's state, to round-off the walk's end point
  tailSpeed_ = fanSpeed_.back();
}

InterfaceSample InterfaceRiemannSolution::sample(double xi) const {
  const ProductsState& star = match_.products;
  const HugoniotState& shocked = match_.target;
  if (xi > shocked.us) return {targetDensity_, 0.0, 0.0, false};
  if (xi > star.u) return {shocked.rho, shocked.up, shocked.P, false};
  if (xi >= tailSpeed_) return {star.rho, star.u, star.p, true};
  if (xi < headSpeed_) return {cj_.rho, cj_.u, cj_.p, true};
  // Inside the fan: u - c rises monotonically from head to tail.
  const auto it = std::upper_bound(fanSpeed_.begin(), fanSpeed_.end(), xi);
  const std::size_t b = static_cast<std::size_t>(it - fanSpeed_.begin());
  const std::size_t a = b - 1;
  const double f = (xi - fanSpeed_[a]) / (fanSpeed_[b] - fanSpeed_[a]);
  auto mix = [f](double p, double q) { return p + f * (q - p); };
  return {mix(fan_[a].rho, fan_[b].rho), mix(fan_[a].u, fan_[b].u), mix(fan_[a].p, fan_[b].p),
          true};
}

}  // namespace ejecta::exact
