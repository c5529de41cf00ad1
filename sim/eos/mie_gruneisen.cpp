#include "sim/eos/mie_gruneisen.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "core/join.hpp"

namespace ejecta {

namespace {

// Sound-speed floor as a fraction of the reference speed: in deep tension the analytic c^2 can
// turn negative; SPH's time step and viscosity need a real, positive c. Every physical state
// has c well above 1e-3 C0, so the floor never touches one.
constexpr double kSoundFloorFraction = 1e-3;

// Denominator of the Hugoniot in eta = 1 - rho0/rho = up/Us: D(eta) = 1 - S1 eta - S2 eta^2 -
// S3 eta^3, so that P_H = rho0 C0^2 eta / D^2 (Us D = C0).
double hugoniotDenominatorEta(const ShockMaterial& m, double eta) {
  return 1.0 - eta * (m.s1 + eta * (m.s2 + eta * m.s3));
}

// First zero of D(eta) in (0, 1), converted to mu = eta / (1 - eta); +inf when there is none.
double limitingCompression(const ShockMaterial& m) {
  constexpr int kScan = 10000;
  double lo = 0.0;
  for (int i = 1; i < kScan; ++i) {
    const double hi = static_cast<double>(i) / kScan;
    if (hugoniotDenominatorEta(m, hi) > 0.0) {
      lo = hi;
      continue;
    }
    double a = lo, b = hi;
    for (int it = 0; it < 100; ++it) {
      const double mid = 0.5 * (a + b);
      (hugoniotDenominatorEta(m, mid) > 0.0 ? a : b) = mid;
    }
    const double eta = 0.5 * (a + b);
    return eta / (1.0 - eta);
  }
  return std::numeric_limits<double>::infinity();
}

void requirePositive(double value, const char* what) {
  if (!(value > 0.0) || !std::isfinite(value))
    throw std::invalid_argument(std::string(what) + " must be positive and finite");
}

// The library. Each entry's `source` names the primary reference; docs/eos_shock_jwl.md tabulates
// them with the seed's printed values and what could be checked in this repository's session.
const std::vector<ShockMaterial>& library() {
  static const std::vector<ShockMaterial> lib = {
      // Water: cubic Us-up fit. Seed Table 3.1 prints C = "18.0 GPa" (the Tillotson A of Table
      // 3.2 pasted in), S2 = +1.986, S3 = 1.2268, gamma0 = 0.5, a = 0.
      {"water", 1000.0, 1480.0, 2.56, -1.986, 0.2268, 0.4934, 1.3937,
       "Steinberg (1987), UCID-20974, water as used with LS-DYNA *EOS_GRUNEISEN; not verified "
       "against the report in this session (see docs/eos_shock_jwl.md)"},
      // Al-2024: seed Table 5.1 prints C0 = 53258 and scrambles the gamma0 / slope rows.
      {"Al-2024", 2785.0, 5328.0, 1.338, 0.0, 0.0, 2.00, 0.48,
       "Steinberg (1996), UCRL-MA-106439, 2024 Al: rho0 2.785 g/cc, C0 0.5328 cm/us, S1 1.338, "
       "gamma0 2.00, b 0.48; not verified against the report in this session"},
      // Al-1100: the seed gives only the density (2701) and reuses the 2024 numbers.
      {"Al-1100", 2707.0, 5386.0, 1.339, 0.0, 0.0, 1.97, 0.48,
       "Steinberg (1996), UCRL-MA-106439, 1100-O Al: rho0 2.707 g/cc, C0 0.5386 cm/us, S1 1.339, "
       "gamma0 1.97, b 0.48; read in a transcription of the table (FronTier's mg-eos.c), not in "
       "the report itself"},
      {"copper", 8930.0, 3940.0, 1.489, 0.0, 0.0, 2.02, 0.47,
       "Steinberg (1996), UCRL-MA-106439, OFHC Cu: rho0 8.93, C0 0.394 cm/us, S1 1.489, gamma0 "
       "2.02, b 0.47; C0, S1, b agree with the Altair Radioss /EOS/GRUNEISEN copper example "
       "(LS-DYNA example 46 deck, which uses rho0 8.96, gamma0 1.97)"},
  };
  return lib;
}

}  // namespace

const ShockMaterial& shockMaterial(std::string_view name) {
  for (const auto& m : library())
    if (m.name == name) return m;
  throw std::invalid_argument("unknown shock-EOS material '" + std::string(name) +
                              "'; known: " + joinList(library(), &ShockMaterial::name));
}

std::vector<std::string> shockMaterialNames() {
  std::vector<std::string> names;
  for (const auto& m : library()) names.push_back(m.name);
  return names;
}

double hugoniotShockVelocity(const ShockMaterial& m, double up) {
  if (up == 0.0) return m.c0;
  // Us^3 - (C0 + S1 up) Us^2 - S2 up^2 Us - S3 up^3 = 0, Newton from the linear estimate.
  const double b = m.c0 + m.s1 * up;
  double us = b;
  for (int it = 0; it < 100; ++it) {
    const double g = ((us - b) * us - m.s2 * up * up) * us - m.s3 * up * up * up;
    const double dg = (3.0 * us - 2.0 * b) * us - m.s2 * up * up;
    const double step = g / dg;
    us -= step;
    if (std::abs(step) <= 1e-15 * std::abs(us)) break;
  }
  return us;
}

HugoniotState hugoniotState(const ShockMaterial& m, double up) {
  HugoniotState h;
  h.up = up;
  h.us = hugoniotShockVelocity(m, up);
  h.rho = m.rho0 * h.us / (h.us - up);
  h.P = m.rho0 * h.us * up;
  h.u = 0.5 * up * up;
  return h;
}

// ----------------------------------------------------------------------------- MieGruneisen

MieGruneisen::MieGruneisen(ShockMaterial material)
    : m_(std::move(material)), muMax_(0.0), csFloor_(0.0) {
  requirePositive(m_.rho0, "Mie-Grueneisen: rho0");
  requirePositive(m_.c0, "Mie-Grueneisen: C0");
  muMax_ = 0.99 * limitingCompression(m_);
  csFloor_ = kSoundFloorFraction * m_.c0;
}

MieGruneisen::State MieGruneisen::state(double rho, double u) const {
  const double rho0 = m_.rho0;
  const double c02 = m_.c0 * m_.c0;
  // Clamp to the fit's range: past the limiting compression the denominator changes sign, and
  // rho -> 0 would divide by zero in P/rho^2.
  const double mu = std::clamp(rho / rho0 - 1.0, -1.0 + 1e-12, muMax_);
  const double rhoEff = rho0 * (1.0 + mu);
  const double dPdu = (m_.gamma0 + m_.a * mu) * rho0;  // = rho Gamma
  double P, dPdrho;
  if (mu > 0.0) {
    const double q = 1.0 + mu;
    const double n = 1.0 + (1.0 - 0.5 * m_.gamma0) * mu - 0.5 * m_.a * mu * mu;
    const double dn = (1.0 - 0.5 * m_.gamma0) - m_.a * mu;
    const double d =
        1.0 - (m_.s1 - 1.0) * mu - m_.s2 * mu * mu / q - m_.s3 * mu * mu * mu / (q * q);
    const double dd = -(m_.s1 - 1.0) - m_.s2 * mu * (2.0 + mu) / (q * q) -
                      m_.s3 * mu * mu * (3.0 + mu) / (q * q * q);
    const double f = rho0 * c02 * mu * n / (d * d);
    const double df = rho0 * c02 * ((n + mu * dn) / (d * d) - 2.0 * mu * n * dd / (d * d * d));
    P = f + dPdu * u;
    dPdrho = df / rho0 + m_.a * u;
  } else {
    P = rho0 * c02 * mu + dPdu * u;
    dPdrho = c02 + m_.a * u;
  }
  return {P, dPdrho + P / (rhoEff * rhoEff) * dPdu};
}

double MieGruneisen::specificEnergy(double rho, double P) const {
  if (!(rho > 0.0)) throw std::domain_error("Mie-Grueneisen: density must be positive");
  const double mu = std::clamp(rho / m_.rho0 - 1.0, -1.0 + 1e-12, muMax_);
  const double dPdu = (m_.gamma0 + m_.a * mu) * m_.rho0;
  if (!(std::abs(dPdu) > 0.0))
    throw std::domain_error("Mie-Grueneisen: pressure does not depend on energy at this density");
  return (P - state(rho, 0.0).P) / dPdu;
}

// ------------------------------------------------------------------------------ Polynomial

PolynomialEosParams polynomialFromShock(const ShockMaterial& m) {
  const double k = m.s1 - 1.0;
  const double n = 1.0 - 0.5 * m.gamma0;
  PolynomialEosParams p;
  p.name = m.name;
  p.rho0 = m.rho0;
  p.a1 = m.rho0 * m.c0 * m.c0;
  p.a2 = p.a1 * (n + 2.0 * k);
  p.a3 = p.a1 * (2.0 * m.s2 + 3.0 * k * k + 2.0 * k * n - 0.5 * m.a);
  p.b0 = m.gamma0;
  p.b1 = m.a;
  p.t1 = p.a1;
  p.t2 = 0.0;
  p.source = "third-order expansion of the Mie-Grueneisen law of " + m.name + " (" + m.source + ")";
  return p;
}

PolynomialEos::PolynomialEos(PolynomialEosParams params) : p_(std::move(params)), csFloor_(0.0) {
  requirePositive(p_.rho0, "polynomial EOS: rho0");
  requirePositive(p_.a1, "polynomial EOS: A1");
  if (p_.t1 == 0.0) p_.t1 = p_.a1;
  csFloor_ = kSoundFloorFraction * std::sqrt(p_.a1 / p_.rho0);
}

PolynomialEos::State PolynomialEos::state(double rho, double u) const {
  const double rho0 = p_.rho0;
  const double mu = std::max(rho / rho0 - 1.0, -1.0 + 1e-12);
  const double rhoEff = rho0 * (1.0 + mu);
  double P, dPdrho, dPdu;
  if (mu > 0.0) {
    dPdu = (p_.b0 + p_.b1 * mu) * rho0;
    P = mu * (p_.a1 + mu * (p_.a2 + mu * p_.a3)) + dPdu * u;
    dPdrho = (p_.a1 + mu * (2.0 * p_.a2 + 3.0 * mu * p_.a3)) / rho0 + p_.b1 * u;
  } else {
    dPdu = p_.b0 * rho0;
    P = mu * (p_.t1 + mu * p_.t2) + dPdu * u;
    dPdrho = (p_.t1 + 2.0 * mu * p_.t2) / rho0;
  }
  return {P, dPdrho + P / (rhoEff * rhoEff) * dPdu};
}

double PolynomialEos::specificEnergy(double rho, double P) const {
  if (!(rho > 0.0)) throw std::domain_error("polynomial EOS: density must be positive");
  const double mu = rho / p_.rho0 - 1.0;
  const double dPdu = (mu > 0.0 ? p_.b0 + p_.b1 * mu : p_.b0) * p_.rho0;
  if (!(std::abs(dPdu) > 0.0))
    throw std::domain_error("polynomial EOS: pressure does not depend on energy at this density");
  return (P - state(rho, 0.0).P) / dPdu;
}

}  // namespace ejecta
