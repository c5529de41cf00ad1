#pragma once
// The SPH scheme's choices ([sph] of a scene): kernel, density and smoothing-length methods,
// the artificial viscosity and its switch and reconstruction, the momentum form.

namespace ejecta {

enum class KernelKind { CubicSpline, WendlandC2, WendlandC4 };
enum class DensityMethod { Summation, Continuity };
enum class SmoothingLengthMethod { Neighbours, Seed, Constant };
// How pair forces weight the two particles' stresses (docs/materials.md):
//   Lagrangian: sigma_i/(Omega_i rho_i^2) + sigma_j/(Omega_j rho_j^2), from the grad-h Lagrangian;
//   Interface:  (sigma_i + sigma_j)/(rho_i rho_j), exact for uniform pressure across a density
//               jump, so material interfaces carry no spurious force (with volume-weighted
//               continuity density).
enum class MomentumForm { Lagrangian, Interface };

// Per-particle artificial viscosity (docs/undex.md, "Viscosity switch"): None keeps alpha
// constant; MorrisMonaghan evolves alpha_i between alpha_min and alpha (Morris & Monaghan 1997).
enum class ViscositySwitch { None, MorrisMonaghan };

// Velocities the viscosity's linear term compares (docs/undex.md, "The reconstructed viscosity"):
// None takes the particles' own. VanLeer carries each to the pair's midpoint along its velocity
// gradient, limited by van Leer's limiter of the two slopes, so that smooth flow (where the two
// reconstructions meet) feels no viscosity and a shock (where the limiter stops the
// reconstruction) the full one. Monotone first limits each particle's gradient (Barth &
// Jespersen) so that no reconstructed velocity leaves the range of those around it, which damps
// the ringing that VanLeer leaves behind a weak shock. The quadratic term always takes the raw
// velocities.
enum class ViscosityReconstruction { None, VanLeer, Monotone };

// The kernel gradient the hydro pair terms use (docs/verification.md, "Sharper shocks"): Kernel,
// the analytic grad W; IntegralApproach, García-Senz, Cabezón & Escartín's (2012, A&A 538, A9)
// integral approach, C_i (x_j - x_i) W_ij with C_i the inverse of the kernel-weighted second
// moment of i's neighbours, exact for linear fields on any particle arrangement.
enum class GradientScheme { Kernel, IntegralApproach };

// The volume a particle's kernel sums give it (docs/verification.md, "Generalised volume
// elements"). Mass: V_i = m_i / sum_j m_j W_ij, the standard density sum. Generalised: Hopkins'
// (2013, MNRAS 428, 2840) V_i = X_i / sum_j X_j W_ij with the weight X = (m / rho)^p of
// Cabezón, García-Senz & Figueira (2017, A&A 606, A78), rho the density of the step before: a
// density jump then no longer smears the volumes (sum_j V_j W_ij stays nearer one across it).
enum class VolumeElements { Mass, Generalised };

// What dissipates at a shock (docs/verification.md, "Riemann-solver dissipation"). Viscosity:
// Monaghan's artificial viscosity added to the pressure force (seed eqs. 1.6-1.7). Riemann: no
// viscosity; each pair's pressure is the star pressure P* of the one-dimensional Riemann problem
// between the two particles along their axis (Godunov SPH, Inutsuka 2002, J. Comput. Phys. 179,
// 238; sim/sph/terms/riemann_dissipation.hpp), and the energy equation uses its star velocity.
enum class Dissipation { Viscosity, Riemann };

struct SphOptions {
  KernelKind kernel = KernelKind::CubicSpline;
  DensityMethod density = DensityMethod::Summation;
  SmoothingLengthMethod smoothingLength = SmoothingLengthMethod::Neighbours;
  double eta = 1.2;          // h = eta * (m/rho)^(1/d) for Neighbours (and initial h for all)
  double relaxation = 1.0;   // theta of the seed's eq. (1.5), Seed method only
  double courant = 0.3;      // xi of the seed's eq. (1.8)
  double forceFactor = 0.25; // dt <= forceFactor * sqrt(h/|a|)
  // Monaghan artificial viscosity, seed eqs. (1.6)-(1.7)
  double alpha = 1.0;
  double beta = 2.0;
  double epsilon = 0.01;     // phi^2 = epsilon * h_ij^2 regulariser
  bool balsara = false;      // Balsara (1995) shear switch
  // Morris & Monaghan (1997) switch: alpha is alpha_max, alphaMin the floor it decays to over
  // tau = h / (alphaDecay c); beta scales as beta/alpha_max times the pair's alpha.
  ViscositySwitch viscositySwitch = ViscositySwitch::None;
  double alphaMin = 0.1;
  double alphaDecay = 0.2;
  ViscosityReconstruction viscosityReconstruction = ViscosityReconstruction::None;
  double conductivity = 0.0; // Price (2008) artificial conductivity coefficient alpha_u; 0 = off
  double hMinFactor = 1e-3;  // h below hMinFactor * initial h is a collapse (run stops)
  // Each particle's h is held at hMaxFactor x its first h (0 = no cap): a particle thrown out
  // of its body and rarefied keeps a bounded kernel instead of growing it until it spans the
  // body it left (sim/run/packages/smoothing_length_cap_package.hpp).
  double hMaxFactor = 0.0;
  MomentumForm form = MomentumForm::Lagrangian;
  GradientScheme gradients = GradientScheme::Kernel;
  VolumeElements volumeElements = VolumeElements::Mass;
  // p of X = (m / rho)^p (Generalised only), in [0, 1]: 0.7 measured the better balance than 1
  // on the blasts (docs/verification.md), not a published value.
  double volumeExponent = 0.7;
  Dissipation dissipation = Dissipation::Viscosity;
  // Monaghan (2000) / Gray, Monaghan & Swift (2001) artificial stress against the tensile
  // instability, applied to materials with strength: epsilon (0 = off; negative = the default,
  // 0.3 when the scene has a material with strength) and the exponent n of f = W(r)/W(dp).
  double artificialStress = -1.0;
  double artificialStressExponent = 4.0;
};

}  // namespace ejecta
