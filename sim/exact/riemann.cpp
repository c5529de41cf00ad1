// Exact Riemann solver, Toro (2009) chapter 4. See riemann.hpp for the conventions.
#include "sim/exact/riemann.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace ejecta::exact {
namespace {

bool isValidState(const GasState& s) {
  return std::isfinite(s.rho) && std::isfinite(s.u) && std::isfinite(s.p) && s.rho > 0.0 &&
         s.p > 0.0;
}

double soundSpeed(const GasState& s, double gamma) { return std::sqrt(gamma * s.p / s.rho); }

}  // namespace

RiemannProblem::RiemannProblem(GasState left, GasState right, double gamma)
    : left_(left), right_(right), gamma_(gamma) {
  if (!(std::isfinite(gamma) && gamma > 1.0)) {
    throw std::invalid_argument("RiemannProblem: gamma must be finite and > 1");
  }
  if (!isValidState(left) || !isValidState(right)) {
    throw std::invalid_argument("RiemannProblem: states need finite rho > 0, p > 0 and u");
  }
  cL_ = soundSpeed(left_, gamma_);
  cR_ = soundSpeed(right_, gamma_);
  // Pressure positivity condition (Toro sec. 4.3.1): otherwise the two rarefactions separate
  // and leave vacuum between them, which needs a different wave structure (Toro 4.6).
  const double criticalSpeed = 2.0 * (cL_ + cR_) / (gamma_ - 1.0);
  if (criticalSpeed <= right_.u - left_.u) {
    throw std::domain_error("RiemannProblem: initial data generate vacuum (uR - uL = " +
                            std::to_string(right_.u - left_.u) +
                            " >= " + std::to_string(criticalSpeed) + ")");
  }
  solveStarPressure();
  computeStarStatesAndSpeeds();
}

double RiemannProblem::pressureFunction(double p, const GasState& side, double c,
                                        double& derivative) const {
  const double g = gamma_;
  if (p > side.p) {  // shock branch (Toro sec. 4.2.1)
    const double a = 2.0 / ((g + 1.0) * side.rho);
    const double b = (g - 1.0) / (g + 1.0) * side.p;
    const double root = std::sqrt(a / (p + b));
    derivative = root * (1.0 - 0.5 * (p - side.p) / (b + p));
    return (p - side.p) * root;
  }
  // rarefaction branch (Toro sec. 4.2.2)
  const double ratio = p / side.p;
  derivative = std::pow(ratio, -0.5 * (g + 1.0) / g) / (side.rho * c);
  return 2.0 * c / (g - 1.0) * (std::pow(ratio, 0.5 * (g - 1.0) / g) - 1.0);
}

// f(p) = fL(p) + fR(p) + (uR - uL) is increasing and concave with f(0+) < 0 (no vacuum), so a
// Newton iteration kept inside a shrinking sign-change bracket [lo, hi] always converges.
void RiemannProblem::solveStarPressure() {
  const double du = right_.u - left_.u;
  auto f = [&](double p, double& df) {
    double dfl = 0.0, dfr = 0.0;
    const double value =
        pressureFunction(p, left_, cL_, dfl) + pressureFunction(p, right_, cR_, dfr) + du;
    df = dfl + dfr;
    return value;
  };

  // Initial guess: primitive-variable (linearised) estimate (Toro sec. 4.3.2), kept positive.
  const double pPv =
      0.5 * (left_.p + right_.p) - 0.125 * du * (left_.rho + right_.rho) * (cL_ + cR_);
  double p = std::max(pPv, 1e-6 * std::min(left_.p, right_.p));

  double lo = 0.0;
  double hi = std::max({p, left_.p, right_.p});
  double dummy = 0.0;
  while (f(hi, dummy) < 0.0) hi *= 2.0;  // f grows like sqrt(p): doubling terminates

  // A Newton step this small is at the round-off level of f: accept it and stop (testing it
  // against the bracket instead would trigger needless bisection steps).
  constexpr double relativeTolerance = 1e-14;
  constexpr int maxIterations = 200;
  for (iterations_ = 1; iterations_ <= maxIterations; ++iterations_) {
    double df = 0.0;
    const double value = f(p, df);
    if (value == 0.0) break;
    const double step = value / df;
    if (std::abs(step) <= relativeTolerance * p) {
      p -= step;
      break;
    }
    (value < 0.0 ? lo : hi) = p;
    const double next = p - step;
    p = (next > lo && next < hi) ? next : 0.5 * (lo + hi);  // Newton left the bracket: bisect
    if (hi - lo <= relativeTolerance * hi) break;
  }
  if (iterations_ > maxIterations) {
    throw std::runtime_error("RiemannProblem: star-pressure iteration did not converge");
  }
  pStar_ = p;
  double dfl = 0.0, dfr = 0.0;
  const double fl = pressureFunction(pStar_, left_, cL_, dfl);
  const double fr = pressureFunction(pStar_, right_, cR_, dfr);
  uStar_ = 0.5 * (left_.u + right_.u) + 0.5 * (fr - fl);  // Toro sec. 4.2
}

void RiemannProblem::computeStarStatesAndSpeeds() {
  const double g = gamma_;
  const double gm = (g - 1.0) / (g + 1.0);
  const double shockFactor = 0.5 * (g + 1.0) / g;
  const double expo = 0.5 * (g - 1.0) / g;

  const double ratioL = pStar_ / left_.p;
  if (leftIsShock()) {
    rhoStarL_ = left_.rho * (ratioL + gm) / (gm * ratioL + 1.0);
    leftHead_ = left_.u - cL_ * std::sqrt(shockFactor * ratioL + expo);
    leftTail_ = leftHead_;
  } else {
    rhoStarL_ = left_.rho * std::pow(ratioL, 1.0 / g);
    leftHead_ = left_.u - cL_;
    leftTail_ = uStar_ - cL_ * std::pow(ratioL, expo);
  }

  const double ratioR = pStar_ / right_.p;
  if (rightIsShock()) {
    rhoStarR_ = right_.rho * (ratioR + gm) / (gm * ratioR + 1.0);
    rightHead_ = right_.u + cR_ * std::sqrt(shockFactor * ratioR + expo);
    rightTail_ = rightHead_;
  } else {
    rhoStarR_ = right_.rho * std::pow(ratioR, 1.0 / g);
    rightHead_ = right_.u + cR_;
    rightTail_ = uStar_ + cR_ * std::pow(ratioR, expo);
  }
}

GasState RiemannProblem::sample(double xOverT) const {
  return xOverT <= uStar_ ? sampleLeft(xOverT) : sampleRight(xOverT);
}

GasState RiemannProblem::sampleLeft(double xi) const {
  const GasState star{rhoStarL_, uStar_, pStar_};
  if (xi <= leftHead_) return left_;
  if (xi >= leftTail_) return star;  // for a shock head == tail, so this is its star side
  // Inside the left fan (Toro sec. 4.4.2).
  const double g = gamma_;
  const double base = 2.0 / (g + 1.0) + (g - 1.0) / ((g + 1.0) * cL_) * (left_.u - xi);
  return GasState{left_.rho * std::pow(base, 2.0 / (g - 1.0)),
                  2.0 / (g + 1.0) * (cL_ + 0.5 * (g - 1.0) * left_.u + xi),
                  left_.p * std::pow(base, 2.0 * g / (g - 1.0))};
}

GasState RiemannProblem::sampleRight(double xi) const {
  const GasState star{rhoStarR_, uStar_, pStar_};
  if (xi >= rightHead_) return right_;
  if (xi <= rightTail_) return star;
  // Inside the right fan (Toro sec. 4.4.2).
  const double g = gamma_;
  const double base = 2.0 / (g + 1.0) - (g - 1.0) / ((g + 1.0) * cR_) * (right_.u - xi);
  return GasState{right_.rho * std::pow(base, 2.0 / (g - 1.0)),
                  2.0 / (g + 1.0) * (-cR_ + 0.5 * (g - 1.0) * right_.u + xi),
                  right_.p * std::pow(base, 2.0 * g / (g - 1.0))};
}

}  // namespace ejecta::exact
