#pragma once
// Converged numerical reference for radially symmetric Riemann problems (planar, cylindrical or
// spherical "shock tubes"): an initial discontinuity at r = radius between two gases at rest or
// moving radially. For j = 2, 3 the geometric divergence makes the solution depend on r and t
// separately, so no exact (self-similar) solution exists; this class integrates the 1D radial
// Euler equations with geometric source terms on a fine grid instead.
//
// Equations (ideal gas, p = (gamma - 1) rho e, E = rho (e + u^2/2)), in the area-weighted
// conservative form of E. F. Toro, "Riemann Solvers and Numerical Methods for Fluid Dynamics",
// 3rd ed., Springer 2009, ch. 17 (sec. 17.2), with A(r) = omega r^(j-1):
//   d/dt (A rho)   + d/dr (A rho u)         = 0
//   d/dt (A rho u) + d/dr (A (rho u^2 + p)) = p dA/dr
//   d/dt (A E)     + d/dr (A u (E + p))     = 0
// Method: finite volumes on a uniform grid; cell volumes V_i = int A dr and face areas
// A_{i+1/2} make the mass and energy updates telescoping sums, so those totals are conserved to
// round-off; MUSCL-Hancock (Toro ch. 14, sec. 14.4) with van Leer limited slopes of the
// primitive variables; HLLC fluxes (Toro ch. 10, sec. 10.4-10.6). Details in radial_euler.cpp
// and docs/exact_solutions.md.
#include <vector>

#include "sim/exact/riemann.hpp"

namespace ejecta::exact {

class RadialRiemannSolution {
 public:
  // j = 1 planar, 2 cylindrical, 3 spherical symmetry; `inner` for r < radius, `outer` beyond
  // (GasState::u is the radial velocity, outward positive). The grid covers [0, rMax] with
  // `cells` uniform cells, reflecting at r = 0 (the symmetry centre) and transmissive at rMax.
  // Throws std::invalid_argument unless j is 1, 2 or 3, gamma > 1, both states have finite
  // rho > 0, p > 0 and u, 0 < radius < rMax and cells >= 4.
  RadialRiemannSolution(int j, GasState inner, GasState outer, double radius, double gamma,
                        double rMax, int cells);

  // Integrates from time() to t (CFL number 0.45). Throws std::invalid_argument if t < time()
  // and std::runtime_error if density or pressure stops being positive (the data are outside
  // what this scheme resolves, e.g. near-vacuum).
  void advanceTo(double t);

  double time() const { return time_; }
  int steps() const { return steps_; }  // time steps taken so far (diagnostic)

  // Primitive state at 0 <= r <= rMax: linear interpolation between cell centres of the cell
  // averages (constant in the outer half of the first and last cells). Throws
  // std::invalid_argument outside [0, rMax].
  GasState at(double r) const;

  // Totals over [0, rMax] with the measure A(r) dr: dr for j = 1 (per unit area, x > 0 only),
  // 2 pi r dr for j = 2 (per unit length of the axis), 4 pi r^2 dr for j = 3.
  double totalMass() const;
  double totalEnergy() const;

  int geometry() const { return j_; }
  double gamma() const { return gamma_; }
  double rMax() const { return rMax_; }
  int cellCount() const { return static_cast<int>(rho_.size()); }

 private:
  struct Primitive {
    double rho, u, p;
  };
  struct Flux {
    double mass, momentum, energy;
  };

  double fillPrimitivesWithGhosts();  // returns the largest |u| + c
  void step(double dt);
  Flux hllc(const Primitive& left, const Primitive& right) const;
  Primitive cellPrimitive(int i) const;
  double faceArea(int face) const;    // A at r = face * dr, without the 2 pi / 4 pi factor
  double cellVolume(int cell) const;  // int A dr over the cell, without that factor
  double measureFactor() const;       // 1, 2 pi or 4 pi

  int j_;
  double gamma_;
  double rMax_;
  double dr_;
  double time_ = 0.0;
  int steps_ = 0;

  // Conserved cell averages (per unit volume).
  std::vector<double> rho_, mom_, energy_;
  // Geometry, precomputed: face areas (cells + 1) and cell volumes.
  std::vector<double> area_, volume_, inverseVolume_;
  // Scratch for one step: primitives with one ghost cell each side, the half-step evolved
  // boundary-extrapolated states of each cell at its left and right faces, the limited
  // pressure slope of each cell and the face fluxes.
  std::vector<Primitive> w_, faceL_, faceR_;
  std::vector<double> pressureSlope_;
  std::vector<Flux> flux_;
};

}  // namespace ejecta::exact
