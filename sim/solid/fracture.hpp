#pragma once
// Fracture and failure of brittle solids.
//  - Grady-Kipp damage with Weibull flaws (Benz & Asphaug 1994, 1995): each particle holds flaws
//    whose activation strains follow a Weibull distribution; once the local tensile strain
//    exceeds a flaw's threshold, a crack grows at c_g = 0.4 c_l, and the damage D = s^3 (s the
//    crack length over the particle size) reduces tension and deviatoric stress by (1 - D).
//  - Principal-stress failure: D jumps to 1 where the largest principal stress exceeds a tensile
//    strength (AUTODYN's "principal stress" failure; the seed's Whipple-shield runs).
//  - Erosion on strain: D jumps to 1 where the equivalent total strain exceeds a limit (the SPH
//    analogue of AUTODYN's geometric-strain erosion: the particle keeps its mass and momentum
//    but carries neither tension nor shear).
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "sim/solid/weibull_flaws.hpp"

namespace ejecta {

enum class FractureKind { None, GradyKipp, PrincipalStress };

struct FractureModel {
  FractureKind kind = FractureKind::None;
  WeibullParameters weibull;                                    // GradyKipp
  double tensileStrength = std::numeric_limits<double>::infinity();  // PrincipalStress [Pa]
  double erosionStrain = std::numeric_limits<double>::infinity();    // any kind
  double crackSpeedFactor = 0.4;  // c_g / c_l (Benz & Asphaug 1994, after Lawn & Wilshaw 1975)
  // Largest growth of the crack fraction s in one time step (GradyKipp). A numerical choice, not
  // a material constant: at 0.3 a particle with all of ~11 flaws active (the Nakamura-Fujiwara
  // scene) needs ~4 steps from intact to broken, about what Courant 0.1 gave there
  // (docs/fragmentation.md). No scene key sets it yet.
  double maxCrackIncrement = 0.3;
  std::uint64_t seed = 1;         // flaw distribution
};

// Rate of the crack fraction s = D^(1/3) of one particle (Benz & Asphaug 1994, 1995):
//   ds/dt = n_act c_g / R_s   while s < (n_act / n_total)^(1/3),
// with n_act the flaws activated by the local strain eps = sigma_t / ((1 - D) E), sigma_t the
// largest tensile principal stress, E Young's modulus, c_g = crackSpeedFactor * c_l and R_s the
// particle's radius (taken as h). c_l is the longitudinal speed of the intact material
// (intactLongitudinalSpeed): damage lowers the stress a particle carries, not the speed at which
// its cracks run. Returns 0 when no flaw is active.
double crackGrowthRate(std::uint32_t activeFlaws, std::uint32_t totalFlaws, double crack,
                       double longitudinalSpeed, double particleRadius, double crackSpeedFactor);

// The crack fraction that n_act of n_total flaws can open: (n_act / n_total)^(1/3), so that
// D = s^3 <= n_act / n_total (each crack relieves only its own share of the volume). 1 for a
// particle without flaws.
double crackCap(std::uint32_t activeFlaws, std::uint32_t totalFlaws);

// One explicit update of the crack fraction over dt at a rate >= 0, bounded by its cap: the
// result is crack + dt rate, but never past max(crack, cap) nor past 1. An explicit step can
// otherwise carry s far beyond the cap (the rate only switches off once s has passed it), and
// s never decreases: a cap that fell (fewer flaws active than before) stops growth, it does not
// heal.
double advanceCrack(double crack, double rate, double dt, double cap);

// The longest time step over which a crack growing at `rate` grows by at most maxIncrement
// (infinity when it does not grow).
double crackStepLimit(double rate, double maxIncrement);

// Young's modulus from the bulk and shear moduli: E = 9 K G / (3 K + G).
inline double youngsModulus(double bulk, double shear) {
  return 9.0 * bulk * shear / (3.0 * bulk + shear);
}

// Longitudinal (P-wave) speed of the intact material, sqrt((K + 4G/3) / rho), from the
// undamaged bulk and shear moduli.
double intactLongitudinalSpeed(double bulk, double shear, double density);

}  // namespace ejecta
