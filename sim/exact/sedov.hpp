#pragma once
// Sedov-Taylor-von Neumann point blast: the similarity solution for energy E released at t = 0
// at the origin of a uniform ideal gas of density rho0 and zero pressure, at rest, in planar
// (j = 1), cylindrical (j = 2) or spherical (j = 3) symmetry. This is the "standard case"
// (omega = 0) of J. R. Kamm & F. X. Timmes, "On efficient generation of numerically robust Sedov
// solutions", LA-UR-07-2849 (2007); see also L. I. Sedov, "Similarity and Dimensional Methods in
// Mechanics", ch. IV.
//
// Method: with V = v t / r, Z = c^2 t^2 / r^2, G = rho / rho0 functions of lambda = r / R(t),
// Z(V) is the algebraic energy integral (as in Kamm & Timmes / Sedov); the two remaining
// similarity ODEs, for ln(V - V0) and ln G against ln(lambda), are integrated once at construction
// from the strong-shock state at lambda = 1 to lambda = e^-40 (classical RK4, fixed small steps)
// and stored as a cubic Hermite table in ln(lambda). alpha is accumulated by quadrature along the
// same integration. Accuracy and speed are documented in docs/exact_solutions.md.
//
// Energy convention (what `energy` means for each j), with E = alpha * rho0 * R^(j+2) / t^2:
//   j = 3: total energy of the blast, E = int_0^R (rho v^2/2 + p/(gamma-1)) 4 pi r^2 dr  [J]
//   j = 2: energy per unit length along the axis,      ... 2 pi r dr                    [J/m]
//   j = 1: energy per unit area of the whole slab, both sides of the plane x = 0 included,
//          E = int_{-R}^{R} (...) dx = 2 int_0^R (...) dx                                [J/m^2]
// These reproduce the published Kamm & Timmes values (gamma = 1.4, rho0 = 1: R = 1 at t = 1 for
// E = 0.0673185, 0.311357, 0.851072 for j = 1, 2, 3).
#include <vector>

namespace ejecta::exact {

// Flow state at a point: density, radial velocity (outward; for j = 1 the velocity along +x at
// x = r > 0, mirror it for x < 0), pressure; gamma of the gas so e() is self-contained.
struct SedovState {
  double rho;
  double v;
  double p;
  double gamma;
  // Specific internal energy p / ((gamma - 1) rho); +inf at r = 0 where rho -> 0 with p finite.
  double e() const;
};

class SedovSolution {
 public:
  // j in {1, 2, 3}; gamma > 1 (and gamma < 7 for j = 3, where the standard solution with a
  // finite central pressure exists); energy > 0 in the convention above; rho0 > 0.
  // Throws std::invalid_argument otherwise.
  SedovSolution(int j, double gamma, double energy, double rho0);

  int geometry() const { return j_; }
  double gamma() const { return gamma_; }
  double energy() const { return energy_; }
  double ambientDensity() const { return rho0_; }

  // Dimensionless constant of E = alpha * rho0 * R^(j+2) / t^2 (depends on j and gamma only).
  double alpha() const { return alpha_; }

  // R(t) = (E t^2 / (alpha rho0))^(1/(j+2)) and dR/dt = 2 R / ((j+2) t); t > 0.
  double shockRadius(double t) const;
  double shockSpeed(double t) const;
  // Inverse of shockRadius: the time at which the shock reaches radius R > 0.
  double timeOfShockRadius(double radius) const;

  // State at distance r >= 0 from the origin (plane, axis, point) at time t > 0. For r > R(t)
  // the undisturbed ambient state (rho0, 0, 0); at r = R(t) the post-shock state; at r = 0 the
  // limit (rho = 0, v = 0, finite central pressure). Throws std::invalid_argument on r < 0,
  // t <= 0 or non-finite input.
  SedovState at(double r, double t) const;

  // Strong-shock (Rankine-Hugoniot) values just behind the shock.
  double postShockDensity() const;           // rho0 (gamma+1)/(gamma-1)
  double postShockVelocity(double t) const;  // 2 U / (gamma+1)
  double postShockPressure(double t) const;  // 2 rho0 U^2 / (gamma+1)

 private:
  // Similarity profile at one table node: x = ln(V - V0) (V0 = V at the origin) and ln G, with
  // their derivatives d/du, u = -ln(lambda). Both are smooth and tend to linear functions of u
  // toward the origin, which makes them good quantities to interpolate.
  struct Node {
    double x, lnG;
    double dx, dlnG;
  };
  // Physical similarity variables at a point, recovered from a Node.
  struct Profile {
    double v;    // V
    double lnG;  // ln(rho / rho0)
    double lnZ;  // ln(c^2 t^2 / r^2)
  };
  // A uniform grid in u = -ln(lambda) over [u0, u0 + step * (nodes.size() - 1)].
  struct Segment {
    double u0 = 0.0;
    double step = 0.0;
    std::vector<Node> nodes;
  };

  void buildProfile();
  Node interpolate(double u) const;
  Profile profileAt(double u) const;

  int j_;
  double gamma_;
  double energy_;
  double rho0_;
  double alpha_ = 0.0;
  double delta_;       // 2 / (j + 2), the exponent of R ~ t^delta
  double v0_;          // V at the origin, delta / gamma
  Segment nearShock_;  // fine steps where the profile is steep
  Segment interior_;   // coarse steps toward the origin, where it is nearly linear in u
};

}  // namespace ejecta::exact
