#pragma once
// Strength of solids: Hooke's law for the deviatoric stress with the Jaumann rate, and von Mises
// plasticity by radial return with a constant yield stress, the Johnson-Cook flow stress, or
// the pressure-dependent rock strength of Collins, Melosh & Ivanov (2004).
// Melting (T >= T_melt) drops the yield stress, and so the deviatoric stress, to zero.
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "sim/state/tensor.hpp"

namespace ejecta {

enum class YieldModel {
  Elastic,      // no plasticity (rubber, verification of wave speeds)
  VonMises,     // constant yield stress
  JohnsonCook,  // Johnson & Cook (1983): (A + B eps_p^n)(1 + C ln eps_dot*)(1 - T*^m)
  Collins,      // Collins, Melosh & Ivanov (2004): Y = (1 - D) Y_i(P) + D Y_d(P), see below
};

// Rock strength of Collins, Melosh & Ivanov (2004, Meteorit. Planet. Sci. 39, 217):
// intact rock follows Lundborg (1968), Y_i = Y_0 + mu_i P / (1 + mu_i P / (Y_M - Y_0)), which
// rises with slope mu_i from the cohesion Y_0 and saturates at the von Mises limit Y_M;
// damaged rock is frictional, Y_d = Y_d0 + mu_d P, never stronger than intact rock (Y_d <= Y_i);
// Collins et al. have Y_d0 = 0, the default (iSALE and miluphcuda allow a damaged cohesion).
// In tension (P < 0) Y_i continues the straight line of slope mu_i through Y_0 down to zero
// at P = -Y_0 / mu_i, and Y_d the line Y_d0 + mu_d P: both are clamped at 0, never negative.
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

struct JohnsonCookParameters {
  double A = 0.0;                     // yield stress [Pa]
  double B = 0.0;                     // hardening modulus [Pa]
  double n = 1.0;                     // hardening exponent
  double C = 0.0;                     // strain-rate constant
  double m = 1.0;                     // thermal-softening exponent
  double referenceStrainRate = 1.0;   // eps_dot_0 [1/s]
  double roomTemperature = 293.0;     // T_room of the homologous temperature [K]
};

struct StrengthModel {
  YieldModel yield = YieldModel::VonMises;
  double shearModulus = 0.0;          // G [Pa]
  double yieldStress = 0.0;           // VonMises [Pa]
  JohnsonCookParameters johnsonCook;
  CollinsParameters collins;          // Collins

  // Flow stress [Pa] at equivalent plastic strain epsP, equivalent strain rate [1/s],
  // temperature [K], and (Collins only) pressure [Pa] and damage; zero at or above
  // meltTemperature, infinite for Elastic.
  double flowStress(double epsP, double strainRate, double temperature, double meltTemperature,
                    double pressure = 0.0, double damage = 0.0) const;

  // True when the yield surface itself weakens with damage (Collins): the stored deviatoric
  // stress is then the material's whole shear stress. For the other models damage acts by
  // scaling it: the force sees (1 - D) S (docs/materials.md, "Plasticity").
  bool yieldCarriesDamage() const { return yield == YieldModel::Collins; }
  // The factor on the stored S in the stress the material exerts: 1 or 1 - D.
  double deviatoricDamageFactor(double damage) const {
    return yieldCarriesDamage() ? 1.0 : 1.0 - damage;
  }
};

struct StrengthLibraryEntry {
  std::string name;
  double shearModulus;
  YieldModel yield;
  double yieldStress;                 // VonMises
  JohnsonCookParameters johnsonCook;  // JohnsonCook
  double meltTemperature;             // the model's T_melt [K]
  std::string source;
};

const std::vector<StrengthLibraryEntry>& strengthLibrary();
const StrengthLibraryEntry* findStrengthEntry(std::string_view name);

// Rate of the deviatoric stress from the velocity gradient L (L[a][b] = d v_a / d x_b):
//   dS/dt = 2 G (eps_dot - tr(eps_dot) I / 3) + S W^T + W S,  eps_dot = (L + L^T)/2,
//   W = (L - L^T)/2 (the Jaumann rate; Libersky & Petschek 1991, Gray et al. 2001 eq. 2.5).
SymTensor jaumannStressRate(const Mat3& L, const SymTensor& S, double shearModulus);

// Equivalent strain rate sqrt(2/3 e:e) of the deviatoric strain rate e of L.
double equivalentStrainRate(const Mat3& L);

// Radial return to the von Mises surface: if sqrt(3 J2) exceeds `flow`, S is scaled back onto
// it. Returns the equivalent plastic strain increment (sqrt(3 J2) - flow) / (3 G), else 0.
double radialReturn(SymTensor& S, double flow, double shearModulus);

}  // namespace ejecta
