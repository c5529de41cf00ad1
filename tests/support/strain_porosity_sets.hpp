#pragma once
// epsilon-alpha parameter sets the model, exact-solution and verification tests share
// (sim/solid/strain_porosity.hpp; the scenes scenes/verification/compaction_sand_1d.toml and
// compaction_epsalpha_1d.toml carry the same).
#include "sim/solid/strain_porosity.hpp"

namespace ejecta::test {

// iSALE's sand of the Housen & Holsapple centrifuge benchmark (iSALE wiki, "Cratering in sand at
// 500 G": alpha_0 = 1.80, eps_e = 0, alpha_x = 1.29, kappa = 0.988, chi = 0.33).
inline EpsilonAlphaParameters isaleSand() {
  EpsilonAlphaParameters p;
  p.initialDistention = 1.80;
  p.elasticStrain = 0.0;
  p.transitionDistention = 1.29;
  p.kappa = 0.988;
  p.soundSpeedRatio = 0.33;
  return p;
}

// A porous aluminium with every regime (an illustrative set): elastic to eps_e = -2e-3 with the
// pores carrying sound at chi = 0.78 of the matrix's (JBM08's c_e = 4.11 km/s over 5.28 km/s),
// exponential with kappa = 0.98 to alpha_x = 1.1, then the power law.
inline EpsilonAlphaParameters strainPorousAluminium() {
  EpsilonAlphaParameters p;
  p.initialDistention = 1.275;
  p.elasticStrain = -2e-3;
  p.transitionDistention = 1.1;
  p.kappa = 0.98;
  p.soundSpeedRatio = 0.78;
  return p;
}

}  // namespace ejecta::test
