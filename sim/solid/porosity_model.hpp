#pragma once
// What every porosity model of a material gives the rest of the code: the distention
// alpha = rho_s / rho >= 1 (rho the bulk density, rho_s the matrix's) a body starts with, the
// porous material's sound speed, and the step limit on alpha. The models: P-alpha
// (sim/solid/porosity.hpp, alpha a function of pressure) and epsilon-alpha
// (sim/solid/strain_porosity.hpp, alpha a function of volumetric strain); the porosity package
// (sim/run/packages/porosity_package.hpp) evolves them. docs/porosity.md has both.
#include <string>

namespace ejecta {

struct ParticleSet;

// The particle field of the distention (sim/run/packages/porosity_package.hpp declares it).
inline constexpr const char* kDistentionField = "distention";
// Its column, or nullptr where the particles carry none (no porous material): the strength of a
// porous particle is its matrix's over alpha (docs/porosity.md, "Strength of porous material").
const double* distentionColumn(const ParticleSet& p);

// The compaction factor f of a porous solid (Jutzi, Benz & Michel 2008): the matrix's share of
// the bulk's volumetric strain, f = dln(rho_s)/dln(rho) = 1 + dln(alpha)/dln(rho), in [0, 1],
// which the matrix's deviatoric strain takes too (docs/porosity.md, "Strength of porous
// material"). The porosity package declares it where a porous material has strength.
inline constexpr const char* kCompactionFactorField = "compaction_factor";
// Its column, or nullptr (no porous solid: f = 1).
const double* compactionFactorColumn(const ParticleSet& p);

class PorosityModel {
 public:
  virtual ~PorosityModel() = default;
  // alpha_0 = 1 / (1 - porosity) of material at rest at zero pressure.
  virtual double initialDistention() const = 0;
  // The porous material's sound speed from its matrix's at the same state: linear in alpha from
  // the porous material's at alpha_0 to the matrix's at alpha = 1 (both models).
  virtual double soundSpeed(double matrixSoundSpeed, double alpha) const = 0;
  // The most alpha may change in one step (a time-step vote).
  virtual double maxChangePerStep() const = 0;
};

// The sound speed both models share: c = c_m + f (c_0 - c_m), f = (alpha - 1)/(alpha_0 - 1)
// in [0, 1], c_m the matrix's at the current state and c_0 the porous material's at alpha_0.
double porousSoundSpeed(double matrixSoundSpeed, double alpha, double initialDistention,
                        double initialSoundSpeed);

}  // namespace ejecta
