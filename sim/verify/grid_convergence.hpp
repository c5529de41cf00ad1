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
//
// The factor 1.25 is for levels in the asymptotic range. Where they are not (the changes
// alternate in sign, grow as the spacing shrinks (no converging power of h gives a finer change
// e21 / e32 >= ln r21 / ln r32), the order does not settle or cannot be found from two equal coarse values,
// or it is below 0.5 or above twice the method's formal order, faster than the scheme's
// truncation error can fall) the band is Roache's fallback (P. J. Roache 2011, J. Fluids Eng.
// 133, 115501: "if p_RE is unreasonable one at least reverts to using p_th and FS = 3"):
// GCI = 3 |(phi1 - phi2) / phi1| / (r21^p - 1) with the formal order, or the observed one where
// that is lower (a slower convergence is not sped up); and where the changes alternate, at least
// half the spread of the three levels (Stern, Wilson, Coleman & Paterson 2001, J. Fluids Eng.
// 123, 793: the oscillation's half amplitude).
//
// With four or more levels, all of them are fitted by least squares too (Eca & Hoekstra 2014,
// least_squares_uncertainty.hpp). The three finest are in the asymptotic range only where the fit
// agrees (its order within the same limits, its residuals below the data range), and the band is
// the wider of the two: three levels fix an order exactly and cannot see the scatter a fourth
// shows, so a band from the two finest alone can understate where they agree by chance. Where
// the three finest alternate, the fit's band replaces the fallback (at least half their spread):
// the fallback bounds a monotone sequence, and on a swing it only scales the last change.
#include <string>
#include <vector>

#include "sim/verify/least_squares_uncertainty.hpp"

namespace ejecta::verify {

enum class UncertaintyBasis {
  None,            // no band: a value is not finite, or the two finest values are equal and
                   // there are only three levels (with more, the fit over all gives the band)
  ObservedOrder,   // Celik et al.: the observed order, factor of safety 1.25
  FormalFallback,  // Roache's fallback: the formal (or a lower observed) order, factor of safety 3
  LeastSquares,    // Eca & Hoekstra's fit over four or more levels, where its band is the wider
};

struct GridConvergence {
  bool valid = false;                 // an order was found (needs 3 levels and e21 != 0)
  std::string note;                   // why not, or a remark (oscillatory, order out of range)
  double order = 0.0;                 // observed order p
  double extrapolated = 0.0;          // phi_ext from the two finest (meaningful when asymptotic)
  double relativeChange = 0.0;        // |(phi1 - phi2) / phi1|
  double extrapolatedError = 0.0;     // |(phi_ext - phi1) / phi_ext|
  double gci = 0.0;                   // the band relative to |phi1| (by `basis`)
  double uncertainty = 0.0;           // gci |phi1|: the band on the finest value
  bool oscillatory = false;           // s < 0
  bool asymptotic = false;            // monotone, the order settled and within [0.5, 2 p_formal],
                                      // and with four or more levels the fit agrees
  double formalOrder = 1.0;           // the method's order the check and the fallback use
  double bandOrder = 0.0;             // the order the band was computed with (least squares: the fitted one)
  UncertaintyBasis basis = UncertaintyBasis::None;
  bool bandAtHalfSpread = false;      // oscillating: the band is half the three finest's spread,
                                      // which the basis's own band fell short of
  LeastSquaresUncertainty leastSquares;  // over all levels (available with four or more)
};

// `spacings` and `values` in any order of resolution (at least 3 pairs; with more, the three
// finest give the order and the extrapolation, and all of them the least-squares check and
// band). `formalOrder`: the method's order for the quantity (1 for SPH across shocks,
// the default; 2 for smooth flow). Throws std::invalid_argument for mismatched sizes, fewer
// than three levels, non-positive or repeated spacings, or a non-positive formal order.
GridConvergence gridConvergence(std::vector<double> spacings, std::vector<double> values,
                                double formalOrder = 1.0);

// "observed order" / "formal-order fallback" / "least squares" / "none": for outputs.
const char* uncertaintyBasisName(UncertaintyBasis basis);

// What the band is, for labels: "GCI band (observed order 1.9, factor of safety 1.25)",
// "fallback band (order 1, factor of safety 3)", "least-squares band over 5 levels (factor of
// safety 3)", or, where half the three finest's spread was the wider, that ("half the three
// finest's spread, wider than the fallback band (...)"); "" without a band. `levels`: how many
// went in.
std::string describeBand(const GridConvergence& g, std::size_t levels);

}  // namespace ejecta::verify
