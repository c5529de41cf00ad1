#pragma once
// Explicit (forward Euler) wall heat solver: the seed's scheme, eqs. 4.11 (1D) and 4.14 (2D),
//   T_i^{n+1} = T_i^n + K (T_{i+1}^n - 2 T_i^n + T_{i-1}^n),   K = alpha dt / dx^2,
// in its finite-volume form C_i dT_i/dt = Sum G (T_nb - T_i) + face flux, which reduces to the
// seed's on a uniform single-material grid and also holds across layer interfaces.
//
// Stability: a step is stable (and keeps the maximum principle) when every free node satisfies
//   dt * (Sum G + 4 eps sigma T^3 [face nodes]) / C <= 1,
// i.e. K <= 1/2 in 1D and Kx + Ky <= 1/2 in 2D (not Kx, Ky <= 1/2 each, as the seed's eq. 4.15
// says), tightened at a radiating face by the radiative conductance 4 eps sigma T^3 at the
// current temperature. The solver never takes a step beyond it: by default it splits the
// caller's step into equal stable sub-steps; with StabilityPolicy::Refuse it throws instead.
// stepUnguarded() takes the raw step without any check (for demonstrating the instability).
#include <span>
#include <stdexcept>
#include <vector>

#include "radiation/layered_wall.hpp"
#include "radiation/wall_boundary.hpp"

namespace ejecta::radiation {

enum class StabilityPolicy {
  Substep,  // split a step that is too large into equal stable sub-steps
  Refuse,   // throw ExplicitStabilityError for a step that is too large
};

struct ExplicitOptions {
  StabilityPolicy stability = StabilityPolicy::Substep;
};

// A step beyond the stability limit under StabilityPolicy::Refuse. The message gives the step,
// the limit, the effective K and the node (layer, position) that sets it.
class ExplicitStabilityError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class ExplicitWallSolver final : public WallSolver {
 public:
  // Uniform initial temperature, or a field of grid.size() values (index grid.index(i, j)).
  // Nodes a boundary fixes take that boundary's temperature. Throws std::invalid_argument for
  // bad boundaries or a field of the wrong size or with non-finite values.
  ExplicitWallSolver(WallGrid grid, WallBoundaries boundaries, double initialTemperature,
                     ExplicitOptions options = {});
  ExplicitWallSolver(WallGrid grid, WallBoundaries boundaries, std::vector<double> initialField,
                     ExplicitOptions options = {});
  // Holds pointers into its own boundaries: neither copied nor moved.
  ExplicitWallSolver(const ExplicitWallSolver&) = delete;
  ExplicitWallSolver& operator=(const ExplicitWallSolver&) = delete;

  // Advances by dt, in stable sub-steps or refusing (see the options). Throws
  // std::runtime_error if the temperatures stop being finite.
  void advance(double dt) override;
  // One forward-Euler step of exactly dt with no stability check: it can diverge.
  void stepUnguarded(double dt);

  // The largest stable step for the current temperatures [s] (infinite when nothing is free).
  double stableTimeStep() const;
  // The effective K = dt * max(rate) / 2 of a step dt: K in 1D, Kx + Ky in 2D, radiation
  // included; the step is stable when it is <= 1/2.
  double effectiveK(double dt) const { return 0.5 * dt / stableTimeStep(); }

  double time() const override { return time_; }
  std::span<const double> temperature() const override { return temperature_; }
  const WallGrid& grid() const override { return grid_; }
  double faceEnergy() const override { return faceEnergy_; }
  long stepsTaken() const { return steps_; }          // forward-Euler steps, sub-steps included

 private:
  // The fastest relaxation rate (Sum G + radiative conductance) / C over the free nodes, and the
  // node where it is reached.
  double maximumRate(std::size_t* where) const;
  void checkFinite() const;

  WallGrid grid_;
  WallBoundaries boundaries_;
  ExplicitOptions options_;
  std::vector<double> fixed_;             // fixed temperature, or < 0 for a free node
  std::vector<FluxFaceNode> faceNodes_;
  std::vector<double> inverseCapacity_;   // 1 / C per node (0 for fixed nodes)
  std::vector<double> conductionRate_;    // Sum G / C per node across the thickness i
  std::vector<double> temperature_, rate_;
  double time_ = 0.0;
  double faceEnergy_ = 0.0;
  long steps_ = 0;
};

}  // namespace ejecta::radiation
