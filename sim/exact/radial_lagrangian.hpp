#pragma once
// A one-dimensional Lagrangian hydrocode in planar (j = 1), cylindrical (j = 2) or spherical
// (j = 3) symmetry: the converged reference for centred explosions in an inert medium (the UNDEX
// scenes, docs/undex.md "The converged 1D reference"), where the Eulerian solver of
// radial_euler.hpp cannot go (two materials with different equations of state mix badly in an
// Eulerian cell; a Lagrangian zone never holds two).
//
// Method (details in radial_lagrangian.cpp):
//   - the staggered grid of von Neumann & Richtmyer (J. Appl. Phys. 21, 232, 1950) as in
//     Wilkins' HEMP (M. L. Wilkins, "Calculation of elastic-plastic flow", Methods in
//     Computational Physics 3, 1964): radii and velocities on the nodes, mass, density, specific
//     internal energy and pressure in the zones, node masses half of each neighbouring zone's;
//   - the compatible energy update of E. J. Caramana, D. E. Burton, M. J. Shashkov & P. P.
//     Whalen, "The construction of compatible hydrodynamics algorithms utilizing conservation of
//     total energy", J. Comput. Phys. 146, 227 (1998): each zone's internal energy changes by
//     exactly minus the work its forces do on its two nodes with the time-centred velocities,
//     inside a predictor-corrector step, so total energy is conserved to round-off;
//   - a quadratic + linear artificial viscosity q = rho (C_Q du^2 + C_L c |du|) in compressed
//     zones (the form of Wilkins 1964/1980 and of E. J. Caramana, M. J. Shashkov & P. P. Whalen,
//     "Formulations of artificial viscosities for multi-dimensional shock wave computations",
//     J. Comput. Phys. 144, 70, 1998, in one dimension; constants below);
//   - zones of any ejecta::EquationOfState, grouped in regions (an explosive, then inert media);
//   - the programmed burn of sim/sources/programmed_burn.hpp: a zone is lit at t_L = t_0 + r/D (r its
//     initial centre's distance from r = 0), its burn fraction rises as (t - t_L) D / (1.5 dr),
//     never below the compression burn (1 - rho0/rho)/(1 - V_CJ) within one ramp width ahead of
//     the front, and the JWL pressure is multiplied by it; e0 is in the internal energy from t = 0;
//   - r = 0 is the symmetry centre (a rigid wall for j = 1); the outer node is free (a given
//     pressure, 0 or ambient, acts on it) or fixed;
//   - fixed Eulerian gauges record pressure, density and velocity every step.
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "sim/eos/eos.hpp"

namespace ejecta::exact {

// The programmed burn of one region (sim/sources/programmed_burn.hpp; BurnTable gives these numbers).
struct RadialBurn {
  double velocity = 0.0;          // detonation velocity D [m/s]; 0: not detonated (inert, F = 1)
  double rho0 = 0.0;              // unreacted density [kg/m^3]; 0: no compression burn
  double cjRelativeVolume = 0.0;  // V_CJ = 1 - p_CJ / (rho0 D^2); 0: no compression burn
  double initiationTime = 0.0;    // [s]; the front leaves r = 0 then
};

// A shell of one material between the previous region's outer radius (0 for the first) and
// `outerRadius`, uniform at the start.
struct RadialRegion {
  std::string name;
  double outerRadius = 0.0;  // [m]
  std::shared_ptr<const EquationOfState> eos;
  double density = 0.0;         // [kg/m^3]
  double specificEnergy = 0.0;  // [J/kg] (an explosive's includes e0)
  double velocity = 0.0;        // radial, outward positive [m/s]
  RadialBurn burn;
};

enum class RadialOuterBoundary { Free, Fixed };

struct RadialSetup {
  int geometry = 3;  // j: 1 planar, 2 cylindrical, 3 spherical
  std::vector<RadialRegion> regions;
  // Target zone width [m]: each region gets round(thickness / zoneWidth) zones (at least 1) of
  // equal width.
  double zoneWidth = 0.0;
  RadialOuterBoundary outer = RadialOuterBoundary::Free;
  double outerPressure = 0.0;  // [Pa] acting on a free outer node (0 or the ambient)
  // Time step dt = courant * dr / (c + 2 (C_L c + C_Q |du|)) over all zones (the viscous term
  // bounds the diffusive limit of q). On the harmonic oscillator the predictor-corrector below is
  // area-preserving (determinant 1) and stable for omega dt < 2, i.e. for Courant numbers up to 1
  // on the grid's fastest mode; 0.8 keeps a margin (the UNDEX gauges' peaks at 0.8 and 0.5 agree
  // to 0.3%, docs/undex.md).
  double courant = 0.8;
  // Artificial viscosity. C_Q = 2 spreads a strong shock over about pi sqrt(2 C_Q / (gamma + 1))
  // ~ 3 zones (von Neumann & Richtmyer's analysis, gamma ~ 3 for water and the products);
  // C_L = 0.2 damps the post-shock ringing of weak shocks, where the quadratic term vanishes,
  // while a weak water shock's width, about 2 C_L c / (beta du_s) zones (a Burgers shock,
  // beta = 1 + B/2A ~ 3.5), stays ~10 zones at the UNDEX gauges' 20 m/s jump.
  double quadraticViscosity = 2.0;
  double linearViscosity = 0.2;
  // Skip the zones the first disturbance has not reached: beyond it the medium is uniform and at
  // rest, its forces are zero and its state its initial one, so leaving it out of the step saves
  // cost (a quarter of an UNDEX run's) and nothing else; the node at its edge is held while its
  // velocity is below 1e-12 c (the scheme's round-off precursor), which moves the gauges by
  // ~1e-11 of their peak. false: every zone, every step.
  bool skipQuietZones = true;
};

// One gauge's history: a sample at t = 0 and after every step.
struct RadialGauge {
  std::string name;
  double radius = 0.0;           // [m], fixed (Eulerian)
  std::vector<double> time;      // [s]
  std::vector<double> pressure;  // [Pa]; NaN beyond the outer node
  std::vector<double> density;   // [kg/m^3]
  std::vector<double> velocity;  // radial [m/s]
};

// The flow at a fixed radius: pressure and density interpolated linearly between zone centres
// (the first/last zone's value between r = 0 and its centre / its centre and the outer node),
// velocity between nodes. NaN for all three beyond the outer node.
struct RadialSample {
  double pressure;
  double density;
  double velocity;
};

class RadialLagrangian {
 public:
  // Throws std::invalid_argument (naming the region and the reason) for j outside 1-3, no
  // regions, radii not increasing, a missing EOS, non-positive or non-finite density, zone width
  // or Courant number (above 1 too), a negative viscosity coefficient, a non-finite energy or
  // velocity, a negative detonation velocity or outer pressure.
  explicit RadialLagrangian(RadialSetup setup);

  // Records `name` at `radius` (>= 0, finite) from now on. Throws std::invalid_argument.
  void addGauge(std::string name, double radius);

  // Integrates to time t. Throws std::invalid_argument if t < time() and std::runtime_error
  // (naming the zone, its region and the time) if a zone inverts or a state turns non-finite.
  void advanceTo(double t);

  double time() const { return time_; }
  long steps() const { return steps_; }
  int geometry() const { return j_; }
  std::size_t zoneCount() const { return mass_.size(); }
  // Zones the steps integrate now: those the first disturbance has reached (skipQuietZones).
  std::size_t activeZones() const { return quiet_; }

  // Totals with the measure of the geometry: per unit area (j = 1, x > 0 only), per unit length
  // of the axis (j = 2, 2 pi r dr) or whole (j = 3, 4 pi r^2 dr).
  double totalMass() const;
  double internalEnergy() const;  // sum of zone mass x specific internal energy (e0 included)
  double kineticEnergy() const;   // sum of node mass x u^2 / 2
  double totalEnergy() const { return internalEnergy() + kineticEnergy(); }
  // Work done on the grid by the outer pressure so far: totalEnergy() - boundaryWork() is
  // constant to round-off.
  double boundaryWork() const { return boundaryWork_; }
  // Mass of one region, and its internal (zone mass x e) and kinetic energy (each zone's half
  // share of its two nodes' u^2 / 2), with the measure above. The regions' kinetic energies sum
  // to kineticEnergy() but for the centre node's. Throws std::invalid_argument for no such region.
  double regionMass(std::size_t region) const;
  double regionInternalEnergy(std::size_t region) const;
  double regionKineticEnergy(std::size_t region) const;

  RadialSample at(double radius) const;
  const std::vector<RadialGauge>& gauges() const { return gauges_; }

  // The grid: N + 1 nodes, N zones (zone k between nodes k and k + 1).
  const std::vector<double>& nodeRadius() const { return r_; }
  const std::vector<double>& nodeVelocity() const { return u_; }
  const std::vector<double>& zoneDensity() const { return rho_; }
  const std::vector<double>& zonePressure() const { return p_; }
  const std::vector<double>& zoneEnergy() const { return e_; }
  const std::vector<double>& zoneBurnFraction() const { return burnFraction_; }
  std::size_t zoneRegion(std::size_t zone) const { return zoneRegion_[zone]; }

 private:
  void step(double dt);
  double stableStep() const;
  // Pressure and sound speed of zones [0, count) from rho and e, the burn fraction at time t
  // (stored when `commit`), pressure scaled by it; then q from the node velocities u.
  void updateZones(std::size_t count, const std::vector<double>& rho, const std::vector<double>& e,
                   const std::vector<double>& u, double t, bool commit, std::vector<double>& p,
                   std::vector<double>& cs, std::vector<double>& q);
  // The first zone of the quiet region, from the initial state.
  std::size_t initialQuietZone() const;
  double zoneStepBound(std::size_t k) const;  // dr / (c + 2 (C_L c + C_Q |du|)) of one zone
  void recordGauges();
  [[noreturn]] void fail(std::size_t zone, const std::string& what) const;

  int j_;
  RadialSetup setup_;
  double measure_;  // 1, 2 pi, 4 pi
  double time_ = 0.0;
  long steps_ = 0;
  double boundaryWork_ = 0.0;
  double lastDt_ = 0.0;

  // Nodes.
  std::vector<double> r_, u_, nodeMass_;
  // Zones: mass per unit measure (rho times r^j/j differences), state, burn.
  std::vector<double> mass_, rho_, e_, p_, cs_, q_;
  std::vector<double> burnFraction_, lightingTime_, burnWidth_;
  std::vector<std::size_t> zoneRegion_;
  std::vector<std::vector<std::size_t>> regionZones_;  // zone indices of each region (EOS batches)
  // Zones [quiet_, N) are uniform, at rest and untouched since t = 0 (their nodes > quiet_ too);
  // quietBound_[k] is the smallest step bound of the initial zones [k, N) (N: infinity).
  std::size_t quiet_ = 0;
  std::vector<double> quietBound_;
  // Step scratch (no allocation in the step loop).
  std::vector<double> rHalf_, uNew_, rhoHalf_, eHalf_, pHalf_, csHalf_, qHalf_;

  std::vector<RadialGauge> gauges_;
};

}  // namespace ejecta::exact
