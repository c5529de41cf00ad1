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

#include "sim/weibull_flaws.hpp"

namespace ejecta {

enum class FractureKind { None, GradyKipp, PrincipalStress };

struct FractureModel {
  FractureKind kind = FractureKind::None;
  WeibullParameters weibull;                                    // GradyKipp
  double tensileStrength = std::numeric_limits<double>::infinity();  // PrincipalStress [Pa]
  double erosionStrain = std::numeric_limits<double>::infinity();    // any kind
  double crackSpeedFactor = 0.4;  // c_g / c_l (Benz & Asphaug 1994, after Lawn & Wilshaw 1975)
  std::uint64_t seed = 1;         // flaw distribution
};

// Rate of the crack fraction s = D^(1/3) of one particle (Benz & Asphaug 1994, 1995):
//   ds/dt = n_act c_g / R_s   while s < (n_act / n_total)^(1/3),
// with n_act the flaws activated by the local strain eps = sigma_t / ((1 - D) E), sigma_t the
// largest tensile principal stress, E Young's modulus, c_g = crackSpeedFactor * c_l and R_s the
// particle's radius (taken as h). Returns 0 when no flaw is active.
double crackGrowthRate(std::uint32_t activeFlaws, std::uint32_t totalFlaws, double crack,
                       double longitudinalSpeed, double particleRadius, double crackSpeedFactor);

// Young's modulus from the bulk and shear moduli: E = 9 K G / (3 K + G).
inline double youngsModulus(double bulk, double shear) {
  return 9.0 * bulk * shear / (3.0 * bulk + shear);
}

}  // namespace ejecta
