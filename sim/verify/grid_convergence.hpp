#pragma once
// Grid convergence of one quantity over three or more resolutions: the observed order, the
// Richardson-extrapolated value and the Grid Convergence Index, by the procedure of Celik,
// Ghia, Roache, Freitas, Coleman & Raad (2008), "Procedure for estimation and reporting of
// uncertainty due to discretization in CFD applications", J. Fluids Eng. 130, 078001 (the ASME
// V&V 20 practice, after Roache 1998, "Verification and Validation in Computational Science and
// Engineering"). For SPH the "grid size" h is the particle spacing.
//
// With three spacings h1 < h2 < h3 (fine to coarse) and values phi1, phi2, phi3:
//   r21 = h2 / h1, r32 = h3 / h2, e21 = phi2 - phi1, e32 = phi3 - phi2, s = sign(e32 / e21);
//   p = |ln|e32 / e21| + q(p)| / ln r21,  q(p) = ln((r21^p - s) / (r32^p - s))  (fixed point);
//   phi_ext = (r21^p phi1 - phi2) / (r21^p - 1);
//   GCI_fine = 1.25 |(phi1 - phi2) / phi1| / (r21^p - 1)  (the factor 1.25 for three grids).
// s < 0 is oscillatory convergence: the procedure still applies but the result is flagged.
#include <optional>
#include <string>
#include <vector>

namespace ejecta::verify {

struct GridConvergence {
  bool valid = false;                 // an order was found (needs 3 levels and e21 != 0)
  std::string note;                   // why not, or a remark (oscillatory, order out of range)
  double order = 0.0;                 // observed order p
  double extrapolated = 0.0;          // phi_ext from the two finest
  double relativeChange = 0.0;        // |(phi1 - phi2) / phi1|
  double extrapolatedError = 0.0;     // |(phi_ext - phi1) / phi_ext|
  double gci = 0.0;                   // GCI_fine, relative to |phi1|
  double uncertainty = 0.0;           // gci |phi1|: the band on the finest value
  bool oscillatory = false;           // s < 0
};

// `spacings` and `values` in any order of resolution (at least 3 pairs; with more, the three
// finest are used). Throws std::invalid_argument for mismatched sizes, fewer than three levels,
// non-positive or repeated spacings.
GridConvergence gridConvergence(std::vector<double> spacings, std::vector<double> values);

}  // namespace ejecta::verify
