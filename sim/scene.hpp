#pragma once
// Scene: a validated, SI-unit description of one run, as read from a TOML scene file.
// Everything the Simulation assembles comes from here; the engine models no more than this asks.
#include <array>
#include <optional>
#include <string_view>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "sim/geometry.hpp"

namespace ejecta {

// Thrown for any bad scene: the message names the file, the line (when known), the key and the
// reason, e.g. "scenes/x.toml:12: key 'bodies[1].spacing': must be positive (got -0.1 m)".
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class KernelKind { CubicSpline, WendlandC2, WendlandC4 };
enum class DensityMethod { Summation, Continuity };
enum class SmoothingLengthMethod { Neighbours, Seed, Constant };
enum class BoundaryKind { Open, Periodic, Wall };
enum class LatticeKind { Cubic, Hexagonal };
enum class ShapeKind { Box, Sphere, Shell, HalfSpace };
enum class DepositProfile { TopHat, Gaussian };
// How pair forces weight the two particles' stresses (docs/materials.md):
//   Lagrangian: sigma_i/(Omega_i rho_i^2) + sigma_j/(Omega_j rho_j^2), from the grad-h Lagrangian;
//   Interface:  (sigma_i + sigma_j)/(rho_i rho_j), exact for uniform pressure across a density
//               jump, so material interfaces carry no spurious force (with volume-weighted
//               continuity density).
enum class MomentumForm { Lagrangian, Interface };

// Per-particle artificial viscosity (docs/undex.md, "Viscosity switch"): None keeps alpha
// constant; MorrisMonaghan evolves alpha_i between alpha_min and alpha (Morris & Monaghan 1997).
enum class ViscositySwitch { None, MorrisMonaghan };

// Velocities the viscosity's linear term compares (docs/undex.md, "The reconstructed viscosity"):
// None takes the particles' own. VanLeer carries each to the pair's midpoint along its velocity
// gradient, limited by van Leer's limiter of the two slopes, so that smooth flow (where the two
// reconstructions meet) feels no viscosity and a shock (where the limiter stops the
// reconstruction) the full one. Monotone first limits each particle's gradient (Barth &
// Jespersen) so that no reconstructed velocity leaves the range of those around it, which damps
// the ringing that VanLeer leaves behind a weak shock. The quadratic term always takes the raw
// velocities.
enum class ViscosityReconstruction { None, VanLeer, Monotone };

struct AxisBounds {
  double min = 0.0, max = 0.0;
  BoundaryKind lower = BoundaryKind::Open;   // boundary at min
  BoundaryKind upper = BoundaryKind::Open;   // boundary at max
  bool bounded = false;  // false: open in both directions with no box (min/max unused)
};

struct SphOptions {
  KernelKind kernel = KernelKind::CubicSpline;
  DensityMethod density = DensityMethod::Summation;
  SmoothingLengthMethod smoothingLength = SmoothingLengthMethod::Neighbours;
  double eta = 1.2;          // h = eta * (m/rho)^(1/d) for Neighbours (and initial h for all)
  double relaxation = 1.0;   // theta of the seed's eq. (1.5), Seed method only
  double courant = 0.3;      // xi of the seed's eq. (1.8)
  double forceFactor = 0.25; // dt <= forceFactor * sqrt(h/|a|)
  // Monaghan artificial viscosity, seed eqs. (1.6)-(1.7)
  double alpha = 1.0;
  double beta = 2.0;
  double epsilon = 0.01;     // phi^2 = epsilon * h_ij^2 regulariser
  bool balsara = false;      // Balsara (1995) shear switch
  // Morris & Monaghan (1997) switch: alpha is alpha_max, alphaMin the floor it decays to over
  // tau = h / (alphaDecay c); beta scales as beta/alpha_max times the pair's alpha.
  ViscositySwitch viscositySwitch = ViscositySwitch::None;
  double alphaMin = 0.1;
  double alphaDecay = 0.2;
  ViscosityReconstruction viscosityReconstruction = ViscosityReconstruction::None;
  double conductivity = 0.0; // Price (2008) artificial conductivity coefficient alpha_u; 0 = off
  double hMinFactor = 1e-3;  // h below hMinFactor * initial h is a collapse (run stops)
  MomentumForm form = MomentumForm::Lagrangian;
  // Monaghan (2000) / Gray, Monaghan & Swift (2001) artificial stress against the tensile
  // instability, applied to materials with strength: epsilon (0 = off; negative = the default,
  // 0.3 when the scene has a material with strength) and the exponent n of f = W(r)/W(dp).
  double artificialStress = -1.0;
  double artificialStressExponent = 4.0;
};

struct TimeOptions {
  double tEnd = 0.0;          // [s], required
  double dtMax = 0.0;         // [s], 0 = unlimited
  double dtMin = 0.0;         // [s], dt below this stops the run (0 = 1e-12 * tEnd)
  long maxSteps = 0;          // 0 = unlimited
};

// One optional model table of a material ([materials.thermal], [materials.strength],
// [materials.fracture]): a model name, a library entry, and values in SI by key.
struct ModelSpec {
  bool present = false;
  std::string model;
  std::string library;
  std::vector<std::pair<std::string, double>> values;
  int line = 0;
  const double* find(std::string_view key) const {
    for (const auto& [k, v] : values)
      if (k == key) return &v;
    return nullptr;
  }
};

struct MaterialSpec {
  std::string name;
  std::string eos = "ideal_gas";  // a kind of sim/eos_catalog.hpp
  double gamma = 1.4;             // ideal gas adiabatic index
  std::string library;            // library entry of the eos (e.g. "granite"); empty: none
  std::vector<std::pair<std::string, double>> parameters;  // overrides, SI
  ModelSpec thermal;              // keys: sim/materials.cpp; docs/scenes.md
  ModelSpec strength;
  ModelSpec fracture;
  int line = 0;                   // source line in the scene file, for later messages
};

struct ShapeSpec {
  ShapeKind kind = ShapeKind::Box;
  std::array<double, 3> min{}, max{};       // Box
  std::array<double, 3> center{};           // Sphere, Shell (a disc in 2D, a segment in 1D)
  double radius = 0.0;                      // Sphere; Shell outer radius
  double innerRadius = 0.0;                 // Shell
  std::array<double, 3> point{};            // HalfSpace: a point on the plane
  std::array<double, 3> normal{};           // HalfSpace: outward normal; inside is behind it
};

struct BodySpec {
  std::string name;
  int material = 0;                         // index into Scene::materials
  ShapeSpec shape;
  LatticeKind lattice = LatticeKind::Cubic;
  double spacing = 0.0;                     // [m]
  double density = 0.0;                     // [kg/m^3]
  // [Pa] or [J/kg]: exactly one, except for a body of a detonated JWL explosive, which may give
  // neither and then starts at the explosive's detonation energy e0 = E0 / rho0.
  std::optional<double> pressure;
  std::optional<double> internalEnergy;
  std::array<double, 3> velocity{};         // [m/s]
  double damage = 0.0;                      // initial damage D in [0, 1] (1: rubble)
  int line = 0;
  // Its index among the file's [[bodies]] entries, voids included, for messages; -1: the same
  // as its index in Scene::bodies (a body built in code).
  int entry = -1;
};

// A crater's bowl: a paraboloid of revolution about `axis` (a parabola in 2D planar) with its
// vertex at `floor`, opening along `axis` (unit), `radius` wide at `depth` above the floor and
// open beyond, as a crater opens to space.
struct BowlSpec {
  std::array<double, 3> floor{};
  std::array<double, 3> axis{};
  double depth = 0.0;
  double radius = 0.0;
};

// A void: a [[bodies]] entry with `void = true`. It makes no particles but claims its space as a
// body does, so the bodies listed after it lose their particles there (earlier bodies win): the
// crater an impactor left, a cavity. Kept apart from Scene::bodies, the bodies with particles,
// so that the energy ledger, the crater analysis and the restarts never see it.
struct VoidSpec {
  std::string name;
  bool isBowl = false;          // shape = "paraboloid": `bowl`; otherwise `shape`
  ShapeSpec shape;
  BowlSpec bowl;
  std::size_t firstCarved = 0;  // index in Scene::bodies of the first body it carves
  int line = 0;
};

// Direct energy deposition (DED): energy added at `time` (default 0) to the particles of a region,
// or of one body (the device, as the seed's Sec. 3.1.1 models a yield as high-energy granite
// particles). A delayed deposit (time > 0) goes to the particles in its region at that moment.
struct EnergyDepositSpec {
  std::string name;
  double energy = 0.0;                      // [J]; in 2D planar per metre depth
  double time = 0.0;                        // [s]; > 0: fired at the first step start >= time
  int body = -1;                            // index into Scene::bodies; -1: every particle
  bool hasCenter = true;                    // false: a body deposit over the whole body
  std::array<double, 3> center{};
  double radius = 0.0;                      // TopHat: particles with |x - c| <= radius
  DepositProfile profile = DepositProfile::TopHat;
  double width = 0.0;                       // Gaussian: exp(-r^2/width^2)
  int line = 0;
};

// A detonation of a JWL explosive by programmed burn (docs/sources.md): each particle of the
// material is lit at t_L = time + (distance to the initiation point or line) / velocity, and its
// pressure is scaled by a burn fraction that rises from 0 to 1 as the front crosses it.
struct DetonationSpec {
  std::string name;
  int material = 0;                         // index into Scene::materials (a JWL explosive)
  std::array<double, 3> point{};            // initiation point, or the start of the line
  bool alongLine = false;                   // true: initiated along the segment point -> lineEnd
  std::array<double, 3> lineEnd{};
  double time = 0.0;                        // initiation time [s]
  double velocity = 0.0;                    // [m/s]; 0 = the explosive's C-J velocity
  int line = 0;                             // source line in the scene file
};

// A gauge: a fixed point whose pressure, density and velocity are written every step
// (gauges.csv; sim/gauges.hpp).
struct GaugeSpec {
  std::string name;
  std::array<double, 3> position{};
  int line = 0;
};

struct OutputOptions {
  double snapshotInterval = 0.0;            // [s]; 0 = first and last only
  bool snapshots = true;
};

// How grids are normalised (docs/fields.md): Shepard divides by the kernel-weighted volume sum, so
// intensive fields (temperature, pressure) keep their value up to a free surface; None keeps the
// plain SPH sum, which falls to zero across a free surface (density, material fractions).
enum class FieldNormalisation { Auto, Shepard, None };

// [fields]: sparse VDB grids written during the run (fields/, docs/fields.md).
struct FieldsOutputOptions {
  bool enabled = false;                 // the scene has a [fields] table
  // Particle fields by name (sim/particle_fields.hpp), "fractions" (one per material) or
  // "fraction_<material>".
  std::vector<std::string> grids{"density", "temperature", "pressure", "damage", "fractions"};
  double voxel = 0.0;                   // [m]; 0 = the median smoothing length
  FieldNormalisation normalise = FieldNormalisation::Auto;
  int every = 1;                        // write with every Nth snapshot (and the last)
  bool levelSet = true;                 // a surface level set of all material
  double extrude = 0.0;                 // 2D planar: slab depth [m]; 0 = one voxel
  bool clip = false;                    // only voxels inside [regionMin, regionMax]
  std::array<double, 3> regionMin{}, regionMax{};  // grid coordinates (RZ: revolved about y)
};

// [crater]: the crater measured at the end of an impact run (fields/crater.hpp).
struct CraterAnalysisOptions {
  // Measured when the scene is an impact: a moving body strikes bodies at rest (2D, RZ, 3D).
  bool enabled = true;
  std::vector<std::string> materials;   // target materials; empty: those of the bodies at rest
  double resolution = 0.0;              // [m]; 0 = half the median smoothing length
};

// [images.camera]: where a 3D picture is taken from (a perspective camera). The ejecta 3D scenes
// have the target's surface normal along +z, so z is up unless the scene says otherwise.
struct ImageCamera {
  std::array<double, 3> position{};         // [m]
  std::array<double, 3> target{};           // [m]
  std::array<double, 3> up{0.0, 0.0, 1.0};  // any vector not along the line of sight
  double fovDegrees = 30.0;                 // vertical field of view
};

// [images]: pictures of the particles at the snapshot cadence, images/<field>_NNNN.png (apps/
// particle_images.hpp over render/), and charts of the run's CSVs at the end.
struct ImageOutputOptions {
  bool enabled = false;                 // the scene has an [images] table
  std::vector<std::string> fields{"density"};  // particle fields (sim/particle_fields.hpp)
  std::vector<std::string> log;         // fields drawn on a log scale
  int every = 1;                        // with every Nth snapshot (and the last)
  int size = 1024;                      // pixels (square)
  std::string cut = "z";                // 3D: keep x, y or z <= cutAt; "none"
  // Where the cut's plane crosses its axis [m]; none: 0 for particles, and for the surface
  // picture 0 when the surface spans it, else the surface's middle.
  std::optional<double> cutAt;
  std::optional<ImageCamera> camera;    // 3D; none: an automatic camera that frames everything
  // Pictures of the grid files of [fields] (apps/grid_images.hpp), at the outputs both tables'
  // cadences select: slices through the plane z = 0 of these grids, images/grid_<name>_NNNN.png,
  // and the surface level set coloured by temperature, images/surface_NNNN.png.
  std::vector<std::string> grids;
  bool surface = false;
};

// [thermal]: the radiation chain (radiation/thermal_study.hpp) run in-situ on the particles at
// chosen output times: the flux on the spacecraft's faces along its pass, their temperatures and
// the shield sizing, written to thermal_NNNN/ (apps/run_thermal.hpp, docs/thermal.md).
struct ThermalOutputOptions {
  bool enabled = false;                 // the scene has a [thermal] table
  // The study file: a path relative to the scene file's folder, or the name of a study compiled
  // in with the scenes ("thermal/follower"), which is how the embedded default scene names it.
  std::string study;
  // Run at the first output at or after each of these times [s]; empty: at the last output.
  std::vector<double> times;
  // false: each pass flies over the hot material of one output (a snapshot's, frozen during the
  // pass). true: each pass starts at its time and flies while the run goes on, each of its sample
  // times seeing the material of that moment (the step at or after it).
  bool evolving = false;
  int line = 0;                         // where [thermal] is, for messages
};

struct Scene {
  std::string name;
  std::string description;
  std::string sourcePath;                   // file it came from ("<default>" when embedded)
  Geometry geometry = Geometry::Planar;
  std::array<AxisBounds, 3> domain{};       // per axis; RZ: axis 0 is r (lower bound = the axis)
  SphOptions sph;
  TimeOptions time;
  std::vector<MaterialSpec> materials;
  std::vector<BodySpec> bodies;             // earlier bodies win where shapes overlap
  std::vector<VoidSpec> voids;              // [[bodies]] entries with void = true
  std::vector<EnergyDepositSpec> deposits;
  std::vector<DetonationSpec> detonations;
  std::vector<GaugeSpec> gauges;
  OutputOptions output;
  FieldsOutputOptions fields;
  CraterAnalysisOptions crater;
  ImageOutputOptions images;
  ThermalOutputOptions thermal;
};

// Reads and validates a scene file. `overrides` are "dotted.key=value" strings applied before
// validation (the command line's --set). Throws SceneError.
Scene loadScene(const std::string& path, const std::vector<std::string>& overrides = {});
// Same, from TOML text; `sourceName` is used in messages.
Scene parseScene(const std::string& tomlText, const std::string& sourceName,
                 const std::vector<std::string>& overrides = {});

}  // namespace ejecta
