#pragma once
// The whole radiation chain for one spacecraft pass (docs/thermal.md): a study file names the
// spacecraft, its approach trajectory, how hot material is selected and how bright it is, the
// wall of every face, the structural limit and the candidate coatings. Given the hot material as
// plain emitter arrays (the caller reads them from a snapshot, coupling/snapshot_emitters.hpp, or a
// grid file, coupling/grid_emitters.hpp) and optionally an occluder (the asteroid's surface:
// coupling/surface_occluder.hpp), the chain
//   1. moves the spacecraft along the trajectory and ray-casts the incident flux on every patch
//      at each sample time, with its standard error (view_factors.hpp);
//   2. turns the peak flux into the steady face temperature of the seed's eq. 4.8
//      (radiative_balance.hpp), next to the seed's own geometric estimate (solid_angle_baseline);
//   3. solves the layered wall of every patch through the flux history (wall_implicit.hpp);
//   4. sizes each candidate coating on the structural layer for every patch (shield_sizing.hpp),
//      with the added mass from the patch areas.
// The library writes no files: the command (apps/cmd_thermal.cpp) writes the outputs.
// Errors in a study file read "FILE:LINE: key 'a.b': reason" (ThermalStudyError).
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/input_error.hpp"
#include "radiation/emitters.hpp"
#include "radiation/geometry_file.hpp"
#include "radiation/layered_wall.hpp"
#include "radiation/shield_sizing.hpp"
#include "radiation/solid_angle_baseline.hpp"
#include "radiation/view_factors.hpp"

namespace ejecta::radiation {

// A bad thermal study file, or a study its spacecraft cannot run (a wall on a missing patch).
class ThermalStudyError : public InputError {
 public:
  using InputError::InputError;
};

// A straight pass at constant velocity: the body origin is at `start` at t = 0 and the flux is
// sampled at `samples` evenly spaced times in [0, duration].
struct ApproachSpec {
  Vec3 target{};                 // the point approached (the crater) [m]
  Vec3 start{};                  // body origin at t = 0 [m]
  Vec3 velocity{};               // [m/s]
  double duration = 1e-3;        // [s]
  int samples = 11;              // >= 2
  std::vector<double> times() const;
};

// Which hot material radiates and how much.
struct EmitterChoice {
  double minTemperature = kMoltenRockThreshold;        // [K]
  double defaultEmissivity = kGraniteEmissivity;       // granite, the seed's 0.45 (its ref. [27])
  std::map<std::string, double> emissivityByMaterial;  // by material name
};

// The wall of one or more patches, layers from the hot face to the cold one.
struct WallSpec {
  std::vector<std::string> patches;   // empty: every patch without a wall of its own
  std::vector<WallLayer> layers;      // hot to cold; the last one is the structure
  // Hot-face optics for the emitters' radiation; unset: the outer layer material's.
  std::optional<double> absorptivity, emissivity;
  // Cold face: insulated when coldEmissivity is 0, else radiating to 0 K.
  double coldEmissivity = 0.0;
  int line = 0;                       // where it was given, for messages
};

struct SizingSpec {
  std::vector<std::string> coatings;  // wall material names; empty: no sizing
  std::vector<std::string> patches;   // empty: every patch
  double maxThickness = 5e-3;         // [m]
  double tolerance = 1e-3;            // relative bracket width
  int coatingCells = 10;
};

struct ThermalStudy {
  std::string source;                 // the file, for messages and the report
  std::string name, description;
  SpacecraftSpec spacecraft;          // body shape and attitude; the pose's position/velocity come
                                      // from the approach
  ApproachSpec approach;
  EmitterChoice emitters;
  std::vector<WallSpec> walls;        // a patch takes the first wall that names it, else the
                                      // first wall with no patch list
  ShieldLimit limit;                  // for the structural layer
  double initialTemperature = 293.15; // [K]
  double timeStep = 0.0;              // wall solver step [s]; 0: duration / 2000
  SizingSpec sizing;
  SamplingOptions sampling;           // default: 1e-3 absolute on view factors, max 2^22 rays
  BaselineOptions baseline;
};

// Parses TOML text; `baseDirectory` resolves a spacecraft mesh path. Throws ThermalStudyError.
ThermalStudy parseThermalStudy(const std::string& tomlText, const std::string& sourceName,
                               const std::filesystem::path& baseDirectory);
ThermalStudy loadThermalStudy(const std::filesystem::path& path);

// Per patch results.
struct PatchThermal {
  std::string patch;
  double area = 0.0;                   // [m^2]
  std::vector<Estimate> flux;          // per sample time [W/m^2]
  std::vector<double> seedFlux;        // the seed's eq. 4.7 sum per sample time
  double peakFlux = 0.0, peakFluxError = 0.0;
  double peakTime = 0.0;               // [s]
  double peakSeedFlux = 0.0;           // the largest seed sum over the samples
  double absorptivity = 0.0, emissivity = 0.0;   // hot-face optics used
  double steadyTemperature = 0.0;      // eq. 4.8 at the peak flux with those optics [K]
  double seedSteadyTemperature = 0.0;  // eq. 4.8 at the seed's sum with its optics 0.08 / 0.02
  std::optional<WallHistory> wall;     // transient solve (absent when the patch has no wall)
  std::vector<double> layerPeak;       // per layer [K]
  std::vector<double> layerMeltTime;   // per layer [s], NaN: never
  double structureLimit = 0.0;         // [K]
  bool structureWithinLimit = true;
  std::vector<ShieldSizing> sizing;    // per candidate coating (when sized)
  // With an occluder: the view factor from the patch to it at each sample time (what the
  // asteroid's surface fills of the face's view), and at the peak-flux sample.
  std::vector<Estimate> toOccluder;
  double peakOccluderFactor = 0.0;
};

struct ThermalResult {
  std::string name, source;
  std::vector<double> times;           // flux sample times [s]
  std::size_t emitterCount = 0;
  std::size_t occluderTriangles = 0;   // 0: nothing but the spacecraft itself blocks rays
  std::vector<std::string> groupNames;
  std::uint64_t rays = 0;              // rays cast in all
  double raySeconds = 0.0, wallSeconds = 0.0, sizingSeconds = 0.0;
  std::vector<PatchThermal> patches;
  // Per coating: the sum over sized patches of the added mass [kg] (NaN if any is infeasible).
  std::map<std::string, double> totalAddedMass;
};

// The whole chain on the given emitters (static during the pass: a snapshot's). An empty emitter set gives
// zero flux everywhere. Throws ThermalStudyError for a wall or sizing patch the spacecraft lacks.
ThermalResult runThermalStudy(const ThermalStudy& study, const Emitters& emitters);
// The same with an occluder (nullptr or empty: none): an opaque triangle mesh, static during the
// pass like the emitters, that neither emits nor receives: the asteroid's surface (a meshed
// level set, coupling/surface_occluder.hpp). A ray from a patch that meets it before an emitter is
// blocked. Throws MeshError for a malformed mesh.
ThermalResult runThermalStudy(const ThermalStudy& study, const Emitters& emitters,
                              const TriangleMesh* occluder);

// The hot material and the occluder the spacecraft sees at one sample time of its pass.
struct PassFrame {
  const Emitters* emitters = nullptr;   // required
  const TriangleMesh* occluder = nullptr;
};
// The same with material that evolves during the pass: frames[i] at the approach's sample time
// i (ApproachSpec::times()), as a run captures them while it advances (coupling/run_thermal.hpp). The
// result's emitterCount and groupNames are the largest frame's. Throws ThermalStudyError unless
// there is one frame per sample time, each with emitters.
ThermalResult runThermalStudy(const ThermalStudy& study, const std::vector<PassFrame>& frames);

// Outputs, as text (the caller writes them): the flux table "time_s,<patch>,<patch>_se,..."; the
// sizing table; the summary as JSON (docs/thermal.md lists the fields).
std::string formatThermalFluxCsv(const ThermalResult& result);
std::string formatThermalSizingCsv(const ThermalResult& result);
std::string formatThermalJson(const ThermalResult& result, const std::string& extraJsonFields = "");
std::string formatThermalText(const ThermalResult& result);

}  // namespace ejecta::radiation
