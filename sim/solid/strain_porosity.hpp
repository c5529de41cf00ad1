#pragma once
// Porosity as a function of volumetric strain: the epsilon-alpha model (Wünnemann, Collins &
// Melosh 2006, Icarus 180, 514; with the elastic compaction and the porous sound speed of
// Collins, Melosh & Wünnemann 2011, Int. J. Impact Eng. 38, 434). The papers' text was not at
// hand: the forms below are those on which three implementations agree (iSALE's, through the
// iSALE wiki's parameter descriptions and SALEc; Spheral's StrainPorosity; miluphcuda's), each
// re-derived here; docs/porosity.md says where they differ and which way ejecta goes.
//
// eps = ln(V / V0) is the bulk's volumetric strain (negative in compression), accumulated from
// its rate. Loaded for the first time the distention follows
//   elastic      eps >= eps_e:         dalpha/deps = alpha (1 - (c(alpha)/c_s0)^2)  (reversible)
//   exponential  eps_x <= eps < eps_e: alpha = alpha_e exp(kappa (eps - eps_e))
//   power law    eps_c <= eps < eps_x: alpha = 1 + (alpha_x - 1) ((eps_c - eps)/(eps_c - eps_x))^2
//   compacted    eps < eps_c:          alpha = 1
// with c(alpha)/c_s0 = 1 + (chi - 1)(alpha - 1)/(alpha_0 - 1) the porous sound speed (chi its
// ratio to the matrix's at alpha_0), alpha_e the elastic law's distention at eps_e, eps_x
// where the exponential reaches alpha_x, and eps_c = eps_x + 2 (1 - alpha_x)/(kappa alpha_x),
// which makes the slope continuous at eps_x. The elastic law is the one under which a porous
// material at rest carries sound at c(alpha): from P = P_s(alpha rho, u)/alpha near P = 0,
// c^2 = c_s0^2 (1 - (dalpha/deps)/alpha). Compaction is irreversible: the distention is the
// loading curve's at the most compressive strain reached, eps_min, carried elastically (the
// same law) from there to the present strain.
//
// The strain that drives alpha leaves out the matrix's thermal expansion (as iSALE/SALEc and
// Spheral do; miluphcuda does not, `thermal_strain = false`): deps = dV/V - Gamma_0/c_s0^2 du,
// with Gamma_0 the matrix's Grüneisen parameter at its reference state. The coefficient is a
// constant, so eps = ln(rho_0/rho) - Gamma_0/c_s0^2 u for material starting at rest at u = 0 is a
// function of the state: the exact compaction wave of sim/exact/porous_compaction.hpp closes on
// it.
#include <string>

#include "sim/solid/porosity_model.hpp"

namespace ejecta {

class EquationOfState;

struct EpsilonAlphaParameters {
  double initialDistention = 1.0;     // alpha_0 = 1 / (1 - porosity)
  double elasticStrain = 0.0;         // eps_e <= 0: plastic compaction begins
  double transitionDistention = 1.0;  // alpha_x in [1, alpha_e]: the exponential ends
  double kappa = 0.98;                // kappa in (0, 1): the exponential's rate
  double soundSpeedRatio = 1.0;       // chi = c_0 / c_s0 in (0, 1] (1: no elastic compaction)
  bool thermalStrain = true;          // leave the matrix's thermal expansion out of eps
  double solidDensity = 0.0;          // rho_s0 [kg/m^3]
  double solidSoundSpeed = 0.0;       // c_s0 [m/s]: the matrix's at rho_s0, u = 0
  double solidGruneisen = 0.0;        // Gamma_0: (dP_s/du)/rho_s0 at rho_s0, u = 0
  double maxChangePerStep = 0.02;     // the most alpha may change in one step
};

class EpsilonAlphaModel final : public PorosityModel {
 public:
  // Checks the parameters (std::invalid_argument naming the scene key) and derives alpha_e,
  // eps_x and eps_c.
  explicit EpsilonAlphaModel(const EpsilonAlphaParameters& parameters);
  // The parameters with the matrix's rho_s0 (given or the EOS's reference density), c_s0 and
  // Gamma_0 taken from its equation of state.
  static EpsilonAlphaModel onMatrix(EpsilonAlphaParameters parameters,
                                    const EquationOfState& matrix);

  const EpsilonAlphaParameters& parameters() const { return par_; }
  double initialDistention() const override { return par_.initialDistention; }
  double maxChangePerStep() const override { return par_.maxChangePerStep; }
  // c_0 = chi c_s0 at alpha_0.
  double soundSpeed(double matrixSoundSpeed, double alpha) const override;

  double elasticDistention() const { return alphaE_; }      // alpha_e, at eps_e
  double transitionStrain() const { return epsX_; }         // eps_x
  double compactionStrain() const { return epsC_; }         // eps_c: alpha reaches 1
  // Gamma_0 / c_s0^2 [kg/J] where the thermal strain is left out, else 0.
  double thermalStrainCoefficient() const { return thermal_; }

  // The rate of eps from the bulk's dV/V rate (div v = -drho/dt / rho) and du/dt.
  double strainRate(double volumeRate, double energyRate) const {
    return volumeRate - thermal_ * energyRate;
  }
  // The strain of a state reached from rest (bulk density rho_0, u = 0): ln(rho_0/rho) - ... u.
  double strainOf(double rho, double u) const;
  // dalpha/dt at strain eps with history eps_min for a strain rate epsRate: along the loading
  // curve where the strain compresses at the most compressive strain reached, by the elastic
  // law otherwise.
  double signedDistentionRate(double eps, double epsMin, double epsRate) const;

  // The loading curve alpha(eps) and its slope, for a first compression.
  double loadingDistention(double eps) const;
  double loadingSlope(double eps) const;
  // The distention at strain eps having reached eps_min (the loading curve's at
  // min(eps, eps_min), unloaded elastically to eps), at most alpha_0.
  double distention(double eps, double epsMin) const;
  // |dalpha/dt| at that state for a strain rate epsRate: the loading slope where the strain
  // passes eps_min (at least kappa alpha_e in the elastic range, whose end the step may cross),
  // the elastic one otherwise (the time-step vote).
  double distentionRate(double eps, double epsMin, double epsRate) const;
  // The elastic law carried from alpha over a strain change dEps (closed form, inverted by
  // Newton's method), in [1, alpha_0].
  double elasticDistention(double alpha, double dEps) const;
  // Its right side, alpha (1 - (c(alpha)/c_s0)^2).
  double elasticSlope(double alpha) const;

 private:
  double elasticIntegral(double alpha) const;  // F with dF/dalpha = 1 / elasticSlope

  EpsilonAlphaParameters par_;
  double k_ = 0.0;        // (chi - 1)/(alpha_0 - 1): c/c_s0 = 1 + k (alpha - 1)
  double alphaE_ = 1.0;
  double epsX_ = 0.0, epsC_ = 0.0;
  double thermal_ = 0.0;
};

}  // namespace ejecta
