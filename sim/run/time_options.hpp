#pragma once
// [time] of a scene: the end time, the limits on the step, and how particles share it.

namespace ejecta {

// Global: every particle takes the smallest step of any. Individual: each particle advances on
// its own power-of-two time bin (sim/run/time_bins.hpp), with a limiter between neighbours.
enum class Stepping { Global, Individual };

struct TimeOptions {
  double tEnd = 0.0;          // [s], required
  double dtMax = 0.0;         // [s], 0 = unlimited
  double dtMin = 0.0;         // [s], dt below this stops the run (0 = 1e-12 * tEnd)
  long maxSteps = 0;          // 0 = unlimited (individual steps: sub-steps)
  Stepping stepping = Stepping::Global;
  // Individual steps: a particle's step may be at most this factor longer than any neighbour's
  // (Saitoh & Makino 2009), and a neighbour whose step is longer is woken (Durier & Dalla Vecchia
  // 2012). A power of two >= 2; 0 switches the limiter off (known to fail on strong shocks).
  // Default 2, not SWIFT's 4: on the 2D Sedov (docs/time_steps.md) 4 costs 18% in L1(rho) and 8x
  // in the energy error for 11% fewer particle-steps.
  int limiterFactor = 2;
  // The Courant step takes each particle's fastest closing pair (timestep_criteria.hpp) where it
  // exceeds h |div v|: for bodies that meet (a lone fragment reaching a block, with individual
  // steps, lost 4.9% of its momentum without it, 0.45% with it). Off by default: in a blast every particle ahead
  // of the shock then steps at the shock's pace, 1.5-2x the individual steps' updates.
  bool closingSpeed = false;
};

}  // namespace ejecta
