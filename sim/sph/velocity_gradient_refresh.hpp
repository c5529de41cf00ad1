#pragma once
// Individual time steps with a reconstructed Riemann dissipation: the velocity gradients of the
// inactive particles an active one's pairs read, re-evaluated at the present state.
//
// On time bins the density pass evaluates only the active particles, so an inactive neighbour's
// gradient is the one of its last evaluation while its velocity is predicted to now: across a
// front that moves between its evaluations the two disagree, and the reconstructed jump is wrong
// (docs/time_steps.md, "Godunov SPH on time bins": with the stale gradients the bins lost 10% in
// L1(rho) on the seed's RZ Sedov and the energy error grew to 8e-3). Re-evaluating them costs a
// gather per such neighbour; their density, h and the rest stay as predicted.
#include <cstddef>
#include <vector>

#include "sim/sph/hydro_workspace.hpp"
#include "sim/state/particles.hpp"

namespace ejecta {

// The real particles whose gradient the pairs of `active` read and that the density pass did not
// evaluate: inactive partners, and the inactive sources of the ghosts among the partners.
// Requires the active particles' pairs (ws.lists.pairs). Ascending.
std::vector<std::size_t> inactivePartners(const ParticleSet& p, const HydroWorkspace& ws,
                                          const std::vector<std::size_t>& active);

// ws.velocityGradient of each particle in `particles` from its gather list at the present
// positions and velocities, as the density pass computes it (corrected, limited as the scene's
// reconstruction says). Requires ws.grid over every particle, ghosts included.
void refreshVelocityGradients(const ParticleSet& p, HydroWorkspace& ws,
                              const std::vector<std::size_t>& particles);

}  // namespace ejecta
