#pragma once
// Porosity: the distention alpha of the porous materials, by P-alpha (sim/solid/porosity.hpp) or
// epsilon-alpha (sim/solid/strain_porosity.hpp). After each equation of state it replaces a
// porous particle's pressure and sound speed by the porous material's, P = P_s(alpha rho, u) /
// alpha, and it votes on the time step so that alpha moves by at most max_distention_change a
// step. It joins first, so the packages after it (burn, strength, fracture) scale the porous
// pressure and sound speed as they would a solid's.
// - P-alpha: after the pair passes it gives alpha's rate from the rates of density and energy;
//   at the end of a step a state the integration left above the crush curve returns to it.
// - epsilon-alpha: alpha is a function of the volumetric strain (evolved from the bulk's
//   dV/V rate) and of the most compressive strain reached (lowered to the strain at the end of
//   each step), evaluated before each equation of state: no rate of its own, no return. The
//   shared distention field is kicked with rate 0 for these particles (the integrator may set it
//   back to its step-start value); the equation of state that follows every kick recomputes it
//   before anything reads it.
// A porous solid (a porous material with strength): its deviatoric stress S is the bulk's, the
// matrix's over alpha, so its rate gains -S (dalpha/dt)/alpha (and the P-alpha return scales S
// by alpha/alpha_returned); at the end of each step its compaction factor f, the matrix's share
// of the step's volumetric strain, 1 + dln(alpha)/dln(rho), is kept for the force pass to scale
// the next step's elastic stress rate by: the matrix's stress alpha S then follows the matrix's
// strain alone (docs/porosity.md, "The matrix's share of the strain").
#include <cstddef>
#include <vector>

#include "sim/run/physics_package.hpp"
#include "sim/solid/porosity.hpp"
#include "sim/solid/strain_porosity.hpp"
#include "sim/sph/sph_options.hpp"

namespace ejecta {

class PorosityPackage : public PhysicsPackage {
 public:
  static constexpr const char* kDistention = kDistentionField;
  static constexpr const char* kDistentionRate = "distention_rate";
  // epsilon-alpha's volumetric strain eps = ln(V/V0) (less the thermal part), its rate, and the
  // most compressive strain reached, eps_min.
  static constexpr const char* kStrain = "volumetric_strain";
  static constexpr const char* kStrainRate = "volumetric_strain_rate";
  static constexpr const char* kLeastStrain = "compaction_strain";
  // A porous solid's distention and bulk density at the start of its step (the step's strains
  // give its compaction factor).
  static constexpr const char* kStartDistention = "distention_at_step_start";
  static constexpr const char* kStartDensity = "density_at_step_start";

  PorosityPackage(const MaterialTable& materials, DensityMethod density);

  std::string name() const override { return "porosity"; }
  void registerFields(ParticleSet& p) override;
  void updateState(ParticleSet& p, const PackageContext& c) override;
  void evaluateDerivatives(ParticleSet& p, const PackageContext& c) override;
  void finalize(ParticleSet& p, const PackageContext& c) override;
  double timestep(const ParticleSet& p, const PackageContext& c) const override;
  void particleTimesteps(const ParticleSet& p, const PackageContext& c,
                         std::span<const std::size_t> which, std::span<double> dt) const override;

 private:
  // The columns the step vote reads, looked up once per vote.
  struct StepColumns {
    const double* distentionRate = nullptr;
    const double* strain = nullptr;
    const double* leastStrain = nullptr;
    const double* strainRate = nullptr;
  };
  StepColumns stepColumns(const ParticleSet& p) const;
  // A porous solid's columns: the compaction factor f and the state its step started from.
  struct MatrixShare {
    double* factor = nullptr;
    double* startDistention = nullptr;
    double* startDensity = nullptr;
  };
  MatrixShare matrixShare(ParticleSet& p) const;
  // At the end of particle i's step (distention alpha): f for its next step.
  void followMatrix(ParticleSet& p, const MatrixShare& share, std::size_t i, double alpha) const;
  double particleTimestep(const ParticleSet& p, const PackageContext& c, const StepColumns& columns,
                          std::size_t i) const;

  DensityMethod density_;
  // Each material's model of its kind, or null (none, or the other kind).
  std::vector<const PalphaModel*> palpha_;
  std::vector<const EpsilonAlphaModel*> epsilonAlpha_;
  bool anyEpsilonAlpha_ = false;
  std::vector<double> initialDistention_;  // alpha_0 by material (1: not porous)
  double largestInitialDistention_ = 1.0;
  std::vector<char> porousSolid_;  // by material: porous and with strength
  bool anyPorousSolid_ = false;
  // Scratch of updateState: each porous material's selected particles and their matrix state.
  std::vector<std::size_t> members_;
  std::vector<double> matrixDensity_, matrixPressure_, matrixSoundSpeed_;
};

}  // namespace ejecta
