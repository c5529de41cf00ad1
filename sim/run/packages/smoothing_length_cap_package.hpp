#pragma once
// The smoothing-length cap (sph.h_max_factor): each particle's h is held at most at the factor
// times the h it started with, stored per particle as `smoothing_length_cap` so that the cap
// travels with the particle (between ranks, through restarts). A particle thrown clear of its
// body and rarefied under continuity density otherwise widens its kernel until it spans the body
// it left and the neighbour check stops the run (docs/convergence.md, "Particles thrown clear").
// Spheral holds h below a per-NodeList hmax the same way; AUTODYN bounds it by a minimum
// density factor. The density pass and setSmoothingFromDensity apply the cap; nothing evolves.
#include "sim/run/physics_package.hpp"

namespace ejecta {

class SmoothingLengthCapPackage : public PhysicsPackage {
 public:
  static constexpr const char* kCap = "smoothing_length_cap";

  explicit SmoothingLengthCapPackage(double factor) : factor_(factor) {}

  std::string name() const override { return "smoothing_length_cap"; }
  // The cap of a particle not carrying one yet (a new run; a restart of a run without it) is
  // factor x its present h.
  void registerFields(ParticleSet& p) override;

  // The caps of the real particles (the column's first numReal entries), or nullptr when `p`
  // carries none. Valid until `p` is resized (ghosts added or dropped).
  static const double* caps(const ParticleSet& p);

 private:
  double factor_;
};

}  // namespace ejecta
