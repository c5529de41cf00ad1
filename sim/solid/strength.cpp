#include "sim/solid/strength.hpp"

#include <algorithm>
#include <cmath>

namespace ejecta {

double intactRockStrength(const CollinsParameters& c, double P) {
  if (P < 0.0) return std::max(c.cohesion + c.frictionIntact * P, 0.0);
  const double rise = c.frictionIntact * P;
  return c.cohesion + rise / (1.0 + rise / (c.strengthLimit - c.cohesion));
}

double damagedRockStrength(const CollinsParameters& c, double P) {
  const double friction = std::max(c.cohesionDamaged + c.frictionDamaged * P, 0.0);
  return std::min(friction, intactRockStrength(c, P));
}

double rockStrength(const CollinsParameters& c, double P, double D) {
  const double d = std::clamp(D, 0.0, 1.0);
  return (1.0 - d) * intactRockStrength(c, P) + d * damagedRockStrength(c, P);
}

double StrengthModel::flowStress(double epsP, double strainRate, double temperature,
                                 double meltTemperature, double pressure, double damage) const {
  if (temperature >= meltTemperature) return 0.0;
  switch (yield) {
    case YieldModel::Elastic: return std::numeric_limits<double>::infinity();
    case YieldModel::VonMises: return yieldStress;
    case YieldModel::Collins: return rockStrength(collins, pressure, damage);
    case YieldModel::JohnsonCook: break;
  }
  const JohnsonCookParameters& jc = johnsonCook;
  const double hardening = jc.A + jc.B * std::pow(std::max(epsP, 0.0), jc.n);
  // Rates below the reference rate do not soften (the usual floor of ln eps_dot* at 0).
  const double rateRatio = std::max(strainRate / jc.referenceStrainRate, 1.0);
  const double rate = 1.0 + jc.C * std::log(rateRatio);
  double thermal = 1.0;
  if (temperature > jc.roomTemperature) {
    const double homologous =
        (temperature - jc.roomTemperature) / (meltTemperature - jc.roomTemperature);
    thermal = std::max(1.0 - std::pow(homologous, jc.m), 0.0);
  }
  return hardening * rate * thermal;
}

SymTensor jaumannStressRate(const Mat3& L, const SymTensor& S, double G) {
  double e[3][3], w[3][3], s[3][3];
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      e[a][b] = 0.5 * (L[a][b] + L[b][a]);
      w[a][b] = 0.5 * (L[a][b] - L[b][a]);
      s[a][b] = S.at(a, b);
    }
  const double third = (e[0][0] + e[1][1] + e[2][2]) / 3.0;
  SymTensor rate;
  for (int k = 0; k < 6; ++k) {
    const int a = kSymRow[k], b = kSymCol[k];
    // (S W^T + W S)_ab = sum_c S_ac W_bc + W_ac S_cb
    double rot = 0.0;
    for (int c = 0; c < 3; ++c) rot += s[a][c] * w[b][c] + w[a][c] * s[c][b];
    rate[k] = 2.0 * G * (e[a][b] - (a == b ? third : 0.0)) + rot;
  }
  return rate;
}

double equivalentStrainRate(const Mat3& L) {
  double e[3][3];
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) e[a][b] = 0.5 * (L[a][b] + L[b][a]);
  const double third = (e[0][0] + e[1][1] + e[2][2]) / 3.0;
  double sum = 0.0;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      const double dev = e[a][b] - (a == b ? third : 0.0);
      sum += dev * dev;
    }
  return std::sqrt(2.0 / 3.0 * sum);
}

double radialReturn(SymTensor& S, double flow, double G) {
  const double vonMises = std::sqrt(3.0 * secondInvariant(S));
  if (vonMises <= flow) return 0.0;
  const double scale = flow / vonMises;  // flow = 0 (melt) zeroes S
  for (double& c : S.c) c *= scale;
  return (vonMises - flow) / (3.0 * G);
}

const std::vector<StrengthLibraryEntry>& strengthLibrary() {
  auto jc = [](double A, double B, double n, double C, double m) {
    JohnsonCookParameters p;
    p.A = A; p.B = B; p.n = n; p.C = C; p.m = m;
    p.referenceStrainRate = 1.0;
    p.roomTemperature = 294.0;
    return p;
  };
  static const std::vector<StrengthLibraryEntry> entries = {
      // Johnson & Cook (1983), 7th Int. Symp. on Ballistics, Table 1 (reference strain rate
      // 1/s); the seed's Table 5.2 prints the same 2024-T351 set.
      {"Al-2024-T351", 27.6e9, YieldModel::JohnsonCook, 0.0,
       jc(265e6, 426e6, 0.34, 0.015, 1.0), 775.0,
       "Johnson & Cook (1983) Table 1, 2024-T351 aluminium; = seed Table 5.2"},
      {"OFHC-copper", 46.0e9, YieldModel::JohnsonCook, 0.0,
       jc(90e6, 292e6, 0.31, 0.025, 1.09), 1356.0,
       "Johnson & Cook (1983) Table 1, OFHC copper"},
      {"Armco-iron", 81.8e9, YieldModel::JohnsonCook, 0.0,
       jc(175e6, 380e6, 0.32, 0.060, 0.55), 1811.0,
       "Johnson & Cook (1983) Table 1, Armco iron"},
      {"4340-steel", 77.5e9, YieldModel::JohnsonCook, 0.0,
       jc(792e6, 510e6, 0.26, 0.014, 1.03), 1793.0,
       "Johnson & Cook (1983) Table 1, 4340 steel (Rc 30)"},
  };
  return entries;
}

const StrengthLibraryEntry* findStrengthEntry(std::string_view name) {
  for (const StrengthLibraryEntry& e : strengthLibrary())
    if (e.name == name) return &e;
  return nullptr;
}

}  // namespace ejecta
