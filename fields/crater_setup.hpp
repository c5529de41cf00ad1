#pragma once
// What a crater measurement needs to know about the run, worked out from its scene: the target's
// original surface (the largest sphere at rest, or a half-space or box face), where the
// impactor's path meets it, the flight direction, and which materials are target.
#include <optional>
#include <string>
#include <vector>

#include "fields/crater.hpp"
#include "fields/crater_scaling.hpp"
#include "sim/setup/scene.hpp"

namespace ejecta::fields {

// [crater] scaling: the class and the impact it scales.
struct CraterScaling {
  CraterScalingLaw law;
  ScalingImpact impact;
};

struct CraterSetup {
  ReferenceSurface surface;
  Point impactPoint{};
  Point alongTrack{};
  bool planar = false;
  double targetDensity = 0.0;               // [kg/m^3], of the outermost target body
  // How far from the impact point, along the surface, the target extends (a box's nearest side
  // face, or the nearest face of a bounded domain that cuts the target, lateral or below, less
  // a few spacings); 0: no limit (a whole sphere, or a half-space in an unbounded domain).
  double searchLimit = 0.0;
  std::vector<int> targetMaterials;         // material indices
  std::vector<std::string> targetNames;     // their names
  std::optional<CraterScaling> scaling;      // [crater] scaling, if given
};

// The setup for an impact scene, in grid coordinates (RZ: (r, z) -> (x, y), axis along y), or
// nothing when the scene is not one (1D; no moving body; no body at rest; [crater] enabled =
// false). A [crater] materials list replaces the bodies-at-rest rule. Throws SceneError when the
// target surface cannot be worked out (e.g. only box targets that the path misses), when the
// impact point lies outside the domain box or within 4 spacings of a face that cuts the target,
// and when [crater] scaling cannot be applied (an unknown class, a planar run, no impact).
std::optional<CraterSetup> craterSetupFromScene(const Scene& scene);

// Options for analyseCrater from a setup at the given resolution [m]: the search reaches 120
// resolutions from the axis (craters some tens of smoothing lengths across, rims included), or
// the setup's searchLimit if that is nearer.
CraterOptions craterOptions(const CraterSetup& setup, double resolution);

}  // namespace ejecta::fields
