#pragma once
// Crank-Nicolson wall heat solver: unconditionally stable, second order in dt and dx, for large
// steps and fine grids. Each step solves
//   C (T' - T)/dt = theta [Cond(T') + F(T', t')] + (1 - theta) [Cond(T) + F(T, t)]
// with theta = 1/2 (Cond: conduction, F: face fluxes). The T^4 re-radiation in F(T') is
// linearised about the latest temperature, T'^4 ~ Tk^4 + 4 Tk^3 (T' - Tk), starting from the
// current one (Tk = T), and iterated (Newton on that term) until the change is below the
// tolerance, so the nonlinear scheme is solved, not only its linearisation.
// Linear systems: a tridiagonal (Thomas) solve in 1D; in 2D a sparse LDL^T factorisation
// (Eigen SimplicialLDLT; the matrix is symmetric positive definite), refactorised only when the
// step or the linearisation changes enough to slow the iteration (a chord method in between).
// Start-up: the first steps are taken as two backward-Euler half steps each (Rannacher 1984),
// which damps what CN alone would leave oscillating when a flux switches on at t = 0 and
// dt >> dx^2/alpha. docs/thermal_wall.md.
#include <memory>
#include <span>
#include <vector>

#include "radiation/layered_wall.hpp"
#include "radiation/wall_boundary.hpp"

namespace ejecta::radiation {

struct CrankNicolsonOptions {
  int startupSteps = 2;        // Rannacher start-up steps (0: pure Crank-Nicolson throughout)
  int maxIterations = 20;      // passes on the T^4 term per step; 1: linearised only
  double tolerance = 1e-11;    // ... until max |dT| <= tolerance * max(1 K, max |T|)
  // 2D: refactorise when the frozen linearisation misses the current one by more than this
  // fraction of a matrix diagonal (the iteration then contracts at least this fast).
  double refactorFraction = 0.05;
};

class CrankNicolsonWallSolver final : public WallSolver {
 public:
  // Uniform initial temperature, or a field of grid.size() values. Throws std::invalid_argument
  // for bad boundaries, options or a field of the wrong size or with non-finite values.
  CrankNicolsonWallSolver(WallGrid grid, WallBoundaries boundaries, double initialTemperature,
                          CrankNicolsonOptions options = {});
  CrankNicolsonWallSolver(WallGrid grid, WallBoundaries boundaries,
                          std::vector<double> initialField, CrankNicolsonOptions options = {});
  ~CrankNicolsonWallSolver() override;
  // Holds pointers into its own boundaries: neither copied nor moved.
  CrankNicolsonWallSolver(const CrankNicolsonWallSolver&) = delete;
  CrankNicolsonWallSolver& operator=(const CrankNicolsonWallSolver&) = delete;

  // One step of dt (two half steps during start-up). Throws std::runtime_error when the T^4
  // iteration does not converge or the temperatures stop being finite.
  void advance(double dt) override;

  double time() const override { return time_; }
  std::span<const double> temperature() const override { return temperature_; }
  const WallGrid& grid() const override { return grid_; }
  double faceEnergy() const override { return faceEnergy_; }
  long stepsTaken() const { return steps_; }
  long factorizations() const { return factorizations_; }
  long solves() const { return solves_; }

  class LinearSystem;  // tridiagonal or sparse LDL^T (wall_implicit.cpp)

 private:
  void step(double dt, double theta);

  WallGrid grid_;
  WallBoundaries boundaries_;
  CrankNicolsonOptions options_;
  std::vector<double> fixed_;
  std::vector<FluxFaceNode> faceNodes_;
  bool radiates_ = false;
  std::vector<double> capacity_;        // C per node
  std::vector<double> fromFixed_;       // Sum over fixed neighbours of G T_fixed, per node
  std::vector<double> temperature_, previous_, iterate_, rate_, base_, rhs_, extraDiagonal_;
  std::unique_ptr<LinearSystem> system_;
  double factoredInverseDt_ = 0.0, factoredTheta_ = 0.0;
  std::vector<double> factoredH_;       // radiative conductance per face node when factorised
  std::vector<double> faceH_, absorbedNew_;  // per face node, this step
  double time_ = 0.0;
  double faceEnergy_ = 0.0;
  long steps_ = 0, factorizations_ = 0, solves_ = 0;
};

}  // namespace ejecta::radiation
