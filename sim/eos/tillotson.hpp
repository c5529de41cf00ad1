#pragma once
// Tillotson (1962) equation of state for solids under shock, in the four-region form of
// Benz & Asphaug (1999), Icarus 142, 5 (appendix) and Melosh (1989), "Impact Cratering",
// appendix II. Equations, sound-speed derivation, sources and seed errata: docs/eos_tillotson.md.
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "sim/eos/eos.hpp"

namespace ejecta {

// Material constants, SI units. Names follow Benz & Asphaug (1999) Table II.
struct TillotsonParameters {
  std::string name;
  double rho0;   // reference density [kg/m^3]
  double A;      // linear (bulk-modulus) coefficient [Pa]
  double B;      // quadratic compression coefficient [Pa]
  double E0;     // energy scale of the b term [J/kg]
  double Eiv;    // specific energy of incipient vaporisation [J/kg]
  double Ecv;    // specific energy of complete vaporisation [J/kg]
  double a;      // dimensionless; 1 + a is the low-density ideal-gas gamma
  double b;      // dimensionless
  double alpha;  // dimensionless decay of the hot-expanded A and b terms
  double beta;   // dimensionless decay of the hot-expanded A term
  std::string source;
};

// Library entries: "granite", "basalt", "ice", "iron", "aluminium". Throws
// std::invalid_argument listing the known names.
const TillotsonParameters& tillotsonLibrary(std::string_view name);
std::vector<std::string> tillotsonLibraryNames();

struct TillotsonOptions {
  // Pressures below this are clamped to it (and c^2 set to its floor there). Default: no floor,
  // so the cold branch keeps its tension, which strength/fracture models need.
  double minimumPressure = -std::numeric_limits<double>::infinity();
  // c^2 >= soundSpeedFloorFraction * A / rho0. Where the Tillotson c^2 is negative or tiny
  // (cold expanded states past the spinodal, rho < ~0.5 rho0 for A = B) the material is
  // mechanically unstable and a real signal speed is still needed for the time step and the
  // artificial viscosity. Benz's Tillotson routine uses 0.25; miluphcuda's default cs_limit
  // sqrt(A/rho0) is 1.0 (docs/eos_tillotson.md).
  double soundSpeedFloorFraction = 0.01;
  // true: B mu^2 is kept in the cold expanded branch (Benz & Asphaug 1999; Melosh 1989).
  // false: dropped there, as in AUTODYN's region II and the seed's eq. (2.2).
  bool quadraticTermWhenExpanded = true;
};

class Tillotson final : public EquationOfState {
 public:
  enum class Region { Compressed, ColdExpanded, Hybrid, HotExpanded };

  explicit Tillotson(TillotsonParameters parameters, TillotsonOptions options = {});

  std::string name() const override { return "tillotson"; }
  void evaluate(const double* rho, const double* u, double* P, double* cs,
                const std::size_t* indices, std::size_t n) const override;
  double pressure(double rho, double u) const override;
  double soundSpeed(double rho, double u) const override;
  // Smallest u >= 0 with pressure(rho, u) == P; std::domain_error if none exists (P below the
  // cold curve P(rho, 0), below minimumPressure, or rho not positive).
  double specificEnergy(double rho, double P) const override;
  double referenceDensity() const override { return par_.rho0; }
  Slopes pressureSlopes(double rho, double u) const override {
    const State s = state(rho, u);
    return {s.dPdrho, s.dPdu};
  }

  Region region(double rho, double u) const;
  const TillotsonParameters& parameters() const { return par_; }
  const TillotsonOptions& options() const { return opt_; }

  // Pressure and its partial derivatives at one point, before any floor.
  struct State {
    double P;
    double dPdrho;  // at constant u
    double dPdu;    // at constant rho
  };
  State state(double rho, double u) const;

 private:
  State cold(double rho, double u) const;
  State hot(double rho, double u) const;
  void pressureAndSoundSpeed(double rho, double u, double& P, double& cs) const;
  double rawPressure(double rho, double u) const { return state(rho, u).P; }

  TillotsonParameters par_;
  TillotsonOptions opt_;
  double cs2Min_;
};

}  // namespace ejecta
