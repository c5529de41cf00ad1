#pragma once
// model = "collins": the rock strength of Collins, Melosh & Ivanov (2004, Meteorit. Planet. Sci.
// 39, 217), Y = (1 - D) Y_i(P) + D Y_d(P):
// intact rock follows Lundborg (1968), Y_i = Y_0 + mu_i P / (1 + mu_i P / (Y_M - Y_0)), which
// rises with slope mu_i from the cohesion Y_0 and saturates at the von Mises limit Y_M;
// damaged rock is frictional, Y_d = Y_d0 + mu_d P, never stronger than intact rock (Y_d <= Y_i);
// Collins et al. have Y_d0 = 0, the default (iSALE and miluphcuda allow a damaged cohesion).
// In tension (P < 0) Y_i continues the straight line of slope mu_i through Y_0 down to zero
// at P = -Y_0 / mu_i, and Y_d the line Y_d0 + mu_d P: both are clamped at 0, never negative.
// The yield surface carries the damage: the stored S is the whole shear stress.
#include "sim/solid/strength_catalog.hpp"

namespace ejecta {

struct CollinsParameters {
  double cohesion = 0.0;          // Y_0, intact strength at zero pressure [Pa]
  double frictionIntact = 0.0;    // mu_i, d Y_i / d P at P = 0
  double strengthLimit = 0.0;     // Y_M, von Mises limit at high pressure [Pa] (> Y_0)
  double frictionDamaged = 0.0;   // mu_d, coefficient of internal friction of damaged rock
  double cohesionDamaged = 0.0;   // Y_d0, strength of damaged rock at zero pressure [Pa]
};

// Y_i(P) [Pa] of intact rock at pressure P [Pa] (compression positive).
double intactRockStrength(const CollinsParameters& c, double pressure);
// Y_d(P) [Pa] of fully damaged rock: min(max(Y_d0 + mu_d P, 0), Y_i(P)).
double damagedRockStrength(const CollinsParameters& c, double pressure);
// Y = (1 - D) Y_i + D Y_d at damage D in [0, 1].
double rockStrength(const CollinsParameters& c, double pressure, double damage);

class CollinsYield final : public YieldSurface {
 public:
  explicit CollinsYield(const CollinsParameters& c) : c_(c) {}
  const CollinsParameters& parameters() const { return c_; }
  double flowStress(double epsP, double strainRate, double temperature, double meltTemperature,
                    double pressure, double damage) const override;
  bool carriesDamage() const override { return true; }

 private:
  CollinsParameters c_;
};

StrengthModelRow collinsStrengthRow();

}  // namespace ejecta
