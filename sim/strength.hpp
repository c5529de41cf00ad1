#pragma once
// Strength of solids: Hooke's law for the deviatoric stress with the Jaumann rate, and von Mises
// plasticity by radial return with a constant yield stress or the Johnson-Cook flow stress.
// Melting (T >= T_melt) drops the yield stress, and so the deviatoric stress, to zero.
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "sim/tensor.hpp"

namespace ejecta {

enum class YieldModel {
  Elastic,      // no plasticity (rubber, verification of wave speeds)
  VonMises,     // constant yield stress
  JohnsonCook,  // Johnson & Cook (1983): (A + B eps_p^n)(1 + C ln eps_dot*)(1 - T*^m)
};

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

  // Flow stress [Pa] at equivalent plastic strain epsP, equivalent strain rate [1/s] and
  // temperature [K]; zero at or above meltTemperature, infinite for Elastic.
  double flowStress(double epsP, double strainRate, double temperature,
                    double meltTemperature) const;
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
