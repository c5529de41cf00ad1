#pragma once
// The numerical uncertainty of one quantity from four or more resolutions by least squares, after
// L. Eça & M. Hoekstra (2014), "A procedure for the estimation of the numerical uncertainty of CFD
// calculations based on grid refinement studies", J. Comput. Phys. 262, 104-130. Three levels
// (grid_convergence.hpp) fix an order exactly and so cannot see scatter: where the two finest
// agree by chance their change, and any band made from it, is small while a further level may lie
// far off. A fit over all levels carries that scatter into the band.
//
// With spacings h_i (x_i = h_i / h_finest) and values phi_i, i = 1..n (n >= 4):
//  1. phi_i = phi_0 + alpha x_i^p by least squares, unweighted and weighted by 1/h_i (finer levels
//     count more); the one with the smaller standard deviation of its residuals is kept:
//       sigma = sqrt( (n / sum w) sum w_i (phi_i - fit_i)^2 / (n - m) ),  m fitted parameters
//     (3 here: phi_0, alpha and p; the normalisation is ejecta's where the paper's was not at hand).
//  2. The error estimate eps = |phi_fit(h_finest) - phi_0| from that fit where the order is
//     reasonable, 0.5 <= p <= p_formal. Below 0.5, from whichever of phi_0 + a x, phi_0 + a x^2
//     and phi_0 + a x + b x^2 fits best (smallest sigma; the paper's set). Above the formal order,
//     from whichever of phi_0 + a x^p_formal and phi_0 + a x + b x^2 fits best: the error cannot
//     fall faster than the scheme lets it. (The paper states its rules for a second-order method,
//     where these are its x^2 and x + x^2; for another formal order they are ejecta's reading.)
//  3. The data range Delta_M = (max phi - min phi) / (n - 1).
//  4. The factor of safety 1.25 where 0.5 <= p < 1.05 p_formal (the paper's [0.5, 2.1) for
//     second order) and sigma < Delta_M, otherwise 3.
//  5. The band on the finest value: U = F_s eps + sigma + |phi_finest - phi_fit(h_finest)| where
//     sigma < Delta_M (a good fit); otherwise U = 3 (sigma / Delta_M) (eps + sigma + |...|).
#include <string>
#include <vector>

namespace ejecta::verify {

struct LeastSquaresUncertainty {
  bool available = false;           // four or more finite levels that are not all equal
  std::string note;                 // why not, or the order and which fit gave the error estimate
  double order = 0.0;               // the least-squares order p (step 1)
  double estimateOrder = 0.0;       // the leading order of the fit that gave eps (step 2)
  bool orderAtSearchBound = false;  // the best p lay at the search's bound (no order in the data)
  bool weighted = false;            // the 1/h-weighted fit was kept
  double extrapolated = 0.0;        // phi_0 of the fit that gave the error estimate
  double errorEstimate = 0.0;       // eps
  double standardDeviation = 0.0;   // sigma
  double dataRange = 0.0;           // Delta_M
  double safetyFactor = 0.0;        // F_s
  double uncertainty = 0.0;         // U, absolute, on the finest value
  bool goodFit = false;             // sigma < Delta_M
};

// `spacings` and `values` in any order (as many of each, at least 4 to be available); spacings
// positive and distinct, as gridConvergence checks. `formalOrder` > 0.
LeastSquaresUncertainty leastSquaresUncertainty(const std::vector<double>& spacings, const std::vector<double>& values,
                                                double formalOrder);

}  // namespace ejecta::verify
