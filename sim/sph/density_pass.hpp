#pragma once
// The density pass: for every real particle, its gather list, the kernel-summed density (or the
// continuity rate), the smoothing length when tied to the density, the grad-h factor omega, and
// the velocity divergence and curl.
//
// Summation:   rho_i = sum_j m_j W(x_ij, h_i)                     (planar, 1D, 3D)
//              eta_i = sum_j m_j W(x_ij, h_i), rho_i = eta_i / (2 pi rt_i)   (RZ, ring masses)
// Continuity:  d rho_i / dt = sum_j m_j v_ij . grad_i W_ij            (the seed's eq. 1.1)
// Smoothing length "neighbours": h_i = eta_h (m_i / rho_i)^(1/d), solved jointly with the
//              summation by Newton iteration (Springel & Hernquist 2002; Price 2012, sec. 2.4);
//              omega_i = 1 + h_i / (d rho_i) sum_j m_j dW/dh.
// Smoothing length "seed": dh/dt = -h/(rho d) d rho/dt (eq. 1.3), applied with relaxation theta.
// Generalised volume elements (SphOptions::volumeElements; Hopkins 2013): every m_j above is
//              X_j = m_j r_j, r = (m / rho)^p / m from the density before the pass, so that
//              rho_i = m_i sum_j X_j W / X_i and h_i = eta_h (X_i / sum_j X_j W)^(1/d).
#include <cstdint>
#include <optional>
#include <vector>

#include "sim/sph/hydro_workspace.hpp"
#include "sim/state/particles.hpp"

namespace ejecta {

// Requires: ghosts made (positions, velocities, masses, h). Produces the quantities above for
// real particles and fills ws.lists' gather lists. Returns the lowest index of a particle whose
// kernel-summed (or integrated) density is not positive, if any; the caller reports it.
// With `active` (individual time steps) only the listed particles are summed; the others keep
// their values (RZ: their smoothed radius and area density are brought to their present state).
std::optional<std::size_t> runDensityPass(ParticleSet& p, HydroWorkspace& ws,
                                          const std::vector<std::size_t>* active = nullptr);

// True when the pass sets h (summation density with the "neighbours" method: h iterated with
// the density); otherwise h is the integrator's and the pass leaves it as it was.
inline bool densityPassSetsSmoothingLength(const SphOptions& sph) {
  return sph.density == DensityMethod::Summation && sph.smoothingLength == SmoothingLengthMethod::Neighbours;
}

// Generalised volume elements: r_i = X_i / m_i = m_i^(p-1) rho_i^(-p) of every real particle from
// its present density (p = sph.volumeExponent), then of every boundary ghost from its source,
// into ws.volumeWeight (the density and force passes read it). `real` keeps the real particles'
// values across a pass that is repeated with wider ghost layers.
std::vector<double> volumeWeightsOf(const ParticleSet& p, double exponent);
void placeVolumeWeights(const ParticleSet& p, const std::vector<double>& real, HydroWorkspace& ws);

// Smoothing length for the "neighbours" method from a density (continuity mode): h from the
// particle's own mass and density, held at its cap (HydroWorkspace::hCap).
void setSmoothingFromDensity(ParticleSet& p, const HydroWorkspace& ws);

}  // namespace ejecta
