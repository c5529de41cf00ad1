#pragma once
// The artificial viscosity pair term: Monaghan's Pi_ij (seed eqs. 1.6-1.7; Monaghan 1992) on
// approaching pairs, with the options a scene may add, each owned here:
//   - the Balsara (1995) shear limiter: Pi_ij times the mean of |div v|/(|div v|+|curl v|+...);
//   - the Morris & Monaghan (1997) switch: alpha per particle, alpha_ij the pair's mean and
//     beta_ij = (beta/alpha_max) alpha_ij, with its source term viscositySwitchRate();
//   - the limited linear reconstruction of the linear term (sim/sph/velocity_reconstruction.hpp).
// Symmetric in i and j, so the momentum and energy it exchanges are conserved.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "sim/sph/hydro_workspace.hpp"
#include "sim/sph/terms/pair.hpp"
#include "sim/sph/velocity_reconstruction.hpp"
#include "sim/state/particles.hpp"

namespace ejecta {

template <int D>
class MonaghanViscosity {
 public:
  // Holds what it needs of the particles `which`; the rest (halos still in flight) come by refresh.
  MonaghanViscosity(const ParticleSet& p, const HydroWorkspace& ws, TermParticles which)
      : cs_(p.cs.data()),
        alpha_(ws.sph.alpha),
        beta_(ws.sph.beta),
        epsilon_(ws.sph.epsilon),
        betaPerAlpha_(ws.sph.alpha > 0.0 ? ws.sph.beta / ws.sph.alpha : 0.0),
        balsara_(ws.sph.balsara),
        reconstruct_(ws.sph.viscosityReconstruction != ViscosityReconstruction::None) {
    if (ws.sph.viscositySwitch != ViscositySwitch::None) {
      if (!p.hasViscositySwitch())
        throw std::logic_error("viscosity switch on but the particles carry no alpha");
      switchAlpha_ = p.alpha.data();  // ghosts carry their source's alpha (a halo field)
    }
    refresh(p, which);
    if (reconstruct_) gradient_ = ws.velocityGradient.data();
  }

  // Computes what it holds of the particles `which` (halos whose values arrived).
  void refresh(const ParticleSet& p, TermParticles which) {
    if (!balsara_) return;
    // Real and ghost particles share their source's div v and curl v.
    shearFactor_.resize(p.size());
#pragma omp parallel for schedule(static)
    for (std::size_t k = 0; k < which.count(); ++k) {
      const std::size_t i = which[k];
      const double div = std::abs(p.divv[i]);
      shearFactor_[i] = div / (div + p.curlv[i] + 1e-4 * p.cs[i] / p.h[i] + 1e-300);
    }
  }

  // Pi_ij / sigma_ij: the pair's viscous pressure over density squared [m^2/s^2 per (kg/m^3)
  // in 3D] (its force is m_j Pi_ij dW/dr x_ij / r); 0 for a receding pair.
  double coefficient(const PairOrigin& o, const Pair& g) const {
    if (!(g.vdotx < 0.0)) return 0.0;  // receding (or a NaN, which the health check reports)
    const std::size_t i = o.i, j = g.j;
    const double cij = 0.5 * (o.cs + cs_[j]);
    const double hij = 0.5 * (o.h + g.hj);
    const double mu = hij * g.vdotx / (g.r2 + epsilon_ * hij * hij);
    // Reconstructed: the linear term sees the approach of the velocities carried to the
    // midpoint, kept between the raw approach and zero, so the reconstruction only ever takes
    // viscosity away and the force stays continuous as a pair turns from approaching to
    // receding (test: the quarter box). The quadratic term keeps the raw approach: it is the
    // strong-shock term (negligible at a weak shock, where the linear term's width is the
    // problem), and without it the noise behind a strong blast grows (docs/undex.md).
    const double muLinear =
        reconstruct_ ? mu * std::clamp(reconstructedApproach<D>(g.dx, g.dv, &gradient_[9 * i],
                                                                &gradient_[9 * j]) /
                                           g.vdotx,
                                       0.0, 1.0)
                     : mu;
    const double alphaIJ = switchAlpha_ ? 0.5 * (switchAlpha_[i] + switchAlpha_[j]) : alpha_;
    const double betaIJ = switchAlpha_ ? betaPerAlpha_ * alphaIJ : beta_;
    double visc = (-alphaIJ * cij * muLinear + betaIJ * mu * mu) / g.sigmaIJ;
    if (balsara_) visc *= 0.5 * (shearFactor_[i] + shearFactor_[j]);
    return visc;
  }

 private:
  const double* cs_;
  double alpha_, beta_, epsilon_, betaPerAlpha_;
  bool balsara_, reconstruct_;
  const double* switchAlpha_ = nullptr;
  const double* gradient_ = nullptr;
  std::vector<double> shearFactor_;
};

// The switch's source (Morris & Monaghan 1997, with the (alpha_max - alpha) growth of Rosswog et
// al. 2000): decay to alpha_min over tau = h/(l c), growth where the flow converges.
inline double viscositySwitchRate(double alpha, double alphaMax, double divv, double cs, double h,
                                  const SphOptions& sph) {
  return -(alpha - sph.alphaMin) * sph.alphaDecay * cs / h + std::max(-divv, 0.0) * (alphaMax - alpha);
}

}  // namespace ejecta
