#include "sim/eos/tillotson.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include "core/join.hpp"

namespace ejecta {

namespace {

constexpr double kMJ = 1.0e6;  // J/kg
constexpr double kGPa = 1.0e9;

// Sources and their verification status are in docs/eos_tillotson.md.
const std::array<TillotsonParameters, 5>& libraryTable() {
  static const std::array<TillotsonParameters, 5> table{{
      // Seed Table 3.2 (from Marinova et al. 2011, Icarus 211, 960, who cite Allen 1967); the
      // seed omits rho0: 2680 kg/m^3 is Marinova et al.'s value (unverified against the paper).
      {"granite", 2680.0, 18.0 * kGPa, 18.0 * kGPa, 16.0 * kMJ, 3.5 * kMJ, 18.0 * kMJ, 0.5, 1.3,
       5.0, 5.0,
       "seed Table 3.2 = Marinova et al. (2011) Icarus 211, 960 (after Allen 1967); "
       "rho0 not in the seed's table"},
      // Benz & Asphaug (1999), Icarus 142, 5, Table II (cgs there: A = 2.67e11 erg/cm^3,
      // E0 = 4.87e12 erg/g, Eiv = 4.72e10 erg/g, Ecv = 1.82e11 erg/g).
      {"basalt", 2700.0, 26.7 * kGPa, 26.7 * kGPa, 487.0 * kMJ, 4.72 * kMJ, 18.2 * kMJ, 0.5, 1.5,
       5.0, 5.0, "Benz & Asphaug (1999) Icarus 142, 5, Table II"},
      // Benz & Asphaug (1999), Table II (A = B = 9.47e10 erg/cm^3, E0 = 1.0e11 erg/g,
      // Eiv = 7.73e9 erg/g, Ecv = 3.04e10 erg/g).
      {"ice", 917.0, 9.47 * kGPa, 9.47 * kGPa, 10.0 * kMJ, 0.773 * kMJ, 3.04 * kMJ, 0.3, 0.1, 10.0,
       5.0, "Benz & Asphaug (1999) Icarus 142, 5, Table II"},
      // Tillotson (1962) GA-3216 iron: rho0 = 7.8 g/cm^3, A = 1.279 Mbar (rounded to 128 GPa),
      // B = 1.05 Mbar, E0 = 0.741 Mbar cm^3/cm^3 / rho0 = 9.5 MJ/kg, Es = 0.190 Mbar / rho0 =
      // 2.44 MJ/kg; Eiv = 2.4, Ecv = 8.67 MJ/kg as in Melosh (1989) Table AII.3 (Ecv unverified).
      {"iron", 7800.0, 128.0 * kGPa, 105.0 * kGPa, 9.5 * kMJ, 2.4 * kMJ, 8.67 * kMJ, 0.5, 1.5, 5.0,
       5.0, "Tillotson (1962) GA-3216; Eiv/Ecv per Melosh (1989) Table AII.3 (Ecv unverified)"},
      // Tillotson (1962) aluminium: rho0 = 2.7 g/cm^3, A = 0.752 Mbar, B = 0.65 Mbar, b = 1.63,
      // E0 = 0.135 Mbar / rho0 = 5.0 MJ/kg. Eiv/Ecv = 2.7/14.1 MJ/kg from Benz's Tillotson table
      // (Tillotson's own sublimation energy is 0.081 Mbar / rho0 = 3.0 MJ/kg); unverified.
      {"aluminium", 2700.0, 75.2 * kGPa, 65.0 * kGPa, 5.0 * kMJ, 2.7 * kMJ, 14.1 * kMJ, 0.5, 1.63,
       5.0, 5.0,
       "Tillotson (1962) GA-3216; Eiv/Ecv from Benz's Tillotson table (unverified)"},
  }};
  return table;
}

void validate(const TillotsonParameters& p, const TillotsonOptions& o) {
  // The first constraint that fails, with its value, so the message says which parameter to fix.
  auto require = [&](bool ok, const char* rule, double value) {
    if (ok) return;
    char got[48];
    std::snprintf(got, sizeof got, "%.6g", value);
    throw std::invalid_argument("tillotson '" + p.name + "': " + rule + " (got " + got + ")");
  };
  require(p.rho0 > 0.0 && std::isfinite(p.rho0), "rho0 must be positive", p.rho0);
  require(p.A > 0.0 && std::isfinite(p.A), "A must be positive", p.A);
  require(p.B >= 0.0 && std::isfinite(p.B), "B must be >= 0", p.B);
  require(p.E0 > 0.0 && std::isfinite(p.E0), "E0 must be positive", p.E0);
  require(p.a > 0.0 && std::isfinite(p.a), "a must be positive", p.a);
  require(p.b >= 0.0 && std::isfinite(p.b), "b must be >= 0", p.b);
  require(p.alpha >= 0.0 && std::isfinite(p.alpha), "alpha must be >= 0", p.alpha);
  require(p.beta >= 0.0 && std::isfinite(p.beta), "beta must be >= 0", p.beta);
  require(p.Eiv >= 0.0 && std::isfinite(p.Eiv), "Eiv must be >= 0", p.Eiv);
  require(p.Ecv > p.Eiv && std::isfinite(p.Ecv), "Ecv must be finite and above Eiv", p.Ecv);
  require(o.soundSpeedFloorFraction > 0.0, "the sound-speed floor must be positive", o.soundSpeedFloorFraction);
  require(!std::isnan(o.minimumPressure), "the minimum pressure must not be NaN", o.minimumPressure);
}

}  // namespace

const TillotsonParameters& tillotsonLibrary(std::string_view name) {
  for (const auto& entry : libraryTable()) {
    if (entry.name == name) return entry;
  }
  throw std::invalid_argument("unknown Tillotson material '" + std::string(name) +
                              "'; known: " + joinList(libraryTable(), &TillotsonParameters::name));
}

std::vector<std::string> tillotsonLibraryNames() {
  std::vector<std::string> names;
  for (const auto& entry : libraryTable()) names.push_back(entry.name);
  return names;
}

Tillotson::Tillotson(TillotsonParameters parameters, TillotsonOptions options)
    : par_(std::move(parameters)), opt_(options) {
  validate(par_, opt_);
  cs2Min_ = opt_.soundSpeedFloorFraction * par_.A / par_.rho0;
}

Tillotson::Region Tillotson::region(double rho, double u) const {
  if (rho >= par_.rho0) return Region::Compressed;
  if (u <= par_.Eiv) return Region::ColdExpanded;
  return u >= par_.Ecv ? Region::HotExpanded : Region::Hybrid;
}

// Compressed / cold branch: P = (a + b s) rho u + A mu + B mu^2, s = 1 / (u/(E0 eta^2) + 1).
// ds/drho = 2 s (1 - s) / rho, so d(b s rho u)/drho = b u s (3 - 2 s); d(s u)/du = s^2.
Tillotson::State Tillotson::cold(double rho, double u) const {
  const double eta = rho / par_.rho0;
  const double mu = eta - 1.0;
  const double s = 1.0 / (u / (par_.E0 * eta * eta) + 1.0);
  const double B = (mu >= 0.0 || opt_.quadraticTermWhenExpanded) ? par_.B : 0.0;
  State st;
  st.P = (par_.a + par_.b * s) * rho * u + par_.A * mu + B * mu * mu;
  st.dPdrho = par_.a * u + par_.b * u * s * (3.0 - 2.0 * s) + (par_.A + 2.0 * B * mu) / par_.rho0;
  st.dPdu = rho * (par_.a + par_.b * s * s);
  return st;
}

// Hot expanded branch: P = a rho u + (b rho u s + A mu X) H, z = rho0/rho - 1, X = exp(-beta z),
// H = exp(-alpha z^2); dz/drho = -rho0/rho^2.
Tillotson::State Tillotson::hot(double rho, double u) const {
  const double eta = rho / par_.rho0;
  const double mu = eta - 1.0;
  const double s = 1.0 / (u / (par_.E0 * eta * eta) + 1.0);
  const double z = par_.rho0 / rho - 1.0;
  const double H = std::exp(-par_.alpha * z * z);
  State st{par_.a * rho * u, par_.a * u, par_.a * rho};
  if (H == 0.0) return st;  // far expanded: ideal gas; skips inf * 0 below
  const double X = std::exp(-par_.beta * z);
  const double F = par_.b * rho * u * s;
  const double G = par_.A * mu * X;
  const double dzdrhoNeg = par_.rho0 / (rho * rho);  // -dz/drho
  const double dF = par_.b * u * s * (3.0 - 2.0 * s);
  const double dG = par_.A * X * (1.0 / par_.rho0 + mu * par_.beta * dzdrhoNeg);
  const double dH = H * 2.0 * par_.alpha * z * dzdrhoNeg;
  st.P += (F + G) * H;
  st.dPdrho += H * (dF + dG) + (F + G) * dH;
  st.dPdu += H * par_.b * rho * s * s;
  return st;
}

Tillotson::State Tillotson::state(double rho, double u) const {
  // Negative u (unphysical; flagged by the run's health check) is evaluated as u = 0, and
  // rho <= 0 at a vanishing density, so that no branch divides by zero.
  u = std::max(u, 0.0);
  rho = std::max(rho, 1.0e-12 * par_.rho0);
  switch (region(rho, u)) {
    case Region::Compressed:
    case Region::ColdExpanded:
      return cold(rho, u);
    case Region::HotExpanded:
      return hot(rho, u);
    case Region::Hybrid:
      break;
  }
  // Linear in u between the two branches (seed eq. 2.3); the weight's u-derivative adds
  // (Ph - Pc)/(Ecv - Eiv) to dP/du.
  const State c = cold(rho, u);
  const State h = hot(rho, u);
  const double span = par_.Ecv - par_.Eiv;
  const double w = (u - par_.Eiv) / span;
  return {(1.0 - w) * c.P + w * h.P, (1.0 - w) * c.dPdrho + w * h.dPdrho,
          (1.0 - w) * c.dPdu + w * h.dPdu + (h.P - c.P) / span};
}

void Tillotson::pressureAndSoundSpeed(double rho, double u, double& P, double& cs) const {
  const State st = state(rho, u);
  const double r = std::max(rho, 1.0e-12 * par_.rho0);
  if (st.P < opt_.minimumPressure) {
    // Clamped pressure is flat in rho and u: no restoring force, only the floor speed.
    P = opt_.minimumPressure;
    cs = std::sqrt(cs2Min_);
    return;
  }
  P = st.P;
  // c^2 = dP/drho|_s = dP/drho|_u + (P / rho^2) dP/du|_rho, since du = (P / rho^2) drho at
  // constant entropy.
  const double c2 = st.dPdrho + st.P / (r * r) * st.dPdu;
  cs = std::sqrt(c2 > cs2Min_ ? c2 : cs2Min_);  // also maps a NaN c2 to the floor
}

void Tillotson::evaluate(const double* rho, const double* u, double* P, double* cs,
                         const std::size_t* indices, std::size_t n) const {
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = indices[k];
    pressureAndSoundSpeed(rho[i], u[i], P[i], cs[i]);
  }
}

double Tillotson::pressure(double rho, double u) const {
  double P = 0.0;
  double cs = 0.0;
  pressureAndSoundSpeed(rho, u, P, cs);
  return P;
}

double Tillotson::soundSpeed(double rho, double u) const {
  double P = 0.0;
  double cs = 0.0;
  pressureAndSoundSpeed(rho, u, P, cs);
  return cs;
}

namespace {

// Root of f on [lo, hi] with f(lo) < 0 <= f(hi): Newton steps, falling back to bisection when a
// step leaves the bracket. The bracket shrinks every iteration, so this always terminates.
template <class F>
double solveBracketed(F f, double lo, double hi) {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  double x = 0.5 * (lo + hi);
  for (int it = 0; it < 200; ++it) {
    const auto [value, slope] = f(x);
    if (value == 0.0) return x;
    (value < 0.0 ? lo : hi) = x;
    const double newton = x - value / slope;
    const bool inside = slope > 0.0 && newton > lo && newton < hi;
    if (inside && std::abs(newton - x) <= 2.0 * eps * std::abs(x)) return newton;
    x = inside ? newton : 0.5 * (lo + hi);
    if (hi - lo <= 2.0 * eps * std::max(hi, 1.0)) return x;
  }
  return x;
}

}  // namespace

double Tillotson::specificEnergy(double rho, double P) const {
  if (!(rho > 0.0) || !std::isfinite(rho) || !std::isfinite(P)) {
    throw std::domain_error("tillotson: specificEnergy needs a positive density, finite pressure");
  }
  if (P < opt_.minimumPressure) {
    throw std::domain_error("tillotson: pressure below the configured minimum pressure");
  }
  const auto f = [&](double u) {
    const State st = state(rho, u);
    return std::pair<double, double>{st.P - P, st.dPdu};
  };
  const double atZero = f(0.0).first;
  if (atZero > 0.0) {
    throw std::domain_error("tillotson: pressure below the cold curve P(rho, u = 0)");
  }
  if (atZero == 0.0) return 0.0;
  // P rises with u on each branch; only the hybrid interpolation can turn back, so it is
  // sampled finely to find the smallest root.
  std::vector<double> knots{0.0};
  if (rho < par_.rho0) {
    knots.push_back(par_.Eiv);
    for (int k = 1; k <= 32; ++k) knots.push_back(par_.Eiv + (par_.Ecv - par_.Eiv) * k / 32.0);
  }
  for (std::size_t k = 1; k < knots.size(); ++k) {
    if (f(knots[k]).first >= 0.0) return solveBracketed(f, knots[k - 1], knots[k]);
  }
  // Last branch is unbounded: P grows at least like a rho u, so doubling finds a bracket.
  double lo = knots.back();
  double hi = std::max({2.0 * lo, par_.E0, par_.Ecv});
  while (f(hi).first < 0.0) {
    lo = hi;
    hi *= 2.0;
    if (!std::isfinite(hi)) throw std::domain_error("tillotson: no energy reaches that pressure");
  }
  return solveBracketed(f, lo, hi);
}

}  // namespace ejecta
