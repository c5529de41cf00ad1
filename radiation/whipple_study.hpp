#pragma once
// A Whipple-shield study file (TOML) and what `ejecta whipple` reports from it: the
// ballistic-limit curve of the shield for every rear-wall thickness listed, the critical diameter
// at the threat's speed, and, for a threat of given size, the rear wall that stops it (the BLE
// solved for t_w, and Christiansen's sizing equations). radiation/whipple.hpp has the equations;
// docs/whipple.md the file format and the seed's examples (scenes/whipple/).
//
//   [shield]  bumper_thickness, bumper_density, wall_thickness (one or a list), wall_density,
//             wall_yield, standoff, area (optional: masses)
//   [threat]  density, angle, diameter and speed (both optional: the design point)
//   [curve]   speed_min, speed_max, samples
//   [options] max_obliquity
// Quantities are numbers (SI) or strings with a unit: "0.16 cm", "2.8 g/cm^3", "37 ksi",
// "10 km/s", "45 deg", "16 m^2". Errors read "FILE:LINE: key 'a.b': reason" (WhippleStudyError).
// The library writes no files: the command does.
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/input_error.hpp"
#include "radiation/whipple.hpp"

namespace ejecta::radiation {

// A bad Whipple shield file, or a shield or threat the equations reject.
class WhippleStudyError : public InputError {
 public:
  using InputError::InputError;
};

struct WhippleThreat {
  double density = 0.0;   // projectile [kg/m^3]
  double angle = 0.0;     // from the bumper normal [rad]
  double diameter = 0.0;  // design projectile [m]; 0: none
  double speed = 0.0;     // design speed [m/s]; 0: none
};

struct WhippleStudy {
  std::string source, name, description;
  WhippleShield shield;                 // wallThickness = wallThicknesses.front()
  std::vector<double> wallThicknesses;  // [m]: one curve each, in the file's order
  double area = 0.0;                    // shielded area [m^2]; 0: no masses
  WhippleThreat threat;
  double speedMin = 0.5e3, speedMax = 15e3;  // [m/s]
  int samples = 146;
  WhippleOptions options;
};

// Parses TOML text. Throws WhippleStudyError.
WhippleStudy parseWhippleStudy(const std::string& tomlText, const std::string& sourceName);
WhippleStudy loadWhippleStudy(const std::filesystem::path& path);

struct WhippleWallResult {
  WhippleShield shield;                    // with this wall
  std::vector<BallisticLimitPoint> curve;
  BallisticLimitPoint weakest;             // the smallest d_c on the curve
  std::optional<BallisticLimit> atThreat;  // at the threat's speed, when given
  std::optional<bool> stopsThreat;         // d_c >= the threat's diameter (needs both)
  double arealMass = 0.0;                  // [kg/m^2]; 0 when wall_density is not given
};

// For a threat of given diameter and speed.
struct WhippleDesign {
  double wallAtThreatSpeed = 0.0;   // t_w with d_c = d at the threat's speed [m]
  double wallUpToThreatSpeed = 0.0; // t_w with d_c >= d at every curve speed up to the threat's [m]
  double governingSpeed = 0.0;      // the speed that sets wallUpToThreatSpeed [m/s]
  WhippleSizing sizing;             // Christiansen's design equations at the threat's speed
  bool bumperAdequate = false;      // t_b >= c_b d rho_p / rho_b
};

struct WhippleResult {
  WhippleStudy study;
  RegimeBoundaries boundaries;
  std::vector<WhippleWallResult> walls;
  std::optional<WhippleDesign> design;
};

// Throws WhippleStudyError (naming the file) for a shield or threat the equations reject.
WhippleResult runWhippleStudy(const WhippleStudy& study);

// ble.csv: one row per wall and speed:
// wall_thickness_m,speed_m_s,normal_speed_m_s,critical_diameter_m,regime
std::string formatWhippleCsv(const WhippleResult& result);
std::string formatWhippleJson(const WhippleResult& result);
std::string formatWhippleText(const WhippleResult& result);

}  // namespace ejecta::radiation
