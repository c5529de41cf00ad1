#pragma once
// Ballistic limits from simulation (`ejecta whipple-limit`, issue 21): for a Whipple-shield scene
// (one with a [shield] table, fields/shield_analysis.hpp), bisect the projectile's diameter at
// each chosen speed between a diameter that does not perforate the rear wall and one that does,
// running the scene for each; the critical diameter lies between the last two. Beside it, the
// same shield's critical diameter by Christiansen's ballistic-limit equations
// (radiation/whipple.hpp), with the plates' thicknesses, standoff and densities read from the
// scene. Each shot is a run directory of its own; a shot already run is read back, not redone,
// so a study resumes where it stopped.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "radiation/whipple.hpp"
#include "sim/setup/scene.hpp"

namespace ejecta::coupling {

struct LimitSearchOptions {
  std::vector<double> speeds;           // [m/s]
  double smallest = 0.0, largest = 0.0; // the starting bracket of diameters [m]
  int iterations = 4;                   // bisections after the two ends
  std::vector<std::string> overrides;   // --set, for every shot (e.g. a coarser spacing)
  std::filesystem::path outDir;         // a folder per shot below it
  int threads = 0;
  // The rear wall's yield stress for the BLE [Pa]; unset: the wall material's strength
  // (Johnson-Cook A, or the von Mises yield stress).
  std::optional<double> wallYield;
  // Told of each shot as it ends (speed, diameter, perforated, seconds; read back: seconds < 0).
  std::function<void(double, double, bool, double)> onShot;
};

struct LimitShot {
  double speed = 0.0, diameter = 0.0;   // [m/s], [m]
  bool perforated = false;
  std::string reason;                   // the verdict's reason (fields/shield_outputs.hpp)
  double wallSeconds = 0.0;             // the run's; 0 when read back
};

struct SpeedLimit {
  double speed = 0.0;                   // [m/s]
  std::optional<double> largestHeld;    // [m] the largest diameter that did not perforate
  std::optional<double> smallestPerforating;  // [m] the smallest that did
  // The midpoint of the bracket, when both ends were found; else unset (the limit is outside
  // the starting bracket: the nearer end bounds it).
  std::optional<double> critical;
  radiation::BallisticLimit equations;  // Christiansen's, for the same shield
};

struct LimitSearchResult {
  radiation::WhippleShield shield;      // as the scene gives it (the BLE's inputs)
  double projectileDensity = 0.0;       // [kg/m^3]
  double impactAngle = 0.0;             // [rad] from the plates' normal
  std::vector<SpeedLimit> limits;
  std::vector<LimitShot> shots;
};

// The BLE's shield from a [shield] scene: bumper and wall thicknesses along the normal, the
// standoff between them, the bumper's density, the wall's yield stress. Throws SceneError when
// the scene has no [shield] with a bumper, or no yield stress can be found for the wall.
radiation::WhippleShield shieldOfScene(const Scene& scene, std::optional<double> wallYield);

// Runs the search on the scene (its text and label, for the shots' runs). Throws SceneError for
// a scene whose projectile is not a sphere, and std::invalid_argument for a bad bracket.
LimitSearchResult searchBallisticLimits(const std::string& sceneText, const std::string& label,
                                        const LimitSearchOptions& options);

// limits.csv: speed, the bracket, the critical diameter, the BLE's; shots.csv: every shot.
std::string limitsCsv(const LimitSearchResult& result);
std::string shotsCsv(const LimitSearchResult& result);

}  // namespace ejecta::coupling
