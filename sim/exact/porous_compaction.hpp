#pragma once
// The exact compaction wave of a P-alpha (sim/solid/porosity.hpp) or epsilon-alpha
// (sim/solid/strain_porosity.hpp) material driven by a piston:
// material at rest (bulk density rho_s0 / alpha_0, u = 0, P = 0) pushed by a face moving at
// constant speed u_p. With Pe > 0 the wave splits in two (Herrmann 1969, J. Appl. Phys. 40,
// 2490, "Hugoniots"; the test of Jutzi, Benz & Michel 2008, Icarus 198, 242):
//   - an elastic precursor to the pores' elastic limit (P-alpha: P = Pe; epsilon-alpha: the
//     strain eps_e), alpha = alpha_e, and behind it
//   - a compaction shock to the piston's velocity, ending on the loading curve: P-alpha's
//     alpha = alpha(P), epsilon-alpha's alpha = alpha(eps) with eps the state's strain,
//     ln(rho_0/rho) - Gamma_0/c_s0^2 u (a function of the state: sim/solid/strain_porosity.hpp).
// Each front is a jump conserving mass, momentum and energy from the state ahead of it (a),
//   rho_a (D - v_a) = rho_b (D - v_b),   P_b - P_a = rho_a (D - v_a)(v_b - v_a),
//   u_b - u_a = (P_a + P_b)(1/rho_a - 1/rho_b) / 2,
// closed by the model's own state behind it: alpha_b P_b = P_s(alpha_b rho_b, u_b). With v_b
// given, P_b follows from rho_b by the first two, and the last is one equation in rho_b, solved
// by bisection to round-off (the Rayleigh line falls with rho_b where the model's Hugoniot
// rises, so the root is unique). A compaction shock faster than the precursor overruns it: then
// one shock runs from rest. The precursor is taken as a jump: the elastic law's path and a jump
// to the same end state differ at second order in its strain (~Pe / K, 1e-3 here).
#include "sim/eos/eos.hpp"
#include "sim/solid/porosity.hpp"
#include "sim/solid/strain_porosity.hpp"

namespace ejecta::exact {

struct PorousState {
  double rho = 0.0;    // bulk density [kg/m^3]
  double u = 0.0;      // specific internal energy [J/kg]
  double P = 0.0;      // [Pa]
  double v = 0.0;      // particle velocity, along the wave [m/s]
  double alpha = 1.0;  // distention
};

struct CompactionWave {
  PorousState initial;     // at rest, ahead of both fronts
  PorousState elastic;     // between the precursor and the compaction shock (= initial if none)
  PorousState compacted;   // behind the compaction shock, moving with the piston
  double precursorSpeed = 0.0;  // [m/s]; 0 when there is no separate precursor
  double shockSpeed = 0.0;      // of the compaction front [m/s]
  bool twoWaves() const { return precursorSpeed > 0.0; }
};

// Throws std::domain_error for a piston too slow to compact (u_p at most the precursor's
// particle velocity) and std::invalid_argument for a non-positive u_p.
CompactionWave compactionWave(const EquationOfState& matrix, const PalphaModel& model,
                              double pistonSpeed);
CompactionWave compactionWave(const EquationOfState& matrix, const EpsilonAlphaModel& model,
                              double pistonSpeed);

}  // namespace ejecta::exact
