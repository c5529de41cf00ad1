#pragma once
// Crater analysis: depth, apparent and rim-to-rim diameters, volume, excavated mass, elongation
// and the radial profile of a crater, measured on a filled-fraction field of the target material
// against the target's original surface (a sphere, or a plane for a half-space target).
// The field is any callable: an SPH grid of fields/, a VDB file, or an analytic shape in tests.
// Method and definitions: docs/crater.md.
#include <array>
#include <functional>
#include <string>
#include <vector>

namespace ejecta::fields {

using Point = std::array<double, 3>;

// Filled fraction of target material at a point: about 1 inside the target, 0 in void, 0.5 on its
// surface. analyseCrater calls it from several OpenMP threads at once: it must be thread safe.
using FractionField = std::function<double(const Point&)>;

// The target's surface before the impact.
struct ReferenceSurface {
  enum class Kind { Sphere, Plane };
  Kind kind = Kind::Sphere;
  Point center{};               // Sphere
  double radius = 0.0;          // Sphere [m]
  Point point{};                // Plane: a point on the original surface
  Point normal{0.0, 1.0, 0.0};  // Plane: unit normal pointing out of the target
};

struct CraterOptions {
  ReferenceSurface surface;
  // Where the crater is. It is projected onto the reference surface; the crater axis is the
  // surface normal there (sphere: the radial direction through the point).
  Point impactPoint{};
  // A 2D planar run: the field lives in the x-y plane (sampled at z = 0), the axis lies in that
  // plane, the crater has two sides, and volume and mass are per metre of depth (m^2, kg/m).
  bool planar = false;
  // March step along rays and profile bin width along the surface [m]; must be > 0. Use the
  // voxel size (or the particle spacing) of the field.
  double resolution = 0.0;
  // How far from the axis to measure, as a distance along the surface [m]. 0: 60 resolutions,
  // and on a sphere at most a quarter of its circumference.
  double searchRadius = 0.0;
  double threshold = 0.5;       // the fraction that marks the surface
  // Voids shorter than this along a ray (cracks, spall gaps) count as filled. 0: 2 resolutions.
  double gapBridge = 0.0;
  // The surface counts as back at the original level (the apparent rim) once the depth is within
  // this of zero [m]. An SPH surface rounds the crater's edge over about a smoothing length,
  // approaching the level slowly: 0 = a quarter of the resolution.
  double levelTolerance = 0.0;
  int azimuths = 72;            // 3D: azimuth sectors about the axis (planar: always the 2 sides)
  // Direction of the impactor's flight, for the along-/cross-track diameters of oblique
  // impacts. Zero: the longest apparent diameter over the azimuths is taken as along-track.
  Point alongTrack{};
  double targetDensity = 0.0;   // [kg/m^3]: excavated mass = density * volume; 0: mass not given
};

// One bin of the radial profile: distance from the axis along the original surface, and the
// depth of the present surface below the original one (negative: above it, e.g. the rim), over
// the azimuths.
struct CraterProfileBin {
  double distance = 0.0;        // bin centre [m]
  double depthMean = 0.0;       // [m]
  double depthMin = 0.0;        // shallowest azimuth [m]
  double depthMax = 0.0;        // deepest azimuth [m]
};

struct CraterMetrics {
  // False when there is no depression deeper than one resolution within the search radius; the
  // numbers are then zero and `note` says why.
  bool found = false;
  std::string note;
  double depth = 0.0;             // deepest point below the original surface [m]
  Point deepestPoint{};           // where it is
  double apparentDiameter = 0.0;  // where the surface returns to the original level [m]
  double rimDiameter = 0.0;       // rim crest to rim crest [m]
  double rimHeight = 0.0;         // mean height of the rim crest above the original surface [m]
  double volume = 0.0;            // below the original surface, inside the apparent rim [m^3]
  double excavatedMass = 0.0;     // targetDensity * volume [kg] (0 when no density was given)
  double alongTrackDiameter = 0.0;  // apparent diameter along the impact direction [m]
  double crossTrackDiameter = 0.0;  // and across it [m]
  double elongation = 1.0;          // alongTrackDiameter / crossTrackDiameter
  std::vector<CraterProfileBin> profile;
  // Apparent radius per azimuth sector [m] (planar: the two sides).
  std::vector<double> apparentRadius;
};

// Measures the crater. Throws std::invalid_argument naming the option for bad options
// (non-positive resolution or radius, zero normal, impact point at the sphere's centre).
CraterMetrics analyseCrater(const FractionField& field, const CraterOptions& options);

// The radial profile as CSV: distance_m,depth_mean_m,depth_min_m,depth_max_m
std::string craterProfileCsv(const CraterMetrics& metrics);

}  // namespace ejecta::fields
