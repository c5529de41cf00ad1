#pragma once
// Fracture: damage by Grady-Kipp crack growth over Weibull flaws, principal-stress failure and
// erosion (sim/solid/fracture.hpp, sim/solid/solid_state.hpp). It owns the flaws, the crack's
// rate and its cap, the crack-growth vote on the time step, the damage's release of tension
// after each equation of state, and failure at the end of each step.
#include <cstddef>

#include "sim/run/physics_package.hpp"
#include "sim/solid/solid_state.hpp"

namespace ejecta {

class FracturePackage : public PhysicsPackage {
 public:
  std::string name() const override { return "fracture"; }
  void registerFields(ParticleSet& p) override;
  void limitKicks(Leapfrog& leapfrog, const PackageContext& c) override;
  void updateState(ParticleSet& p, const PackageContext& c) override;
  void evaluateDerivatives(ParticleSet& p, const PackageContext& c) override;
  void finalize(ParticleSet& p, const PackageContext& c) override;
  double timestep(const ParticleSet& p, const PackageContext& c) const override;
  void particleTimesteps(const ParticleSet& p, const PackageContext& c,
                         std::span<const std::size_t> which, std::span<double> dt) const override;

  // Grady-Kipp flaws from the particles as built at t = 0 (their volumes m/rho), so a restarted
  // run draws the flaws of the uninterrupted one.
  void distributeFlaws(const ParticleSet& initial, const MaterialTable& materials);
  bool flawsReady() const { return flawsReady_; }
  // Particles that failed (principal stress or erosion) in the last step.
  std::size_t lastFailures() const { return lastFailures_; }

 private:
  FlawSet flaws_;
  bool flawsReady_ = false;
  std::size_t lastFailures_ = 0;
};

}  // namespace ejecta
