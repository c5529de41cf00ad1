#pragma once
// Porosity below the resolution: the P-alpha model (Herrmann 1969, J. Appl. Phys. 40, 2490) in
// the SPH form of Jutzi, Benz & Michel (2008, Icarus 198, 242; "JBM08"). A porous material
// carries its distention alpha = rho_s / rho >= 1 (rho the bulk density, rho_s the matrix's);
// its pressure is the matrix's over alpha, P = P_s(alpha rho, u) / alpha, and alpha falls along
// a crush curve as the material is loaded past the elastic limit Pe, to 1 (fully compacted) at
// Ps (JBM08's quadratic, n = 2):
//   alpha(P) = 1 + (alpha_e - 1) ((Ps - P) / (Ps - Pe))^n,   Pe <= P < Ps,
// or the two-segment curve that Spheral and miluphcuda implement for strongly porous material
// (pumice; attributed to Jutzi et al. 2009, whose text was not read), with a transition at Pt:
//   alpha(P) = 1 + (alpha_e - alpha_t) ((Pt - P)/(Pt - Pe))^n1 [P < Pt]
//                + (alpha_t - 1) ((Ps - P)/(Ps - Pe))^n2.
// Below Pe, and on unloading, the pores deform elastically:
//   dalpha/dP = alpha^2 / K_s (1 - 1/h^2),  h = 1 + (alpha - 1)(c_e - c_s) / (c_s (alpha_e - 1)),
// with K_s = rho_s0 c_s^2 the matrix's bulk modulus and c_e the porous material's sound speed at
// alpha_0 (with c_e = c_s the pores are rigid below Pe). alpha_e, the distention when P reaches
// Pe elastically, follows from integrating that law from alpha_0 at P = 0 (it depends on itself
// through h, so it is found by fixed-point iteration). The sound speed runs linearly in alpha
// from c_e at alpha_0 to the matrix's at alpha = 1.
// The rate of alpha follows from P = P_s(alpha rho, u)/alpha and alpha = alpha(P):
//   dalpha/dt = dalpha/dP (alpha dPs/drho_s drho/dt + dPs/du du/dt)
//                         / (alpha + dalpha/dP (P - rho dPs/drho_s)).
// docs/porosity.md derives it, says where these forms were checked (the paper's text was not at
// hand: against Spheral's and miluphcuda's implementations of JBM08) and gives the exact
// compaction wave that verifies them.
#include <string>

#include "sim/solid/porosity_model.hpp"

namespace ejecta {

class EquationOfState;

struct PalphaParameters {
  double initialDistention = 1.0;  // alpha_0 = 1 / (1 - porosity)
  double elasticPressure = 0.0;    // Pe [Pa]: plastic compaction begins
  double solidPressure = 0.0;      // Ps [Pa]: fully compacted (alpha = 1)
  double crushExponent = 2.0;      // n (n2) of the crush curve (JBM08: 2)
  // The two-segment curve (below); with transitionDistention = alpha_e (the default, < 0 here
  // meaning "alpha_e") its first segment vanishes and the curve is JBM08's.
  double transitionPressure = 0.0;     // Pt [Pa]; 0: Ps
  double transitionDistention = -1.0;  // alpha_t; < 0: alpha_e
  double transitionExponent = 2.0;     // n1
  double solidDensity = 0.0;       // rho_s0 [kg/m^3]: the matrix's reference density
  double solidSoundSpeed = 0.0;    // c_s [m/s]: the matrix's sound speed at rho_s0, u = 0
  double porousSoundSpeed = 0.0;   // c_e [m/s]: the porous material's at alpha_0
  // The most alpha may change in one step (a time-step vote): the explicit integration of its
  // rate follows the crush curve to ~this.
  double maxChangePerStep = 0.02;
};

class PalphaModel final : public PorosityModel {
 public:
  // Checks the parameters (std::invalid_argument naming the scene key) and finds alpha_e.
  explicit PalphaModel(const PalphaParameters& parameters);

  const PalphaParameters& parameters() const { return par_; }
  double initialDistention() const override { return par_.initialDistention; }
  double maxChangePerStep() const override { return par_.maxChangePerStep; }
  // alpha_e: where the crush curve starts, at P = Pe.
  double elasticDistention() const { return alphaE_; }
  double transitionDistention() const { return alphaT_; }

  // The crush curve: alpha_e for P <= Pe, 1 for P >= Ps.
  double crushDistention(double P) const;
  // Its slope dalpha/dP (<= 0) for Pe <= P < Ps; 0 elsewhere.
  double crushSlope(double P) const;
  // The elastic slope dalpha/dP (<= 0 for c_e <= c_s) at distention alpha.
  double elasticSlope(double alpha) const;
  // c_e at alpha_0 (porousSoundSpeed).
  double soundSpeed(double matrixSoundSpeed, double alpha) const override;

  // dalpha/dt at bulk pressure P and density rho, from the matrix's partial derivatives
  // (dPs/drho_s at constant u, dPs/du at constant rho_s, at rho_s = alpha rho) and the rates of
  // the bulk density and specific energy. The plastic branch applies while the material loads
  // (dP/dt > 0) above Pe on or above its crush curve; otherwise the elastic one. A material
  // compacted off the curve and reloaded is elastic until it meets the curve again (Herrmann's
  // irreversibility).
  double distentionRate(double alpha, double P, double rho, double dPsdRhoS, double dPsdU,
                        double rhoRate, double uRate) const;

  // States above the crush curve (alpha > alpha(P) at P > Pe) are not admissible: the
  // explicit integration of the rate leaves a state a little above it where the curve bends.
  // Returns the distention the state (rho, u) has on the curve, alpha* = alpha(P_s(alpha* rho,
  // u) / alpha*), where the given one lies above it, else alpha unchanged: the return that
  // keeps the integration on the curve, as the radial return keeps the stress on the yield
  // surface.
  double returnToCrushCurve(double alpha, double rho, double u, const EquationOfState& matrix) const;

 private:
  double elasticDistentionAtPe(double alphaE) const;

  PalphaParameters par_;
  double bulkModulus_ = 0.0;  // K_s = rho_s0 c_s^2
  double alphaE_ = 1.0;
  double alphaT_ = 1.0;       // the transition distention (alpha_e: one segment)
};

}  // namespace ejecta
