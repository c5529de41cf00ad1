#pragma once
// Exact solution of the Riemann problem for the 1D Euler equations with one ideal gas
// (p = (gamma - 1) rho e), after E. F. Toro, "Riemann Solvers and Numerical Methods for Fluid
// Dynamics", 3rd ed., Springer 2009, chapter 4 (sec. 4.2 pressure function, 4.3 Newton iteration
// for p*, 4.4 star densities, wave speeds and fans, 4.5 sampling).
//
// Used as the reference for shock-tube verification tests. Units are whatever the caller uses
// consistently (SI in ejecta); nothing here is dimensional.
#include <stdexcept>

namespace ejecta::exact {

// Primitive state of the gas: density, velocity along x, pressure.
struct GasState {
  double rho;
  double u;
  double p;
};

// The self-similar solution of an initial discontinuity at x = 0, t = 0 with `left` for x < 0
// and `right` for x > 0. The solution depends on x/t only; it is three waves (left shock or
// rarefaction, contact at the star velocity, right shock or rarefaction) around the "star"
// region of pressure p* and velocity u*.
//
// Throws std::invalid_argument unless gamma > 1 and both states have finite rho > 0, p > 0, u;
// throws std::domain_error when the data generate vacuum (pressure positivity condition
// violated: 2 (cL + cR) / (gamma - 1) <= uR - uL, Toro sec. 4.3.1 and 4.6), a case this solver does
// not cover.
class RiemannProblem {
 public:
  RiemannProblem(GasState left, GasState right, double gamma);

  // State at similarity coordinate x/t (x measured from the initial interface). At x/t exactly
  // on the contact the left star state is returned. +-infinity gives the undisturbed states.
  GasState sample(double xOverT) const;

  double starPressure() const { return pStar_; }
  double starVelocity() const { return uStar_; }
  double starDensityLeft() const { return rhoStarL_; }
  double starDensityRight() const { return rhoStarR_; }

  // Wave types: true when p* exceeds the respective initial pressure (Toro sec. 4.2).
  bool leftIsShock() const { return pStar_ > left_.p; }
  bool rightIsShock() const { return pStar_ > right_.p; }

  // Speeds (dx/dt) of the wave edges. For a shock head and tail coincide with the shock speed;
  // for a rarefaction the head is the edge facing the undisturbed gas and the tail the edge
  // facing the star region. The contact moves at starVelocity().
  double leftHeadSpeed() const { return leftHead_; }
  double leftTailSpeed() const { return leftTail_; }
  double rightHeadSpeed() const { return rightHead_; }
  double rightTailSpeed() const { return rightTail_; }

  // Number of Newton steps the star-pressure solve took (diagnostic).
  int iterations() const { return iterations_; }

  double gamma() const { return gamma_; }
  GasState left() const { return left_; }
  GasState right() const { return right_; }

 private:
  void solveStarPressure();
  void computeStarStatesAndSpeeds();
  // Toro's f_K(p) (sec. 4.2) for one side, and its derivative.
  double pressureFunction(double p, const GasState& side, double c, double& derivative) const;
  GasState sampleLeft(double xi) const;
  GasState sampleRight(double xi) const;

  GasState left_, right_;
  double gamma_;
  double cL_ = 0.0, cR_ = 0.0;
  double pStar_ = 0.0, uStar_ = 0.0;
  double rhoStarL_ = 0.0, rhoStarR_ = 0.0;
  double leftHead_ = 0.0, leftTail_ = 0.0, rightHead_ = 0.0, rightTail_ = 0.0;
  int iterations_ = 0;
};

}  // namespace ejecta::exact
