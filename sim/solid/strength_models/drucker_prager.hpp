#pragma once
// model = "drucker_prager": a frictional (granular, damaged) material whose yield stress grows
// linearly with pressure up to a limit, Y = min(max(Y_0 + mu P, 0), Y_M), the simpler
// alternative to `collins` for rubble and regolith (issue 20).
//
// Drucker & Prager (1952, Q. Appl. Math. 10, 157) bound the stress by sqrt(J2) = k + alpha I1'
// with I1' = 3P the first invariant in compression. With ejecta's yield stress Y = sqrt(3 J2)
// (the von Mises radial return, sim/solid/strength.hpp) that is Y = Y_0 + mu P with
// Y_0 = sqrt(3) k and mu = 3 sqrt(3) alpha: the cohesion and friction coefficient given here are
// those two, the form iSALE's Drucker-Prager option takes (miluphcuda's takes a Mohr-Coulomb c
// and phi and converts them: docs/materials.md). The cap Y_M is the
// von Mises limit the same rock reaches at high pressure (as Y_M of Collins et al. 2004). In
// tension (P < 0) the line continues to zero at P = -Y_0 / mu, never negative.
//
// The surface describes the material as it is (already broken, or granular): damage does not
// weaken it, and the stored S is the whole shear stress (carriesDamage), as for damaged
// `collins` rock. A material that is intact until it fractures is `collins`.
#include "sim/solid/strength_catalog.hpp"

namespace ejecta {

struct DruckerPragerParameters {
  double cohesion = 0.0;       // Y_0, strength at zero pressure [Pa], >= 0
  double friction = 0.0;       // mu = dY/dP, > 0
  double strengthLimit = 0.0;  // Y_M, the cap at high pressure [Pa], > Y_0
};

// Y(P) [Pa] at pressure P [Pa] (compression positive).
double druckerPragerStrength(const DruckerPragerParameters& c, double pressure);

class DruckerPragerYield final : public YieldSurface {
 public:
  explicit DruckerPragerYield(const DruckerPragerParameters& c) : c_(c) {}
  const DruckerPragerParameters& parameters() const { return c_; }
  double flowStress(double epsP, double strainRate, double temperature, double meltTemperature,
                    double pressure, double damage) const override;
  bool carriesDamage() const override { return true; }

 private:
  DruckerPragerParameters c_;
};

StrengthModelRow druckerPragerStrengthRow();

}  // namespace ejecta
