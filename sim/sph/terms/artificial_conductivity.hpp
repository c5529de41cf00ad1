#pragma once
// The artificial conductivity pair term (Price 2008, J. Comput. Phys. 227, 10040): a diffusion of
// specific internal energy across pressure jumps, with signal speed v_sig = sqrt(|P_i - P_j| /
// rho_ij), which smooths the wall-heating spike a contact discontinuity leaves:
//   du_i/dt += sum_j m_j a_u v_sig (u_i - u_j) / sigma_ij dW_ij.
// Antisymmetric in i and j, so the energy it moves is conserved.
#include <cmath>

#include "sim/sph/sph_options.hpp"
#include "sim/sph/terms/pair.hpp"
#include "sim/state/particles.hpp"

namespace ejecta {

class ArtificialConductivity {
 public:
  ArtificialConductivity(const ParticleSet& p, const SphOptions& sph)
      : rho_(p.rho.data()), u_(p.u.data()), P_(p.P.data()), alphaU_(sph.conductivity) {}

  bool enabled() const { return alphaU_ > 0.0; }

  // The pair's contribution to du_i/dt [J/(kg s)], and its signal speed v_sig [m/s] where the
  // pair heats i (u_j > u_i; 0 otherwise): individual time steps limit the step of a particle
  // that conducts heat in by its fastest (sim/run/timestep_criteria.hpp).
  struct Term {
    double rate;
    double inflowSignal;
  };
  Term term(const PairOrigin& o, const Pair& g) const {
    const std::size_t j = g.j;
    const double rhoIJ = 0.5 * (o.rho + rho_[j]);
    const double vsigU = std::sqrt(std::abs(o.P - P_[j]) / rhoIJ);
    return {g.mj * alphaU_ * vsigU * (o.u - u_[j]) / g.sigmaIJ * g.dWavg, u_[j] > o.u ? vsigU : 0.0};
  }

 private:
  const double* rho_;
  const double* u_;
  const double* P_;
  double alphaU_;
};

}  // namespace ejecta
