#pragma once
// Strength of solids: Hooke's law for the deviatoric stress with the Jaumann rate, and von Mises
// plasticity by radial return onto a yield surface. The yield surfaces (elastic, a constant
// yield stress, the Johnson-Cook flow stress, the pressure-dependent rock strength of Collins,
// Melosh & Ivanov 2004) live one to a file in sim/solid/strength_models/ and are listed, with
// their scene keys, in sim/solid/strength_catalog.hpp.
// Melting (T >= T_melt) drops the yield stress, and so the deviatoric stress, to zero.
#include <memory>
#include <utility>

#include "sim/state/tensor.hpp"

namespace ejecta {

// One yield model: the flow stress below the melting point, and whether damage weakens the
// yield surface itself.
class YieldSurface {
 public:
  virtual ~YieldSurface() = default;
  // Flow stress [Pa] at equivalent plastic strain epsP, equivalent strain rate [1/s],
  // temperature [K] (below meltTemperature), pressure [Pa] and damage.
  virtual double flowStress(double epsP, double strainRate, double temperature,
                            double meltTemperature, double pressure, double damage) const = 0;
  // True when the yield surface itself weakens with damage (Collins): the stored deviatoric
  // stress is then the material's whole shear stress. For the other models damage acts by
  // scaling it: the force sees (1 - D) S (docs/materials.md, "Plasticity").
  virtual bool carriesDamage() const { return false; }
};

// A material's strength: its shear modulus and yield surface (one per material, shared by
// copies; one virtual call per particle in applyPlasticity).
class StrengthModel {
 public:
  StrengthModel(double G, std::shared_ptr<const YieldSurface> yield)
      : shearModulus(G), yield_(std::move(yield)), carriesDamage_(yield_->carriesDamage()) {}

  double shearModulus = 0.0;  // G [Pa]

  const YieldSurface& yield() const { return *yield_; }

  // Flow stress [Pa] at equivalent plastic strain epsP, equivalent strain rate [1/s],
  // temperature [K], and (Collins only) pressure [Pa] and damage; zero at or above
  // meltTemperature, infinite for Elastic.
  double flowStress(double epsP, double strainRate, double temperature, double meltTemperature,
                    double pressure = 0.0, double damage = 0.0) const {
    if (temperature >= meltTemperature) return 0.0;
    return yield_->flowStress(epsP, strainRate, temperature, meltTemperature, pressure, damage);
  }

  // YieldSurface::carriesDamage of the model.
  bool yieldCarriesDamage() const { return carriesDamage_; }
  // The factor on the stored S in the stress the material exerts: 1 or 1 - D.
  double deviatoricDamageFactor(double damage) const {
    return yieldCarriesDamage() ? 1.0 : 1.0 - damage;
  }

 private:
  std::shared_ptr<const YieldSurface> yield_;
  bool carriesDamage_ = false;
};

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
