#pragma once
// The integral approach to derivatives (IAD; García-Senz, Cabezón & Escartín 2012, A&A 538, A9;
// its SPH-EXA form in Cabezón, García-Senz & Figueira 2017, A&A 606, A78): in place of the
// analytic kernel gradient, the pair terms use A_ij = C_i (x_j - x_i) W_ij(h_i), where
//   C_i = tau_i^-1,  tau_i = sum_j V_j W_ij(h_i) (x_j - x_i) (x) (x_j - x_i),  V_j = m_j / rho_j,
// so that sum_j V_j (f_j - f_i) A_ij is the exact gradient of any linear f on any arrangement of
// neighbours (the analytic gradient is exact only on a regular lattice). The momentum and energy
// equations built from it stay pairwise antisymmetric (sim/sph/hydro_force.cpp), so momentum and
// energy are conserved as with the kernel gradient.
#include "sim/sph/hydro_workspace.hpp"
#include "sim/state/particles.hpp"

namespace ejecta {

// Fills ws.iadMatrix for the real particles from their gather lists (after the density pass and
// the ghosts' refresh: it reads the neighbours' densities). A particle whose tau is singular or
// nearly so (its neighbours on a line or a plane) gets C = 0: the pair terms then use the kernel
// gradient for it.
void computeIadMatrices(const ParticleSet& p, HydroWorkspace& ws);

// The D x D inverse of the symmetric tau (row-major 3 x 3, components beyond D ignored) into C;
// false (C all zero) when tau is not positive or its determinant is below 1e-4 of the product of
// its diagonal (neighbours nearly on a line or a plane).
template <int D>
bool invertSymmetric(const double tau[9], double C[9]);

}  // namespace ejecta
