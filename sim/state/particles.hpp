#pragma once
// ParticleSet: the state of every particle, stored as a structure of arrays so that the pair
// loops stream through contiguous memory. Real (owned) particles occupy [0, numReal); ghost
// particles (mirror images at walls and the RZ axis, periodic images) follow them and are
// rebuilt every step from their sources.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "sim/state/field_spec.hpp"

namespace ejecta {

using Vec3Array = std::array<std::vector<double>, 3>;
using StressArray = std::array<std::vector<double>, 6>;

// Where the values of a declared field live in a ParticleSet: a named member (the built-in
// fields, which the hot loops use by name), a column of a package's own, or nowhere (derived).
struct FieldStorage {
  enum class Kind { Scalar, Vector, Stress, Int32, Int64, Extra, Derived };
  Kind kind = Kind::Derived;
  std::vector<double> ParticleSet::*scalar = nullptr;
  Vec3Array ParticleSet::*vector = nullptr;
  StressArray ParticleSet::*stress = nullptr;
  std::vector<int> ParticleSet::*int32 = nullptr;
  std::vector<std::int64_t> ParticleSet::*int64 = nullptr;
  std::size_t extra = 0;  // Extra: index of the package's first column
};

// One field a ParticleSet carries: its declaration and where its values are.
struct Field {
  FieldSpec spec;
  FieldStorage storage;
};

// The built-in fields come in groups that a run carries only when a term needs them.
enum class FieldGroup { Core, Fracture, Strength, Burn, ViscositySwitch, Package };

struct ParticleSet {
  // The Core group's fields declared (sim/state/builtin_fields.cpp), no particles.
  ParticleSet();

  // --- Primary state (integrated in time; written to snapshots) ---
  Vec3Array x;                  // position [m]; RZ: x[0] = r, x[1] = z
  Vec3Array v;                  // velocity [m/s]
  std::vector<double> mass;     // [kg]; in RZ the whole ring's mass; 2D planar: per metre depth
  std::vector<double> rho;      // mass density [kg/m^3]
  std::vector<double> u;        // specific internal energy [J/kg]
  std::vector<double> h;        // smoothing length [m]
  std::vector<int> material;    // index into the MaterialTable
  std::vector<std::int64_t> id; // stable identity, survives reordering

  // --- Derived by the equation of state ---
  std::vector<double> P;        // pressure [Pa]
  std::vector<double> cs;       // sound speed [m/s]

  // --- Time derivatives (kept between steps: the leapfrog needs them, restarts store them) ---
  Vec3Array a;                  // acceleration [m/s^2]
  std::vector<double> du_dt;    // [J/kg/s]
  std::vector<double> drho_dt;  // [kg/m^3/s] (continuity density only)
  std::vector<double> dh_dt;    // [m/s]

  // --- Auxiliary per-step quantities of the density pass ---
  std::vector<double> omega;    // grad-h correction factor (1 when h is not tied to density)
  std::vector<double> divv;     // velocity divergence estimate [1/s]
  std::vector<double> curlv;    // |curl v| estimate [1/s]
  std::vector<double> areaDensity;  // RZ only: eta = 2 pi r rho [kg/m^2], the 2D summation

  // --- Thermal state (derived from u by each material's thermal model) ---
  std::vector<double> temperature;  // [K]

  // --- Solid mechanics: allocated only when a material has strength (enableStrength) ---
  // Deviatoric stress [Pa], components in sim/state/tensor.hpp order (xx, yy, zz, xy, xz, yz); the
  // first stressComponents() are used (4 in 1D, 2D and RZ, where zz is the hoop stress; 6 in 3D).
  StressArray stress;
  StressArray dstress_dt;  // [Pa/s]
  std::vector<double> plasticStrain;  // equivalent plastic strain
  std::vector<double> totalStrain;    // equivalent total strain, integral of strainRate
  std::vector<double> strainRate;     // equivalent strain rate sqrt(2/3 e':e') [1/s]

  // --- Fracture: allocated only when a material can fracture (enableFracture) ---
  // Crack fraction s = D^(1/3) (Benz & Asphaug 1994: the crack length over the particle size),
  // integrated in time; the damage is D = s^3. 1 = fully damaged: no tension, no shear.
  std::vector<double> crack;
  std::vector<double> dcrack_dt;      // [1/s]

  // --- Programmed burn: allocated only when the scene detonates an explosive (enableBurn) ---
  // Lighting time t_L [s] (-infinity: not an explosive, always burnt) and burn fraction F in
  // [0, 1], the factor on the JWL pressure (sim/sources/programmed_burn.hpp). F never decreases.
  std::vector<double> lightingTime;
  std::vector<double> burnFraction;

  // --- Viscosity switch: allocated only when the scene evolves alpha (enableViscositySwitch) ---
  // Per-particle Monaghan viscosity coefficient alpha_i (Morris & Monaghan 1997), integrated in
  // time like u, and its rate.
  std::vector<double> alpha;
  std::vector<double> dalpha_dt;     // [1/s]

  std::size_t numReal = 0;
  // For ghost k (index numReal + k): the real particle it images.
  std::vector<std::size_t> ghostSource;

  std::size_t size() const { return mass.size(); }
  int stressComponents() const { return stressComponents_; }
  bool hasFracture() const { return fracture_; }
  bool hasBurn() const { return burn_; }
  bool hasViscositySwitch() const { return viscositySwitch_; }
  double damage(std::size_t i) const { return fracture_ ? crack[i] * crack[i] * crack[i] : 0.0; }
  // Allocate (zeroed) the solid-mechanics arrays for `components` stress components (4 or 6).
  void enableStrength(int components);
  // Allocate (zeroed) the fracture arrays.
  void enableFracture();
  // Allocate the burn arrays: every particle burnt (t_L = -infinity, F = 1) until set.
  void enableBurn();
  // Allocate the viscosity-switch arrays: alpha = `initial` everywhere, rate 0.
  void enableViscositySwitch(double initial);
  std::size_t numGhosts() const { return size() - numReal; }

  // --- The field registry (sim/state/field_spec.hpp) ---
  // Every field this set carries, in the order the leapfrog advances them: the Core group, then
  // Fracture before Strength (a crack's cap is computed from the stress before its kick), then
  // Burn, the viscosity switch, and packages' fields in the order they were declared.
  const std::vector<Field>& fields() const { return fields_; }
  // The field called `name`, or nullptr.
  const Field* field(std::string_view name) const;
  // Component c of a Float64 field with storage (throws std::logic_error otherwise).
  std::vector<double>& column(const Field& f, int c);
  const std::vector<double>& column(const Field& f, int c) const;
  // Declares a package's Float64 field (FieldGroup::Package), its entries set to spec.fill. A
  // field of that name already carried (e.g. read back from a snapshot) keeps its values and
  // takes this declaration; its component count must match (std::invalid_argument otherwise).
  void declare(const FieldSpec& spec);
  // Sets the range of a Clamp-limited field (the viscosity switch's alpha from the scene).
  void setClampRange(std::string_view name, double lo, double hi);

  // A set with the same fields declared (groups, package columns, stress components) and no
  // particles: what a gather fills, without copying this set's values.
  ParticleSet withSameFields() const;

  // Resize every array to n particles (new entries zeroed; omega set to 1).
  void resize(std::size_t n);
  // Append one particle with primary state; derived fields zeroed.
  void append(const std::array<double, 3>& pos, const std::array<double, 3>& vel, double m,
              double density, double specificEnergy, double smoothingLength, int mat);
  // Drop all ghosts.
  void clearGhosts();
  // Reorder real particles by the permutation `order` (new[i] = old[order[i]]). Ghosts are
  // dropped first.
  void permute(const std::vector<std::size_t>& order);

 private:
  void addGroup(FieldGroup group);
  template <typename F> void forEachColumn(F&& f);

  std::vector<Field> fields_;
  std::vector<FieldGroup> fieldGroups_;       // the group of each entry of fields_
  std::vector<std::vector<double>> extra_;    // packages' columns
  int stressComponents_ = 0;
  bool fracture_ = false;
  bool burn_ = false;
  bool viscositySwitch_ = false;
};

}  // namespace ejecta
