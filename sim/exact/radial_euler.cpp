// Radially symmetric Euler solver used as a converged reference; see radial_euler.hpp.
//
// One step of the MUSCL-Hancock scheme (Toro 2009, ch. 14, sec. 14.4), adapted to the
// area-weighted radial equations of Toro ch. 17 (sec. 17.2):
//   1. Reconstruction: limited (van Leer) slopes of rho, u, p in each cell give the boundary
//      extrapolated states at its two faces.
//   2. Hancock predictor: both face states are evolved by dt/2. Toro writes this step with the
//      conservative flux difference; here it uses the primitive-variable equations (the same to
//      second order, and the geometric terms enter naturally):
//        rho_t + u rho_r + rho div(u) = 0,  u_t + u u_r + p_r / rho = 0,
//        p_t + u p_r + gamma p div(u) = 0,
//      where div(u) = r^(1-j) d(r^(j-1) u)/dr is taken as the discrete divergence
//      (A_R u_R - A_L u_L) / V of the cell. That form contains the geometric term (j-1) u / r and
//      stays exact for u = a r in the first cell, where r -> 0.
//   3. Corrector: HLLC fluxes (Toro ch. 10) at every face from the evolved states, then
//      V_i dU/dt = -(A_{i+1/2} F_{i+1/2} - A_{i-1/2} F_{i-1/2}) + S_i, where S_i is non-zero only
//      for momentum: the integral of p dA over the cell of the half-step linear pressure, i.e.
//      p_i (A_{i+1/2} - A_{i-1/2}) plus, for j = 3, the slope correction dp dr^2 / 6.
// Mass and energy change only through face fluxes, so their totals telescope. A uniform
// pressure at rest stays exactly at rest because the momentum source balances the pressure
// flux difference (the update is written so that they cancel in floating point too).
#include "sim/exact/radial_euler.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace ejecta::exact {
namespace {

constexpr double kCfl = 0.45;  // MUSCL-Hancock is stable up to 1 in 1D; 0.45 keeps a margin

bool isValidState(const GasState& s) {
  return std::isfinite(s.rho) && std::isfinite(s.u) && std::isfinite(s.p) && s.rho > 0.0 &&
         s.p > 0.0;
}

// van Leer's limiter (Toro sec. 14.3 / 13.8): harmonic mean of the one-sided differences,
// zero at extrema, so the reconstruction creates no new extrema.
double vanLeer(double left, double right) {
  const double product = left * right;
  return product > 0.0 ? 2.0 * product / (left + right) : 0.0;
}

double integerPower(double x, int n) {
  double result = 1.0;
  for (int k = 0; k < n; ++k) result *= x;
  return result;
}

}  // namespace

RadialRiemannSolution::RadialRiemannSolution(int j, GasState inner, GasState outer, double radius,
                                             double gamma, double rMax, int cells)
    : j_(j), gamma_(gamma), rMax_(rMax) {
  if (j < 1 || j > 3) throw std::invalid_argument("RadialRiemannSolution: j must be 1, 2 or 3");
  if (!(std::isfinite(gamma) && gamma > 1.0)) {
    throw std::invalid_argument("RadialRiemannSolution: gamma must be finite and > 1");
  }
  if (!isValidState(inner) || !isValidState(outer)) {
    throw std::invalid_argument("RadialRiemannSolution: states need finite rho > 0, p > 0 and u");
  }
  if (!(std::isfinite(rMax) && radius > 0.0 && radius < rMax)) {
    throw std::invalid_argument("RadialRiemannSolution: need 0 < radius < rMax");
  }
  if (cells < 4) throw std::invalid_argument("RadialRiemannSolution: need at least 4 cells");

  const auto n = static_cast<std::size_t>(cells);
  dr_ = rMax / cells;
  area_.resize(n + 1);
  volume_.resize(n);
  for (int f = 0; f <= cells; ++f) area_[static_cast<std::size_t>(f)] = faceArea(f);
  for (int i = 0; i < cells; ++i) volume_[static_cast<std::size_t>(i)] = cellVolume(i);
  inverseVolume_.resize(n);
  for (std::size_t k = 0; k < n; ++k) inverseVolume_[k] = 1.0 / volume_[k];

  // Cell averages of the conserved variables; the cell containing the interface gets the
  // volume-weighted mix, which places the discontinuity at `radius` to within round-off.
  rho_.resize(n);
  mom_.resize(n);
  energy_.resize(n);
  const double radiusPow = integerPower(radius, j_);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = integerPower(static_cast<double>(i) * dr_, j_);
    const double b = integerPower(static_cast<double>(i + 1) * dr_, j_);
    const double innerFraction = std::clamp((radiusPow - a) / (b - a), 0.0, 1.0);
    auto mix = [&](double innerValue, double outerValue) {
      return innerFraction * innerValue + (1.0 - innerFraction) * outerValue;
    };
    auto totalEnergyDensity = [&](const GasState& s) {
      return s.p / (gamma_ - 1.0) + 0.5 * s.rho * s.u * s.u;
    };
    rho_[i] = mix(inner.rho, outer.rho);
    mom_[i] = mix(inner.rho * inner.u, outer.rho * outer.u);
    energy_[i] = mix(totalEnergyDensity(inner), totalEnergyDensity(outer));
  }

  w_.resize(n + 2);
  faceL_.resize(n);
  faceR_.resize(n);
  pressureSlope_.resize(n);
  flux_.resize(n + 1);
}

double RadialRiemannSolution::faceArea(int face) const { return integerPower(face * dr_, j_ - 1); }

double RadialRiemannSolution::cellVolume(int cell) const {
  return (integerPower((cell + 1) * dr_, j_) - integerPower(cell * dr_, j_)) / j_;
}

double RadialRiemannSolution::measureFactor() const {
  constexpr double factors[] = {1.0, 2.0 * std::numbers::pi, 4.0 * std::numbers::pi};
  return factors[j_ - 1];
}

RadialRiemannSolution::Primitive RadialRiemannSolution::cellPrimitive(int i) const {
  const auto k = static_cast<std::size_t>(i);
  const double rho = rho_[k];
  const double u = mom_[k] / rho;
  const double p = (gamma_ - 1.0) * (energy_[k] - 0.5 * mom_[k] * u);
  return {rho, u, p};
}

// w_[i + 1] holds cell i; one ghost each side: the mirror image at the centre (reflecting,
// u -> -u) and a copy of the last cell at rMax (transmissive, zero gradient). Returns the
// largest signal speed |u| + c, for the time step, and checks positivity on the way.
double RadialRiemannSolution::fillPrimitivesWithGhosts() {
  const int n = cellCount();
  double maxSpeed = 0.0;
  for (int i = 0; i < n; ++i) {
    const Primitive w = cellPrimitive(i);
    if (!(w.rho > 0.0 && w.p > 0.0 && std::isfinite(w.u))) {
      throw std::runtime_error("RadialRiemannSolution: lost positivity of density or pressure");
    }
    maxSpeed = std::max(maxSpeed, std::abs(w.u) + std::sqrt(gamma_ * w.p / w.rho));
    w_[static_cast<std::size_t>(i + 1)] = w;
  }
  const Primitive first = w_[1];
  w_[0] = {first.rho, -first.u, first.p};
  w_[static_cast<std::size_t>(n + 1)] = w_[static_cast<std::size_t>(n)];
  return maxSpeed;
}

// HLLC flux (Toro sec. 10.4-10.6) with the pressure-based wave-speed estimates of Toro
// sec. 10.5.2 (PVRS star pressure, eqs. 10.59-10.61). In the star regions the flux is written
// as the physical flux of the star state, F* = (rho* S*, rho* S*^2 + p*, (E* + p*) S*), which
// equals Toro's F_K + S_K (U*_K - U_K) but gives exactly zero mass and energy flux when
// S* = 0, as at the reflecting centre.
RadialRiemannSolution::Flux RadialRiemannSolution::hllc(const Primitive& left,
                                                        const Primitive& right) const {
  const double g = gamma_;
  const double cL = std::sqrt(g * left.p / left.rho);
  const double cR = std::sqrt(g * right.p / right.rho);
  const double rhoMean = 0.5 * (left.rho + right.rho);
  const double cMean = 0.5 * (cL + cR);
  const double pPvrs = 0.5 * (left.p + right.p) - 0.5 * (right.u - left.u) * rhoMean * cMean;
  const double pStar = std::max(0.0, pPvrs);
  auto shockFactor = [g](double pSide, double pEstimate) {
    return pEstimate <= pSide ? 1.0
                              : std::sqrt(1.0 + (g + 1.0) / (2.0 * g) * (pEstimate / pSide - 1.0));
  };
  const double sL = left.u - cL * shockFactor(left.p, pStar);
  const double sR = right.u + cR * shockFactor(right.p, pStar);
  const double massL = left.rho * (sL - left.u);  // mass flux through the left wave
  const double massR = right.rho * (sR - right.u);
  const double sStar =
      (right.p - left.p + left.u * massL - right.u * massR) / (massL - massR);  // Toro 10.37

  auto energyDensity = [g](const Primitive& w) {
    return w.p / (g - 1.0) + 0.5 * w.rho * w.u * w.u;
  };
  auto physicalFlux = [&](const Primitive& w) {
    const double e = energyDensity(w);
    return Flux{w.rho * w.u, w.rho * w.u * w.u + w.p, w.u * (e + w.p)};
  };
  // Star state on side K (Toro eqs. 10.33, 10.36, 10.39), then its physical flux.
  auto starFlux = [&](const Primitive& w, double sK, double massK) {
    const double rhoStar = massK / (sK - sStar);
    const double pStarK = w.p + massK * (sStar - w.u);
    const double eStar =
        rhoStar * (energyDensity(w) / w.rho + (sStar - w.u) * (sStar + w.p / massK));
    return Flux{rhoStar * sStar, rhoStar * sStar * sStar + pStarK, (eStar + pStarK) * sStar};
  };

  if (sL >= 0.0) return physicalFlux(left);
  if (sR <= 0.0) return physicalFlux(right);
  return sStar >= 0.0 ? starFlux(left, sL, massL) : starFlux(right, sR, massR);
}

void RadialRiemannSolution::step(double dt) {
  const int n = cellCount();
  const double halfDt = 0.5 * dt;
  const double invDr = 1.0 / dr_;
  const double g = gamma_;

  // Reconstruction and Hancock half-step predictor, cell by cell.
  for (int i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const Primitive& wm = w_[k];
    const Primitive& w = w_[k + 1];
    const Primitive& wp = w_[k + 2];
    const double dRho = vanLeer(w.rho - wm.rho, wp.rho - w.rho);
    const double dU = vanLeer(w.u - wm.u, wp.u - w.u);
    const double dP = vanLeer(w.p - wm.p, wp.p - w.p);
    const double uLeft = w.u - 0.5 * dU;
    const double uRight = w.u + 0.5 * dU;
    const double divergence = (area_[k + 1] * uRight - area_[k] * uLeft) * inverseVolume_[k];
    const double rhoDot = -(w.u * dRho * invDr + w.rho * divergence);
    const double uDot = -(w.u * dU + dP / w.rho) * invDr;
    const double pDot = -(w.u * dP * invDr + g * w.p * divergence);
    const Primitive shift{halfDt * rhoDot, halfDt * uDot, halfDt * pDot};
    faceL_[k] = {w.rho - 0.5 * dRho + shift.rho, uLeft + shift.u, w.p - 0.5 * dP + shift.p};
    faceR_[k] = {w.rho + 0.5 * dRho + shift.rho, uRight + shift.u, w.p + 0.5 * dP + shift.p};
    pressureSlope_[k] = dP;
  }

  // Fluxes. Face 0: the centre, where the outside state is the mirror image of cell 0's.
  // Face n: transmissive, the outside state equals the inside one.
  const Primitive& centre = faceL_[0];
  flux_[0] = hllc({centre.rho, -centre.u, centre.p}, centre);
  for (int f = 1; f < n; ++f) {
    const auto k = static_cast<std::size_t>(f);
    flux_[k] = hllc(faceR_[k - 1], faceL_[k]);
  }
  const Primitive& edge = faceR_[static_cast<std::size_t>(n - 1)];
  flux_[static_cast<std::size_t>(n)] = hllc(edge, edge);

  // Conservative update with the geometric momentum source.
  const double slopeIntegral = j_ == 3 ? dr_ * dr_ / 6.0 : 0.0;  // int (r - r_mid) dA / dr
  for (int i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const double aL = area_[k], aR = area_[k + 1];
    const Flux& fL = flux_[k];
    const Flux& fR = flux_[k + 1];
    const double pHalf = 0.5 * (faceL_[k].p + faceR_[k].p);
    const double scale = dt * inverseVolume_[k];
    rho_[k] -= scale * (aR * fR.mass - aL * fL.mass);
    // aR fR - aL fL - pHalf (aR - aL), grouped so that a uniform pressure at rest cancels
    // exactly, not merely to round-off: quiescent gas keeps u == 0 bit for bit.
    mom_[k] -= scale * (aR * (fR.momentum - pHalf) - aL * (fL.momentum - pHalf) -
                        pressureSlope_[k] * slopeIntegral);
    energy_[k] -= scale * (aR * fR.energy - aL * fL.energy);
  }
}

void RadialRiemannSolution::advanceTo(double t) {
  if (!(t >= time_)) {
    throw std::invalid_argument("RadialRiemannSolution::advanceTo: t is before time()");
  }
  while (time_ < t) {
    double dt = kCfl * dr_ / fillPrimitivesWithGhosts();
    // Land exactly on t; also avoid a sliver of a step right after this one.
    if (time_ + dt >= t) {
      dt = t - time_;
    } else if (time_ + 1.5 * dt > t) {
      dt = 0.5 * (t - time_);
    }
    step(dt);
    time_ = time_ + dt >= t ? t : time_ + dt;
    ++steps_;
  }
}

GasState RadialRiemannSolution::at(double r) const {
  if (!(r >= 0.0 && r <= rMax_)) {
    throw std::invalid_argument("RadialRiemannSolution::at: r outside [0, rMax]");
  }
  const int n = cellCount();
  const double x = r / dr_ - 0.5;  // position in units of cells, 0 at the first centre
  if (x <= 0.0) {
    const Primitive w = cellPrimitive(0);
    return {w.rho, w.u, w.p};
  }
  if (x >= n - 1) {
    const Primitive w = cellPrimitive(n - 1);
    return {w.rho, w.u, w.p};
  }
  const int i = static_cast<int>(x);
  const double s = x - i;
  const Primitive a = cellPrimitive(i);
  const Primitive b = cellPrimitive(i + 1);
  return {a.rho + s * (b.rho - a.rho), a.u + s * (b.u - a.u), a.p + s * (b.p - a.p)};
}

double RadialRiemannSolution::totalMass() const {
  double sum = 0.0;
  for (std::size_t k = 0; k < rho_.size(); ++k) sum += rho_[k] * volume_[k];
  return measureFactor() * sum;
}

double RadialRiemannSolution::totalEnergy() const {
  double sum = 0.0;
  for (std::size_t k = 0; k < energy_.size(); ++k) sum += energy_[k] * volume_[k];
  return measureFactor() * sum;
}

}  // namespace ejecta::exact
