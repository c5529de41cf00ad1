#pragma once
// The crater's debris against the follower (issue 21; the seed's sec. 5.3.1 leaves it open:
// "once an algorithm that predicts the debris size is developed"). Which fragments of a run
// (fields/fragments.hpp) the spacecraft meets during its approach (a thermal study's
// [approach] and [spacecraft]), at what speed and angle, and whether its Whipple shield
// (a Whipple study's [shield]) stops each by Christiansen's ballistic-limit equations
// (radiation/whipple.hpp).
//
// Both move in straight lines over the pass, which starts at the fragments' time: over a
// millisecond the asteroid's gravity (~1e-2 m/s^2 for 70 m) moves nothing. A fragment is met
// when its centre comes within the spacecraft's bounding radius plus its own radius of the
// spacecraft's centre. RZ: a fragment is a ring (or a body on the axis), the spacecraft flies
// along the axis, and the distance is measured in the meridional plane (the ring's nearest
// piece). The impact speed is the relative speed; its angle is taken from the flight direction
// (the leading face's normal). Sizes below the run's resolution are not measured: each
// encounter says whether its fragment's size is (docs/fragments.md).
#include <optional>
#include <string>
#include <vector>

#include "fields/fragments.hpp"
#include "radiation/thermal_study.hpp"
#include "radiation/whipple.hpp"

namespace ejecta::coupling {

struct Encounter {
  std::size_t fragment = 0;        // index in the census
  double time = 0.0;               // [s] after the pass starts: the closest approach
  double missDistance = 0.0;       // [m] centre to centre then
  double speed = 0.0;              // [m/s] relative to the spacecraft
  double angle = 0.0;              // [rad] from the flight direction
  double diameter = 0.0;           // [m] the fragment's equivalent diameter
  double mass = 0.0;               // [kg] (RZ: the whole ring's)
  double density = 0.0;            // [kg/m^3] its mean density
  bool resolved = false;           // its size is measured (fields/fragments.hpp)
  // With a shield:
  std::optional<radiation::BallisticLimit> limit;
  bool perforates = false;         // diameter > d_c
  double requiredWall = 0.0;       // [m] the rear wall that would stop it
};

struct DebrisThreat {
  double passDuration = 0.0;       // [s]
  double spacecraftRadius = 0.0;   // [m] bounding radius of the body
  std::vector<Encounter> encounters;  // in order of closest approach
  bool shieldGiven = false;
  std::size_t perforating = 0, perforatingResolved = 0;
  double requiredWall = 0.0;          // [m] over every encounter
  double requiredWallResolved = 0.0;  // [m] over the encounters whose size is measured
};

// Throws std::invalid_argument for a 1D or 2D planar census, or an RZ pass off the axis.
DebrisThreat assessDebrisThreat(const fields::FragmentCensus& census,
                                const radiation::ThermalStudy& follower,
                                const std::optional<radiation::WhippleShield>& shield,
                                const radiation::WhippleOptions& options = {});

// One row per encounter (units in the header).
std::string encountersCsv(const DebrisThreat& threat);

}  // namespace ejecta::coupling
