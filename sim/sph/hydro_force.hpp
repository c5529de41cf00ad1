#pragma once
// The force pass: pressure gradient, Monaghan artificial viscosity and the internal energy
// equation, with the grad-h terms when h is tied to the density (Price 2012, eqs. 35-36):
//   dv_i/dt = -sum_j m_j [ P_i/(Om_i rho_i^2) gradW_ij(h_i) + P_j/(Om_j rho_j^2) gradW_ij(h_j)
//                          + Pi_ij gradW_ij(avg) ]
//   du_i/dt =  P_i/(Om_i rho_i^2) sum_j m_j v_ij . gradW_ij(h_i) + 1/2 sum_j m_j Pi_ij v_ij . gradW
// Pi_ij is the seed's eq. (1.6)-(1.7) (Monaghan 1992) with the optional Balsara (1995) factor.
// With the Morris & Monaghan (1997) switch, alpha is per particle: the pair takes the mean
// alpha_ij = (alpha_i + alpha_j)/2 and beta_ij = (beta/alpha_max) alpha_ij (symmetric in i, j,
// so momentum and energy stay conserved), and the pass also yields
//   d alpha_i/dt = -(alpha_i - alpha_min) l c_i / h_i + max(-div v_i, 0) (alpha_max - alpha_i).
// Optional artificial conductivity (Price 2008): du_i += sum_j m_j a_u v_sig (u_i-u_j)/sigma_ij dW.
// The optional terms are the pair terms of sim/sph/terms/.
// RZ (ring masses, Brookshaw 2003 / Garcia-Senz et al. 2009 area-weighted form): rho^2 becomes
// rho * eta and rho_ij becomes eta_ij; the hoop terms +P_i rt'/(rho_i rt_i) (radial acceleration)
// and -P_i v_r rt'/(rho_i rt_i) (energy) complete the Lagrangian derivation (docs/rz.md).
#include <cstddef>
#include <functional>
#include <vector>

#include "sim/sph/hydro_workspace.hpp"
#include "sim/state/particles.hpp"

namespace ejecta {

// A distributed pass's halos, whose values arrive while the pass runs: entries [first, p.size())
// are other ranks' particles, with their positions and h already here (the pairs were built from
// them) and the rest of their values in flight. The pass sums the real particles none of whose
// pairs is a halo first, calling progress() between slices of them (MPI moves a message only
// inside its calls), then arrive() (which finishes the refresh), then the others. Each
// particle's sum is the one the blocking order gives, term for term: the same bits.
struct HaloArrival {
  std::size_t first = 0;
  std::function<void()> progress;
  std::function<void()> arrive;
};

// Requires: density pass done, EOS evaluated, ghosts refreshed, pair lists built (and, without
// `halos`, the halos refreshed).
// Produces for the real particles a and du_dt; with continuity density drho_dt (and dh_dt for the
// seed's h); with the switch dalpha_dt; for solids dstress_dt and the strain rate.
// With `active` (individual time steps) only the listed real particles are summed, and only
// their pairs need be built; the others keep their derivatives.
void runForcePass(ParticleSet& p, HydroWorkspace& ws, const HaloArrival* halos = nullptr,
                  const std::vector<std::size_t>* active = nullptr);

// The viscosity switch's state, for a run whose scene turns it on and whose particles do not yet
// carry alpha (a new run, or a restart from a snapshot written without it): alpha_min, except
// alpha_max in explosive particles (those with a programmed-burn lighting time), which the
// detonation shock is certain to cross. No-op when the switch is off or alpha is present.
void initialiseViscosityAlpha(ParticleSet& p, const SphOptions& sph);

}  // namespace ejecta
