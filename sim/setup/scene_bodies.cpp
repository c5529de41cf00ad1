// The scene's [[bodies]]: shapes, lattices, initial state, voids.
#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <string>

#include "sim/setup/scene_schema.hpp"
#include "sim/setup/scene_sections.hpp"

namespace ejecta::scene_detail {

std::string vectorLayout(Geometry g) {
  switch (g) {
    case Geometry::Line: return "[x]";
    case Geometry::Planar: return "[x, y]";
    case Geometry::Axisymmetric: return "[r, z]";
    case Geometry::Spatial: return "[x, y, z]";
  }
  return "";
}

Box domainBox(const Scene& scene) {
  Box b;
  const int dim = spatialDimension(scene.geometry);
  for (int d = 0; d < 3; ++d) {
    const AxisBounds& a = scene.domain[d];
    b.lo[d] = (d < dim && a.bounded) ? a.min : -INFINITY;
    b.hi[d] = (d < dim && a.bounded) ? a.max : INFINITY;
  }
  if (scene.geometry == Geometry::Axisymmetric) b.lo[0] = 0.0;
  return b;
}

void readShape(const TableReader& r, const Scene& scene, ShapeSpec& shape) {
  static const EnumNames<ShapeKind> kShapes{{"box", ShapeKind::Box},
                                            {"sphere", ShapeKind::Sphere},
                                            {"shell", ShapeKind::Shell},
                                            {"half_space", ShapeKind::HalfSpace}};
  // Each shape's keys, from the schema (scene_schema_bodies.cpp).
  static const std::map<ShapeKind, KeyList> kShapeKeys = [] {
    std::map<ShapeKind, KeyList> keys;
    for (const auto& [name, kind] : kShapes) {
      const std::vector<std::string_view>& own = sceneShape(name).keys;
      keys[kind] = KeyList(own.begin(), own.end());
    }
    return keys;
  }();
  r.require("shape");
  shape.kind = *r.optEnum("shape", kShapes);
  const std::string shapeName = r.table().get("shape")->value<std::string>().value_or("");
  const KeyList& own = kShapeKeys.at(shape.kind);
  for (const auto& [kind, keys] : kShapeKeys)
    for (std::string_view k : keys)
      if (r.has(k) && !contains(own, k))
        r.fail(k, "not used by shape '" + shapeName + "' (it takes " + joinKeys(own) + ")");
  for (std::string_view k : own) r.require(k);

  const int dim = spatialDimension(scene.geometry);
  const std::string layout = vectorLayout(scene.geometry);
  const Dimension m = Dimension::Length;
  Box extent;  // the shape's bounding box
  switch (shape.kind) {
    case ShapeKind::Box:
      shape.min = *r.optVector("min", m, dim, layout);
      shape.max = *r.optVector("max", m, dim, layout);
      for (int d = 0; d < dim; ++d)
        r.check(shape.min[d] < shape.max[d], "max",
                "every component must exceed min's (component " + std::to_string(d) + ")");
      extent = {shape.min, shape.max};
      break;
    case ShapeKind::Sphere:
    case ShapeKind::Shell: {
      shape.center = *r.optVector("center", m, dim, layout);
      const char* outerKey = shape.kind == ShapeKind::Sphere ? "radius" : "outer_radius";
      shape.radius = r.requireQuantity(outerKey, m);
      r.check(shape.radius > 0.0, outerKey, positiveMessage(shape.radius, m));
      if (shape.kind == ShapeKind::Shell) {
        shape.innerRadius = r.requireQuantity("inner_radius", m);
        r.check(shape.innerRadius >= 0.0, "inner_radius", nonNegativeMessage(shape.innerRadius, m));
        r.check(shape.innerRadius < shape.radius, "inner_radius", "must be below outer_radius");
      }
      for (int d = 0; d < 3; ++d) {
        extent.lo[d] = shape.center[d] - shape.radius;
        extent.hi[d] = shape.center[d] + shape.radius;
      }
      break;
    }
    case ShapeKind::HalfSpace: {
      shape.point = *r.optVector("point", m, dim, layout);
      shape.normal = *r.optVector("normal", Dimension::None, dim, layout);
      double norm = 0.0;
      for (int d = 0; d < dim; ++d) norm += shape.normal[d] * shape.normal[d];
      r.check(norm > 0.0, "normal", "must not be the zero vector");
      for (int d = 0; d < dim; ++d) shape.normal[d] /= std::sqrt(norm);
      // A half-space is bounded only by the domain box, so every axis must be bounded.
      const Box dom = domainBox(scene);
      for (int d = 0; d < dim; ++d)
        if (!std::isfinite(dom.lo[d]) || !std::isfinite(dom.hi[d]))
          r.fail("shape", "a half_space is clipped to the domain, but domain axis " +
                              std::string(1, "xyz"[d]) + " is unbounded; give domain." +
                              std::string(1, "xyz"[d]) + " min and max");
      extent = dom;
      // Some corner of the domain box must lie behind the plane.
      bool anyInside = false;
      for (int corner = 0; corner < (1 << dim); ++corner) {
        double side = 0.0;
        for (int d = 0; d < dim; ++d)
          side +=
              ((((corner >> d) & 1) ? dom.hi[d] : dom.lo[d]) - shape.point[d]) * shape.normal[d];
        anyInside = anyInside || side <= 0.0;
      }
      r.check(anyInside, "point", "the half-space does not reach into the domain");
      break;
    }
  }
  const Box dom = domainBox(scene);
  for (int d = 0; d < dim; ++d)
    if (extent.hi[d] <= dom.lo[d] || extent.lo[d] >= dom.hi[d])
      r.fail("shape", "the " + shapeName + " lies entirely outside the domain (axis " +
                          std::string(1, "xyz"[d]) + ")");
}

namespace {

// A paraboloid bowl (void bodies only): floor = `point`, opening along `normal`, `radius` wide at
// `depth` above the floor.
void readBowl(const TableReader& r, const Scene& scene, BowlSpec& bowl) {
  // The keys of the other shapes are errors (scene_schema_bodies.cpp).
  const SceneShape& bowlShape = sceneShape("paraboloid");
  const KeyList own(bowlShape.keys.begin(), bowlShape.keys.end());
  for (const SceneShape& other : sceneShapes())
    for (std::string_view k : other.keys)
      if (r.has(k) && !contains(own, k))
        r.fail(k, "not used by shape 'paraboloid' (it takes " + joinKeys(own) + ")");
  for (std::string_view k : own) r.require(k);
  const int dim = spatialDimension(scene.geometry);
  const std::string layout = vectorLayout(scene.geometry);
  const Dimension m = Dimension::Length;
  bowl.floor = *r.optVector("point", m, dim, layout);
  bowl.axis = *r.optVector("normal", Dimension::None, dim, layout);
  double norm = 0.0;
  for (int d = 0; d < dim; ++d) norm += bowl.axis[d] * bowl.axis[d];
  r.check(norm > 0.0, "normal", "must not be the zero vector");
  for (int d = 0; d < dim; ++d) bowl.axis[d] /= std::sqrt(norm);
  if (scene.geometry == Geometry::Axisymmetric) {
    r.check(bowl.floor[0] == 0.0, "point", "in rz a paraboloid's floor must be on the axis (r = 0)");
    r.check(bowl.axis[0] == 0.0, "normal", "in rz a paraboloid must open along the axis ([0, 1] or [0, -1])");
  }
  r.check(dim >= 2, "shape", "a paraboloid needs 2D, RZ or 3D");
  bowl.radius = r.requireQuantity("radius", m);
  r.check(bowl.radius > 0.0, "radius", positiveMessage(bowl.radius, m));
  bowl.depth = r.requireQuantity("depth", m);
  r.check(bowl.depth > 0.0, "depth", positiveMessage(bowl.depth, m));
}

// rest_on, rest_direction, rest_gap: where the body is moved to once every body is read
// (sim/setup/resting_bodies.hpp).
void readRest(const TableReader& r, const Scene& scene, BodySpec& b) {
  const int dim = spatialDimension(scene.geometry);
  if (!r.has("rest_on")) {
    for (std::string_view k : {"rest_direction", "rest_gap"})
      r.check(!r.has(k), k, "applies only with rest_on (the body it rests on)");
    return;
  }
  b.restOn = r.requireString("rest_on");
  r.check(b.shape.kind != ShapeKind::HalfSpace, "rest_on",
          "a half_space cannot be moved to rest on another body (a box, sphere or shell can)");
  b.restDirection = {0.0, 0.0, 0.0};
  b.restDirection[static_cast<std::size_t>(dim - 1)] = -1.0;  // down: -x in 1D, -y in 2D and RZ, -z in 3D
  if (const auto given = r.optVector("rest_direction", Dimension::None, dim, vectorLayout(scene.geometry))) {
    double norm = 0.0;
    for (int d = 0; d < dim; ++d) norm += (*given)[d] * (*given)[d];
    r.check(norm > 0.0 && std::isfinite(norm), "rest_direction", "must be a finite vector, not zero");
    for (int d = 0; d < dim; ++d) b.restDirection[d] = (*given)[d] / std::sqrt(norm);
    if (scene.geometry == Geometry::Axisymmetric)
      r.check(b.restDirection[0] == 0.0, "rest_direction",
              "in rz a body can only move along the axis ([0, 1] or [0, -1]): its rings would not stay rings");
  }
  // Not below one spacing: nearer, the other body's particles may fall inside this one's shape
  // (and be carved) before any pair comes within the gap.
  b.restGap = r.optQuantity("rest_gap", Dimension::None).value_or(1.0);
  r.check(b.restGap >= 1.0 && b.restGap <= 2.0, "rest_gap",
          "must be in [1, 2] spacings (1: the two lattices meet as one)");
}

// A [[bodies]] entry with void = true: a name and a shape, nothing that particles would need.
void readVoid(const TableReader& r, Scene& scene, int line) {
  for (std::string_view k : {"material", "lattice", "spacing", "density", "pressure",
                             "internal_energy", "velocity", "damage", "rest_on", "rest_direction",
                             "rest_gap"})
    r.check(!r.has(k), k, "a void body makes no particles: it takes name, shape and the shape's "
                           "keys only");
  VoidSpec v;
  v.line = line;
  v.name = r.requireString("name");
  v.firstCarved = scene.bodies.size();
  r.require("shape");
  v.isBowl = r.optString("shape") == "paraboloid";
  if (v.isBowl) {
    readBowl(r, scene, v.bowl);
  } else {
    r.check(!r.has("depth"), "depth", "only shape 'paraboloid' takes a depth");
    readShape(r, scene, v.shape);
  }
  scene.voids.push_back(std::move(v));
}

}  // namespace

void readBodies(const TableReader& root, Scene& scene) {
  const std::vector<const toml::table*> list = root.tableArray("bodies");
  if (list.empty()) root.fail("bodies", "at least one [[bodies]] entry is required");
  static const EnumNames<LatticeKind> kLattices{{"cubic", LatticeKind::Cubic},
                                                {"hexagonal", LatticeKind::Hexagonal}};
  const int dim = spatialDimension(scene.geometry);
  std::set<std::string> names;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const TableReader r(root.context(), *list[i], "bodies[" + std::to_string(i) + "]", "bodies[]");
    if (r.optBool("void").value_or(false)) {
      checkUniqueName(r, names, r.requireString("name"));
      readVoid(r, scene, lineOf(*list[i]));
      continue;
    }
    if (r.optString("shape") == "paraboloid")
      r.fail("shape", "shape 'paraboloid' is for void bodies only (add void = true)");
    if (r.has("depth")) r.fail("depth", "only a void body's shape 'paraboloid' takes a depth");
    BodySpec b;
    b.line = lineOf(*list[i]);
    b.entry = static_cast<int>(i);
    b.name = r.requireString("name");
    checkUniqueName(r, names, b.name);
    const std::string material = r.requireString("material");
    b.material = -1;
    for (std::size_t m = 0; m < scene.materials.size(); ++m)
      if (scene.materials[m].name == material) b.material = static_cast<int>(m);
    if (b.material < 0) {
      std::string known;
      for (const MaterialSpec& m : scene.materials)
        known += (known.empty() ? "'" : ", '") + m.name + "'";
      r.fail("material", "no material named '" + material + "' (materials: " + known + ")");
    }
    readShape(r, scene, b.shape);
    b.lattice = r.optEnum("lattice", kLattices).value_or(b.lattice);
    b.spacing = r.requireQuantity("spacing", Dimension::Length);
    r.check(b.spacing > 0.0, "spacing", positiveMessage(b.spacing, Dimension::Length));
    b.density = r.requireQuantity("density", Dimension::Density);
    r.check(b.density > 0.0, "density", positiveMessage(b.density, Dimension::Density));
    b.pressure = r.optQuantity("pressure", Dimension::Pressure);
    b.internalEnergy = r.optQuantity("internal_energy", Dimension::SpecificEnergy);
    // Neither is allowed for a detonated explosive (checked in readDetonations).
    if (b.pressure && b.internalEnergy)
      r.fail("internal_energy", "give exactly one of 'pressure' and 'internal_energy'");
    if (b.pressure)
      r.check(*b.pressure >= 0.0, "pressure", nonNegativeMessage(*b.pressure, Dimension::Pressure));
    if (b.internalEnergy)
      r.check(*b.internalEnergy >= 0.0, "internal_energy",
              nonNegativeMessage(*b.internalEnergy, Dimension::SpecificEnergy));
    b.velocity = r.optVector("velocity", Dimension::Velocity, dim, vectorLayout(scene.geometry))
                     .value_or(b.velocity);
    b.damage = r.optQuantity("damage", Dimension::None).value_or(0.0);
    r.check(b.damage >= 0.0 && b.damage <= 1.0, "damage", "must be in [0, 1]");
    readRest(r, scene, b);
    scene.bodies.push_back(std::move(b));
  }
  if (scene.bodies.empty())
    root.fail("bodies", "every [[bodies]] entry is a void; at least one must make particles");
  for (const VoidSpec& v : scene.voids)
    if (v.firstCarved >= scene.bodies.size())
      throw SceneError(root.context().source() + ":" + std::to_string(v.line) +
                       ": void body '" + v.name +
                       "' is listed after every body and carves nothing (earlier bodies win: "
                       "list it before the bodies it cuts)");
}

}  // namespace ejecta::scene_detail
