#pragma once
// What a run writes besides its particles ([output], [fields], [crater], [images], [thermal]).
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace ejecta {

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
  // Particle fields by name (sim/state/particle_fields.hpp), "fractions" (one per material) or
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
  // The pi-group scaling class the crater is set beside (fields/crater_scaling.hpp); empty: none.
  std::string scaling;
  std::optional<double> gravity;        // [m/s^2] for the scaling; none: a uniform sphere's
  std::optional<double> strength;       // [Pa] Y for the scaling; none: the class's
};

// [fragments]: fragment identification at the end of the run and at chosen outputs
// (fields/fragments.hpp, docs/fragments.md).
struct FragmentAnalysisOptions {
  bool enabled = false;                 // the scene has a [fragments] table
  double linkFactor = 2.0;              // friends within linkFactor (h_i + h_j) / 2
  double damageThreshold = 0.99;        // failed particles link to nobody
  double resolvedSpacings = 4.0;        // sizes below this many spacings are not measured
  int every = 0;                        // also with every Nth snapshot; 0 = at the end only
};

// [shield]: a Whipple shield's perforation verdict, rear-wall deflection and debris cloud
// (fields/shield_analysis.hpp, docs/whipple.md).
struct ShieldAnalysisOptions {
  bool enabled = false;                 // the scene has a [shield] table
  std::string wall;                     // the rear wall's body (a box, its material its own)
  std::string bumper;                   // the bumper's body (a box); empty: none
  double damageThreshold = 0.99;        // wall particles at or above it have failed
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
  std::vector<std::string> fields{"density"};  // particle fields (sim/state/particle_fields.hpp)
  std::vector<std::string> log;         // fields drawn on a log scale
  int every = 1;                        // with every Nth snapshot (and the last)
  int size = 1024;                      // pixels (square)
  std::string cut = "z";                // 3D: keep x, y or z <= cutAt; "none"
  // Where the cut's plane crosses its axis [m]; none: 0 for particles, and for the surface
  // picture 0 when the surface spans it, else the surface's middle.
  std::optional<double> cutAt;
  std::optional<ImageCamera> camera;    // 3D; none: an automatic camera that frames everything
  // Pictures of the grid files of [fields] (coupling/grid_images.hpp), at the outputs both tables'
  // cadences select: slices through the plane z = 0 of these grids, images/grid_<name>_NNNN.png,
  // and the surface level set coloured by temperature, images/surface_NNNN.png.
  std::vector<std::string> grids;
  bool surface = false;
};

// [thermal]: the radiation chain (radiation/thermal_study.hpp) run in-situ on the particles at
// chosen output times: the flux on the spacecraft's faces along its pass, their temperatures and
// the shield sizing, written to thermal_NNNN/ (coupling/run_thermal.hpp, docs/thermal.md).
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

}  // namespace ejecta
