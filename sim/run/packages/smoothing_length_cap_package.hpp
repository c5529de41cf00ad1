#pragma once
// The smoothing-length cap (sph.h_max_factor): each particle's h is held at most at the factor
// times the h it started with, stored per particle as `smoothing_length_cap` so that the cap
// travels with the particle (between ranks, through restarts). A particle thrown clear of its
// body and rarefied under continuity density otherwise widens its kernel until it spans the body
// it left and the neighbour check stops the run (docs/convergence.md, "Particles thrown clear").
// Spheral holds h below a per-NodeList hmax the same way. The density pass and
// setSmoothingFromDensity apply the cap; nothing evolves.
//
// Under continuity density the package also floors each particle's density at the density
// whose h is the cap (AUTODYN's SPH bounds its density by a minimum density factor the same
// way): a particle far more rarefied than its neighbours takes their mass flux into its own
// small density, and one step can drive it through zero. At its cap the density pass divides
// that flux by the kernel sum instead (sim/sph/density_pass.cpp), so its density changes at
// the rate its neighbours' divergence gives, and rises again if it is compressed.
#include <optional>

#include "sim/run/physics_package.hpp"
#include "sim/sph/axis_correction.hpp"
#include "sim/sph/sph_options.hpp"
#include "sim/state/geometry.hpp"

namespace ejecta {

class SmoothingLengthCapPackage : public PhysicsPackage {
 public:
  static constexpr const char* kCap = "smoothing_length_cap";

  SmoothingLengthCapPackage(const SphOptions& sph, Geometry geometry);

  std::string name() const override { return "smoothing_length_cap"; }
  // The cap of a particle not carrying one yet (a new run; a restart of a run without it) is
  // factor x its present h.
  void registerFields(ParticleSet& p) override;
  // The predicted state held to the caps before h is set from it.
  void afterDrift(ParticleSet& p, const PackageContext& c) override;
  // Each h held at its cap (an h integrated by the seed's dh/dt or predicted between an
  // individual step's ends can pass it) and, under continuity density, each density at its
  // floor; finite values only, so a NaN still reaches the health check. The run calls it
  // before every equation-of-state evaluation (sim/run/simulation.cpp).
  void holdToCaps(ParticleSet& p, const ParticleMask* only) const;

  // The caps of the real particles (the column's first numReal entries), or nullptr when `p`
  // carries none. Valid until `p` is resized (ghosts added or dropped).
  static const double* caps(const ParticleSet& p);

 private:
  double factor_;
  double eta_;
  bool continuity_;
  Geometry geometry_;
  std::optional<AxisCorrection> axis_;  // RZ: the density of an area density needs rt
};

}  // namespace ejecta
