#include "fields/crater_setup.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>

namespace ejecta::fields {

namespace {

double dot(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const Point& a) { return std::sqrt(dot(a, a)); }
Point add(const Point& a, const Point& b, double s) {
  return {a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]};
}

Point bodyCentre(const ShapeSpec& s) {
  switch (s.kind) {
    case ShapeKind::Box:
      return {(s.min[0] + s.max[0]) / 2, (s.min[1] + s.max[1]) / 2, (s.min[2] + s.max[2]) / 2};
    case ShapeKind::Sphere:
    case ShapeKind::Shell: return s.center;
    case ShapeKind::HalfSpace: return s.point;
  }
  return {};
}

double outerRadius(const ShapeSpec& s) { return s.radius; }

// Spacings kept between the crater search and where the target's material ends (a box
// target's side, a domain face): an SPH surface is rounded there over about a smoothing length.
constexpr double kSpacingsClearOfEdges = 3.0;

// Whether the plane x[axis] = position passes through the body (a face beyond it leaves the body
// whole). A half-space is unbounded: every face that is not above it (skipped by the caller) cuts.
bool planeCuts(const ShapeSpec& s, int axis, double position) {
  const auto a = static_cast<std::size_t>(axis);
  switch (s.kind) {
    case ShapeKind::Sphere:
    case ShapeKind::Shell: return std::abs(position - s.center[a]) < s.radius;
    case ShapeKind::Box: return position > s.min[a] && position < s.max[a];
    case ShapeKind::HalfSpace: return true;
  }
  return true;
}

// A target cut by the domain box (a cropped body) is measured inside it. The crater is measured
// on a field splatted from the real particles alone, so past any face that cuts the target
// (open, a wall or a periodic side alike: no ghost or image is splatted) a ray finds no material
// and would read a bottomless crater. The search stops kSpacingsClearOfEdges short of the
// nearest such face, lateral or below the surface; a face above it (outward normal within 45
// degrees of the surface normal) cuts nothing the rays need, and the RZ axis is no face. Since
// the rays start one search radius below the surface (fields/crater.cpp), a face below limits
// the lateral reach too. Throws SceneError when the impact point is outside the box or too near
// a face for any crater to be measured.
void limitSearchToDomain(const Scene& scene, int dims, const BodySpec& target, CraterSetup& setup) {
  const Point& q = setup.impactPoint;
  Point n = setup.surface.normal;
  if (setup.surface.kind == ReferenceSurface::Kind::Sphere) {
    const Point r = {q[0] - setup.surface.center[0], q[1] - setup.surface.center[1],
                     q[2] - setup.surface.center[2]};
    const double length = norm(r);
    n = length > 0.0 ? Point{r[0] / length, r[1] / length, r[2] / length} : Point{};
  }
  static const char* kAxisNames[] = {"x", "y", "z"};
  double limit = INFINITY;
  std::string nearest;
  for (int axis = 0; axis < dims; ++axis) {
    const auto a = static_cast<std::size_t>(axis);
    const AxisBounds& b = scene.domain[a];
    if (!b.bounded) continue;
    const bool rzAxis = scene.geometry == Geometry::Axisymmetric && axis == 0;
    const struct {
      double position, outward;
      bool counts;
      const char* side;
    } faces[] = {{b.min, -1.0, !rzAxis, "lower"}, {b.max, 1.0, true, "upper"}};
    for (const auto& f : faces) {
      const bool above = f.outward * n[a] > std::numbers::sqrt2 / 2;
      if (!f.counts || above || !planeCuts(target.shape, axis, f.position)) continue;
      const double distance = f.outward * (f.position - q[a]);
      if (distance < limit) {
        limit = distance;
        nearest = std::string(f.side) + " " + kAxisNames[axis] + " face";
      }
    }
  }
  if (!std::isfinite(limit)) return;
  const double spacing = target.spacing;
  const double needed = (kSpacingsClearOfEdges + 1.0) * spacing;
  if (limit < needed) {
    char text[200];
    if (limit < 0.0)
      std::snprintf(text, sizeof text, "outside the domain, %g m past its %s", -limit,
                    nearest.c_str());
    else
      std::snprintf(text, sizeof text,
                    "%g m inside the domain's %s, under the %g m (%g spacings) a crater "
                    "measurement needs", limit, nearest.c_str(), needed, needed / spacing);
    throw SceneError(scene.sourcePath + ": crater: the impact point lies " + text +
                     "; widen the domain, or set [crater] enabled = false");
  }
  const double inside = limit - kSpacingsClearOfEdges * spacing;
  setup.searchLimit = setup.searchLimit > 0.0 ? std::min(setup.searchLimit, inside) : inside;
}

// The impactor's volume [m^3] in RZ (shapes revolved about the axis) or 3D; 0 for a shape with
// no finite volume.
double impactorVolume(const ShapeSpec& s, Geometry g) {
  const double pi = std::numbers::pi;
  switch (s.kind) {
    case ShapeKind::Sphere: return 4.0 / 3.0 * pi * s.radius * s.radius * s.radius;
    case ShapeKind::Shell:
      return 4.0 / 3.0 * pi * (std::pow(s.radius, 3) - std::pow(s.innerRadius, 3));
    case ShapeKind::Box:
      if (g == Geometry::Axisymmetric)  // a ring of r in [min_r, max_r]
        return pi * (s.max[0] * s.max[0] - s.min[0] * s.min[0]) * (s.max[1] - s.min[1]);
      return (s.max[0] - s.min[0]) * (s.max[1] - s.min[1]) * (s.max[2] - s.min[2]);
    case ShapeKind::HalfSpace: return 0.0;
  }
  return 0.0;
}

// The pi-group scaling [crater] scaling asks for: the class and the impact's numbers.
void addScaling(const Scene& scene, const BodySpec& impactor, CraterSetup& setup) {
  const std::string where = scene.sourcePath + ": crater.scaling: ";
  const CraterScalingLaw* law = craterScalingClass(scene.crater.scaling);
  if (!law)
    throw SceneError(where + "no class '" + scene.crater.scaling + "' (the classes: " +
                     craterScalingClassNames() + ")");
  if (setup.planar)
    throw SceneError(where + "pi-group scaling is for craters in 3D or RZ; a 2D planar run's "
                     "crater is a trench");
  const ShapeSpec& shape = impactor.shape;
  if (scene.geometry == Geometry::Axisymmetric &&
      (shape.kind == ShapeKind::Sphere || shape.kind == ShapeKind::Shell) &&
      std::abs(shape.center[0]) > 1e-9 * shape.radius)
    throw SceneError(where + "the impactor '" + impactor.name + "' is off the axis: in RZ it is a "
                     "ring, not a sphere");
  const double volume = impactorVolume(shape, scene.geometry);
  if (!(volume > 0.0))
    throw SceneError(where + "the impactor '" + impactor.name + "' has no finite volume");
  ScalingImpact impact;
  impact.impactorMass = impactor.density * volume;
  impact.impactorRadius = std::cbrt(3.0 * volume / (4.0 * std::numbers::pi));
  impact.speed = norm(impactor.velocity);
  impact.targetDensity = setup.targetDensity;
  if (scene.crater.gravity) {
    impact.gravity = *scene.crater.gravity;
  } else if (setup.surface.kind == ReferenceSurface::Kind::Sphere) {
    // A uniform sphere of the outer target's density: g = G M / R^2 = (4/3) pi G rho R, with
    // G = 6.67430e-11 m^3 kg^-1 s^-2 (CODATA 2018).
    constexpr double kGravitationalConstant = 6.67430e-11;
    impact.gravity = 4.0 / 3.0 * std::numbers::pi * kGravitationalConstant *
                     setup.targetDensity * setup.surface.radius;
  }
  CraterScalingLaw target = *law;
  if (scene.crater.strength) target.strength = *scene.crater.strength;
  try {
    scaleCrater(target, impact);  // refused now, not after the run
  } catch (const std::invalid_argument& e) {
    // Gravity helps only a class that has a gravity regime.
    const bool gravityWouldDo = impact.gravity == 0.0 && !scene.crater.gravity &&
                                (!law->radiusForm() || law->h1 > 0.0);
    throw SceneError(where + (scene.crater.strength ? "with crater.strength: " : "") + e.what() +
                     (gravityWouldDo ? "; give [crater] gravity" : ""));
  }
  setup.scaling = CraterScaling{target, impact};
}

// First hit of the ray c + t d (t > 0, |d| = 1) on an axis-aligned box's faces, as a plane.
std::optional<ReferenceSurface> boxFaceHit(const ShapeSpec& box, const Point& c, const Point& d,
                                           int dims) {
  double best = INFINITY;
  std::optional<ReferenceSurface> face;
  for (int axis = 0; axis < dims; ++axis) {
    if (d[axis] == 0.0) continue;
    const double plane = d[axis] > 0 ? box.min[axis] : box.max[axis];
    const double t = (plane - c[axis]) / d[axis];
    if (t <= 0.0 || t >= best) continue;
    const Point p = add(c, d, t);
    bool inside = true;
    for (int o = 0; o < dims; ++o)
      if (o != axis && (p[o] < box.min[o] || p[o] > box.max[o])) inside = false;
    if (!inside) continue;
    best = t;
    ReferenceSurface s;
    s.kind = ReferenceSurface::Kind::Plane;
    s.point = p;
    s.normal = {0, 0, 0};
    s.normal[axis] = d[axis] > 0 ? -1.0 : 1.0;
    face = s;
  }
  return face;
}

}  // namespace

namespace {

// The setup of an impact scene, or nothing when the scene is not one (craterSetupFromScene).
std::optional<CraterSetup> impactSetup(const Scene& scene) {
  if (!scene.crater.enabled || scene.geometry == Geometry::Line) return std::nullopt;
  const int dims = spatialDimension(scene.geometry);
  const BodySpec* impactor = nullptr;
  for (const BodySpec& b : scene.bodies)
    if (norm(b.velocity) > 0.0 && (!impactor || norm(b.velocity) > norm(impactor->velocity)))
      impactor = &b;
  if (!impactor) return std::nullopt;

  CraterSetup setup;
  setup.planar = scene.geometry == Geometry::Planar;
  auto isTarget = [&](const BodySpec& b) {
    if (!scene.crater.materials.empty())
      return std::find(scene.crater.materials.begin(), scene.crater.materials.end(),
                       scene.materials[b.material].name) != scene.crater.materials.end();
    return norm(b.velocity) == 0.0;
  };
  std::vector<const BodySpec*> targets;
  for (const BodySpec& b : scene.bodies)
    if (&b != impactor && isTarget(b)) targets.push_back(&b);
  if (targets.empty()) return std::nullopt;
  for (const BodySpec* b : targets)
    if (std::find(setup.targetMaterials.begin(), setup.targetMaterials.end(), b->material) ==
        setup.targetMaterials.end()) {
      setup.targetMaterials.push_back(b->material);
      setup.targetNames.push_back(scene.materials[b->material].name);
    }

  const Point c = bodyCentre(impactor->shape);
  const double speed = norm(impactor->velocity);
  const Point d = {impactor->velocity[0] / speed, impactor->velocity[1] / speed,
                   impactor->velocity[2] / speed};
  setup.alongTrack = d;

  // The surface: a half-space target wins, then the largest sphere, then a box face.
  const BodySpec* outer = nullptr;
  for (const BodySpec* b : targets)
    if (b->shape.kind == ShapeKind::HalfSpace) outer = b;
  if (outer) {
    setup.surface.kind = ReferenceSurface::Kind::Plane;
    setup.surface.point = outer->shape.point;
    const double n = norm(outer->shape.normal);
    setup.surface.normal = {outer->shape.normal[0] / n, outer->shape.normal[1] / n,
                            outer->shape.normal[2] / n};
  } else {
    for (const BodySpec* b : targets)
      if ((b->shape.kind == ShapeKind::Sphere || b->shape.kind == ShapeKind::Shell) &&
          (!outer || outerRadius(b->shape) > outerRadius(outer->shape)))
        outer = b;
    if (outer) {
      setup.surface.kind = ReferenceSurface::Kind::Sphere;
      setup.surface.center = outer->shape.center;
      setup.surface.radius = outerRadius(outer->shape);
    }
  }
  if (!outer) {
    for (const BodySpec* b : targets)
      if (auto face = boxFaceHit(b->shape, c, d, dims)) {
        setup.surface = *face;
        outer = b;
        break;
      }
    if (outer) {
      // The side faces of the box bound the search along the surface.
      const ShapeSpec& box = outer->shape;
      double limit = INFINITY;
      const Point p = setup.surface.point;
      for (int axis = 0; axis < dims; ++axis) {
        if (setup.surface.normal[axis] != 0.0) continue;
        limit = std::min({limit, p[axis] - box.min[axis], box.max[axis] - p[axis]});
      }
      if (scene.geometry == Geometry::Axisymmetric)
        limit = box.max[0] - p[0];  // the axis is no edge
      setup.searchLimit = std::max(limit - kSpacingsClearOfEdges * outer->spacing, outer->spacing);
    }
    if (!outer)
      throw SceneError(scene.sourcePath + ": crater: the path of body '" + impactor->name +
                       "' meets no target body's surface; give [crater] materials or disable it");
  }
  setup.targetDensity = outer->density;

  // Where the path meets the surface (closest approach when it misses a sphere).
  if (setup.surface.kind == ReferenceSurface::Kind::Plane) {
    const Point& n = setup.surface.normal;
    const double dn = dot(d, n);
    const Point rel = {c[0] - setup.surface.point[0], c[1] - setup.surface.point[1],
                       c[2] - setup.surface.point[2]};
    const double t = dn != 0.0 ? -dot(rel, n) / dn : 0.0;
    setup.impactPoint = add(c, d, t);
  } else {
    const Point rel = {c[0] - setup.surface.center[0], c[1] - setup.surface.center[1],
                       c[2] - setup.surface.center[2]};
    const double b = dot(rel, d);
    const double disc = b * b - (dot(rel, rel) - setup.surface.radius * setup.surface.radius);
    const double t = disc >= 0.0 ? -b - std::sqrt(disc) : -b;
    setup.impactPoint = add(c, d, t);
  }
  limitSearchToDomain(scene, dims, *outer, setup);
  if (!scene.crater.scaling.empty()) addScaling(scene, *impactor, setup);
  return setup;
}

}  // namespace

std::optional<CraterSetup> craterSetupFromScene(const Scene& scene) {
  std::optional<CraterSetup> setup = impactSetup(scene);
  if (!setup && scene.crater.enabled && !scene.crater.scaling.empty())
    throw SceneError(scene.sourcePath + ": crater.scaling: the scene has no impact to scale (a "
                     "moving body striking bodies at rest, in RZ or 3D)");
  return setup;
}

CraterOptions craterOptions(const CraterSetup& setup, double resolution) {
  CraterOptions o;
  o.surface = setup.surface;
  o.impactPoint = setup.impactPoint;
  // A normal impact has no track along the surface (the longest diameter stands in for it).
  const Point n = setup.surface.kind == ReferenceSurface::Kind::Sphere
                      ? Point{setup.impactPoint[0] - setup.surface.center[0],
                              setup.impactPoint[1] - setup.surface.center[1],
                              setup.impactPoint[2] - setup.surface.center[2]}
                      : setup.surface.normal;
  const double a = norm(setup.alongTrack), b = norm(n);
  const double along = a > 0.0 && b > 0.0 ? std::abs(dot(setup.alongTrack, n)) / (a * b) : 1.0;
  constexpr double kNormal = 0.99985;  // cos 1 degree
  o.alongTrack = along > kNormal ? Point{} : setup.alongTrack;
  o.planar = setup.planar;
  o.resolution = resolution;
  o.targetDensity = setup.targetDensity;
  o.searchRadius = 120.0 * resolution;
  if (setup.searchLimit > 0.0) o.searchRadius = std::min(o.searchRadius, setup.searchLimit);
  return o;
}

}  // namespace ejecta::fields
