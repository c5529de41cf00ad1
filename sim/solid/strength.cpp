#include "sim/solid/strength.hpp"

#include <algorithm>
#include <cmath>

namespace ejecta {

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

}  // namespace ejecta
