// Geometry files → GeometryConfig: read with core's table reader (every key checked against its
// table's allowed keys, messages "FILE:LINE: key 'a.b': reason"). Lengths, temperatures, speeds
// and times are numbers (SI) or quantity strings ("2 m", "1500 K"), read by core/units.hpp.
#include <cmath>
#include <numbers>

#include "radiation/geometry_file_reader.hpp"
#include "radiation/study_input.hpp"

namespace ejecta::radiation {

namespace fs = std::filesystem;

namespace {

using config::TableReader;
using namespace input;

const config::SchemaTables& geometrySchema() {
  static const config::SchemaTables keys = {
      {"", {"geometry", "spacecraft", "surfaces", "emitters", "hot_material", "occluder", "receivers",
            "points", "sampling", "references"}},
      {"references[]", {"from", "to", "value", "source"}},
      {"geometry", {"name", "description"}},
      {"spacecraft", {"shape", "size", "radius", "length", "segments", "sectors", "mesh", "patch", "scale",
                      "position", "forward", "up", "rotation_axis", "rotation_angle", "velocity", "times"}},
      {"surfaces[]", {"name", "shape", "corner", "edge1", "edge2", "center", "normal", "radius", "segments",
                      "subdivisions", "mesh", "scale"}},
      {"emitters[]", {"name", "shape", "center", "normal", "radius", "min", "max", "spacing", "emitter_radius",
                      "points", "radii", "temperature", "emissivity"}},
      {"hot_material", {"min_temperature"}},
      {"occluder", {"shape", "center", "radius", "subdivisions", "mesh", "scale", "temperature", "emissivity"}},
      {"receivers", {"patches", "baseline_length", "baseline_uses_emitter_size"}},
      {"points[]", {"name", "position", "normal"}},
      {"sampling", {"rays", "tolerance", "relative_tolerance", "min_rays", "max_rays", "replicates", "seed",
                    "sampler"}},
  };
  return keys;
}

constexpr auto kRaise = &config::raiseInputError<GeometryFileError>;
constexpr Dimension kLength = Dimension::Length;

template <typename E>
E requireEnum(const TableReader& t, std::string_view k, const config::EnumNames<E>& names) {
  t.require(k);
  return *t.optEnum(k, names);
}

double emissivity(const TableReader& t) {
  return numberIn(t, "emissivity", kGraniteEmissivity, 1e-300, 1.0, "(0, 1]");
}

// rotation_angle: a plain number is in degrees (as the key always read); a string carries its unit.
double rotationAngle(const TableReader& t) {
  const toml::node& n = t.require("rotation_angle");
  if (n.is_string()) return t.requireQuantity("rotation_angle", Dimension::Angle);
  return t.requireQuantity("rotation_angle", Dimension::None) * std::numbers::pi / 180.0;
}

SpacecraftSpec readSpacecraft(const TableReader& t, const fs::path& base) {
  SpacecraftSpec sc;
  sc.body = readShape(t, ShapeRole::Spacecraft, base);
  sc.pose.position = optVec3(t, "position", kLength).value_or(Vec3{});
  sc.pose.velocity = optVec3(t, "velocity", Dimension::Velocity).value_or(Vec3{});
  const bool byAxis = t.has("rotation_axis") || t.has("rotation_angle");
  if (byAxis && (t.has("forward") || t.has("up")))
    t.fail("rotation_axis", "give the attitude as forward/up or as rotation_axis/rotation_angle, not both");
  if (byAxis) {
    const Vec3 axis = direction(t, "rotation_axis", {0, 0, 1});
    sc.pose.attitude = Rotation::fromAxisAngle(axis, rotationAngle(t));
  } else {
    const Vec3 forward = direction(t, "forward", {1, 0, 0}), up = direction(t, "up", {0, 1, 0});
    try {
      sc.pose.attitude = Rotation::fromForwardUp(forward, up);
    } catch (const std::invalid_argument& e) {
      t.fail("up", e.what());
    }
  }
  if (t.has("times")) {
    sc.times = quantityList(t, "times", Dimension::Time);
    if (sc.times.empty()) t.fail("times", "must list at least one time");
  }
  return sc;
}

EmitterSpec readEmitter(const TableReader& t) {
  EmitterSpec e;
  using K = EmitterSpec::Kind;
  e.kind = requireEnum<K>(t, "shape", {{"sphere", K::Sphere}, {"box", K::Box}, {"disc", K::Disc}, {"points", K::Points}});
  const std::string shape = t.requireString("shape");
  e.name = t.requireString("name");
  onlyFor(t, {"center", "radius"}, e.kind == K::Sphere || e.kind == K::Disc, shape);
  onlyFor(t, {"normal"}, e.kind == K::Disc, shape);
  onlyFor(t, {"min", "max"}, e.kind == K::Box, shape);
  onlyFor(t, {"spacing"}, e.kind != K::Points, shape);
  onlyFor(t, {"points", "radii"}, e.kind == K::Points, shape);
  e.emissivity = emissivity(t);
  if (t.has("emitter_radius")) e.emitterRadius = requirePositive(t, "emitter_radius", kLength);
  // One temperature, or (points) one per point.
  const toml::node& temp = t.require("temperature");
  if (temp.is_array()) {
    if (e.kind != K::Points) t.fail("temperature", "an array of temperatures needs shape 'points'");
    e.temperatures = quantityList(t, "temperature", Dimension::Temperature);
  } else {
    e.temperatures = {t.requireQuantity("temperature", Dimension::Temperature)};
  }
  for (double T : e.temperatures)
    if (!(T >= 0.0)) t.fail("temperature", "must be >= 0 K");
  switch (e.kind) {
    case K::Sphere:
    case K::Disc:
      e.center = requireVec3(t, "center", kLength);
      e.radius = requirePositive(t, "radius", kLength);
      e.spacing = requirePositive(t, "spacing", kLength);
      if (e.kind == K::Disc) e.normal = direction(t, "normal", {0, 0, 1});
      break;
    case K::Box:
      e.min = requireVec3(t, "min", kLength);
      e.max = requireVec3(t, "max", kLength);
      for (int k = 0; k < 3; ++k)
        if (!(e.max[k] > e.min[k])) t.fail("max", "must exceed min in every component");
      e.spacing = requirePositive(t, "spacing", kLength);
      break;
    case K::Points: {
      const toml::node* n = t.find("points");
      const toml::array* a = n ? n->as_array() : nullptr;
      if (!a || a->empty()) t.fail("points", "list at least one point [[x, y, z], ...]");
      for (std::size_t i = 0; i < a->size(); ++i)
        e.points.push_back(vec3At(t, *a->get(i), t.key("points") + "[" + std::to_string(i) + "]", kLength));
      e.radii = quantityList(t, "radii", kLength);
      if (!e.radii.empty() && e.radii.size() != e.points.size())
        t.fail("radii", "needs one radius per point (" + std::to_string(e.points.size()) + ")");
      for (double r : e.radii)
        if (!(r > 0.0)) t.fail("radii", "every radius must be > 0");
      if (e.radii.empty() && e.emitterRadius == 0.0) t.fail("emitter_radius", "points need radii or emitter_radius");
      if (e.temperatures.size() != 1 && e.temperatures.size() != e.points.size())
        t.fail("temperature", "needs one value or one per point (" + std::to_string(e.points.size()) + ")");
      break;
    }
  }
  if (e.kind != K::Points) {
    // Guard against a lattice of billions of points from a slip of the spacing.
    const double extent = e.kind == K::Box ? vec3::norm(vec3::sub(e.max, e.min)) : 2.0 * e.radius;
    if (std::pow(extent / e.spacing, e.kind == K::Disc ? 2.0 : 3.0) > 5e7)
      t.fail("spacing", "makes more than 5e7 emitters; use a coarser spacing");
  }
  return e;
}

OccluderSpec readOccluder(const TableReader& t, const fs::path& base) {
  OccluderSpec occ;
  using K = SurfaceShape::Kind;
  occ.shape.kind = requireEnum<K>(t, "shape", {{"sphere", K::Sphere}, {"mesh", K::Mesh}});
  occ.shape.name = "occluder";
  if (occ.shape.kind == K::Sphere) {
    onlyFor(t, {"mesh", "scale"}, false, "sphere");
    occ.shape.center = requireVec3(t, "center", kLength);
    occ.shape.radius = requirePositive(t, "radius", kLength);
    occ.shape.subdivisions = static_cast<int>(integerIn(t, "subdivisions", 5, 0, 7));
  } else {
    onlyFor(t, {"center", "radius", "subdivisions"}, false, "mesh");
    occ.shape.mesh = meshPath(t, base);
    occ.shape.scale = optPositive(t, "scale", kLength, 1.0);
  }
  occ.temperature = t.optQuantity("temperature", Dimension::Temperature).value_or(0.0);
  if (!(occ.temperature >= 0.0)) t.fail("temperature", "must be >= 0 K");
  occ.emissivity = emissivity(t);
  return occ;
}

SamplingOptions readSampling(const TableReader& t) {
  SamplingOptions o;
  auto count = [&t](std::string_view k, std::uint64_t fallback) {
    return static_cast<std::uint64_t>(integerIn(t, k, static_cast<long long>(fallback), 1, 1LL << 40));
  };
  o.rays = count("rays", 0);
  o.absoluteTolerance = optPositive(t, "tolerance", Dimension::None, o.absoluteTolerance);
  o.relativeTolerance = optPositive(t, "relative_tolerance", Dimension::None, o.relativeTolerance);
  if (t.has("rays") && (t.has("tolerance") || t.has("relative_tolerance")))
    t.fail("rays", "give a fixed ray count or tolerances, not both");
  o.minRays = count("min_rays", o.minRays);
  o.maxRays = count("max_rays", o.maxRays);
  if (o.maxRays < o.minRays) t.fail("max_rays", "must be >= min_rays");
  o.replicates = static_cast<int>(integerIn(t, "replicates", o.replicates, 2, 1024));
  if (const auto seed = t.optInteger("seed")) o.seed = static_cast<std::uint64_t>(*seed);
  o.sampler = t.optEnum<sampling::Sampler>("sampler", {{"sobol", sampling::Sampler::Sobol},
                                                       {"random", sampling::Sampler::Random}})
                  .value_or(o.sampler);
  return o;
}

std::string indexed(std::string_view k, std::size_t i) {
  std::string out(k);
  out += "[" + std::to_string(i) + "]";
  return out;
}

GeometryConfig validate(const config::Context& ctx, const TableReader& top, const fs::path& base) {
  GeometryConfig c;
  c.source = ctx.source();
  if (const toml::table* g = top.optTable("geometry")) {
    const TableReader t(ctx, *g, "geometry", "geometry");
    c.name = t.optString("name").value_or("");
    c.description = t.optString("description").value_or("");
  }
  if (const toml::table* s = top.optTable("spacecraft"))
    c.spacecraft = readSpacecraft(TableReader(ctx, *s, "spacecraft", "spacecraft"), base);
  const auto surfaces = top.tableArray("surfaces");
  for (std::size_t i = 0; i < surfaces.size(); ++i)
    c.surfaces.push_back(readShape(TableReader(ctx, *surfaces[i], indexed("surfaces", i), "surfaces[]"), ShapeRole::Plate, base));
  const auto emitters = top.tableArray("emitters");
  for (std::size_t i = 0; i < emitters.size(); ++i)
    c.emitters.push_back(readEmitter(TableReader(ctx, *emitters[i], indexed("emitters", i), "emitters[]")));
  if (const toml::table* h = top.optTable("hot_material")) {
    const TableReader t(ctx, *h, "hot_material", "hot_material");
    c.minTemperature = t.optQuantity("min_temperature", Dimension::Temperature).value_or(c.minTemperature);
  }
  if (const toml::table* o = top.optTable("occluder"))
    c.occluder = readOccluder(TableReader(ctx, *o, "occluder", "occluder"), base);
  if (const toml::table* r = top.optTable("receivers")) {
    const TableReader t(ctx, *r, "receivers", "receivers");
    c.receiverPatches = stringList(t, "patches");
    c.baseline.receiverSide = optPositive(t, "baseline_length", kLength, c.baseline.receiverSide);
    if (t.optBool("baseline_uses_emitter_size").value_or(false)) c.baseline.length = BaselineLength::EmitterDiameter;
  }
  const auto points = top.tableArray("points");
  for (std::size_t i = 0; i < points.size(); ++i) {
    const TableReader t(ctx, *points[i], indexed("points", i), "points[]");
    c.points.push_back({t.requireString("name"), requireVec3(t, "position", kLength), direction(t, "normal", {0, 0, 1})});
  }
  if (const toml::table* s = top.optTable("sampling")) c.sampling = readSampling(TableReader(ctx, *s, "sampling", "sampling"));
  const auto references = top.tableArray("references");
  for (std::size_t i = 0; i < references.size(); ++i) {
    const TableReader t(ctx, *references[i], indexed("references", i), "references[]");
    ReferenceFactor r;
    r.from = t.requireString("from");
    r.to = t.requireString("to");
    r.value = t.requireQuantity("value", Dimension::None);
    if (!(r.value >= 0.0 && r.value <= 1.0)) t.fail("value", "a view factor is between 0 and 1");
    r.source = t.optString("source").value_or("");
    r.line = config::lineOf(*references[i]);
    c.references.push_back(std::move(r));
  }
  if (!c.spacecraft && c.surfaces.empty() && c.points.empty())
    kRaise(ctx.source() + ":1: nothing to receive radiation: give [spacecraft], [[surfaces]] or [[points]]");
  return c;
}

}  // namespace

SurfaceShape readShape(const TableReader& t, ShapeRole role, const fs::path& base) {
  SurfaceShape s;
  using K = SurfaceShape::Kind;
  const bool spacecraft = role != ShapeRole::Plate;
  const bool defaults = role == ShapeRole::StudyBody;  // a thermal study's body: a 1 m box unless told
  if (defaults && !t.has("shape")) s.kind = K::Box;
  else if (spacecraft) s.kind = requireEnum<K>(t, "shape", {{"box", K::Box}, {"cylinder", K::Cylinder}, {"mesh", K::Mesh}});
  else s.kind = requireEnum<K>(t, "shape", {{"rectangle", K::Rectangle}, {"disc", K::Disc},
                                           {"sphere", K::Sphere}, {"mesh", K::Mesh}});
  const std::string shape = t.optString("shape").value_or("box");
  onlyFor(t, {"size"}, s.kind == K::Box, shape);
  onlyFor(t, {"length", "sectors"}, s.kind == K::Cylinder, shape);
  onlyFor(t, {"mesh", "patch", "scale"}, s.kind == K::Mesh, shape);
  onlyFor(t, {"radius"}, s.kind == K::Cylinder || s.kind == K::Disc || s.kind == K::Sphere, shape);
  onlyFor(t, {"segments"}, s.kind == K::Cylinder || s.kind == K::Disc, shape);
  onlyFor(t, {"corner", "edge1", "edge2"}, s.kind == K::Rectangle, shape);
  onlyFor(t, {"center"}, s.kind == K::Disc || s.kind == K::Sphere, shape);
  onlyFor(t, {"normal"}, s.kind == K::Disc, shape);
  onlyFor(t, {"subdivisions"}, s.kind == K::Sphere, shape);
  switch (s.kind) {
    case K::Box: {
      s.size = defaults ? optVec3(t, "size", kLength).value_or(Vec3{1, 1, 1}) : requireVec3(t, "size", kLength);
      for (int k = 0; k < 3; ++k)
        if (!(s.size[k] > 0.0)) t.fail("size", "every size must be > 0 ([depth, height, width] in m)");
      break;
    }
    case K::Cylinder:
      s.radius = requirePositive(t, "radius", kLength);
      s.length = requirePositive(t, "length", kLength);
      s.segments = static_cast<int>(integerIn(t, "segments", 64, 3, 1 << 16));
      s.sectors = static_cast<int>(integerIn(t, "sectors", 1, 1, s.segments));
      if (s.segments % s.sectors != 0) t.fail("sectors", "must divide segments");
      break;
    case K::Rectangle:
      s.corner = requireVec3(t, "corner", kLength);
      s.edge1 = requireVec3(t, "edge1", kLength);
      s.edge2 = requireVec3(t, "edge2", kLength);
      if (vec3::norm(vec3::cross(s.edge1, s.edge2)) == 0.0) t.fail("edge2", "edges must not be zero or parallel");
      break;
    case K::Disc:
      s.center = requireVec3(t, "center", kLength);
      s.normal = direction(t, "normal", {0, 0, 1});
      s.radius = requirePositive(t, "radius", kLength);
      s.segments = static_cast<int>(integerIn(t, "segments", 256, 3, 1 << 16));
      break;
    case K::Sphere:
      s.center = requireVec3(t, "center", kLength);
      s.radius = requirePositive(t, "radius", kLength);
      s.subdivisions = static_cast<int>(integerIn(t, "subdivisions", 4, 0, 7));
      break;
    case K::Mesh:
      s.mesh = meshPath(t, base);
      // The length of one mesh unit: 0.001 or "1 mm" for a mesh drawn in millimetres.
      s.scale = optPositive(t, "scale", kLength, 1.0);
      break;
  }
  // Plates are named by `name` (a mesh plate: the name of its faces outside any group); a
  // spacecraft mesh may name its ungrouped faces by `patch`.
  if (!spacecraft) s.name = t.requireString("name");
  else if (s.kind == K::Mesh && t.has("patch")) s.name = t.requireString("patch");
  return s;
}

GeometryConfig parseGeometryConfig(const std::string& tomlText, const std::string& sourceName,
                                   const fs::path& baseDirectory) {
  const InputDocument doc(tomlText, sourceName, geometrySchema(), kRaise);
  return validate(doc.context(), doc.top(), baseDirectory);
}

GeometryConfig loadGeometryConfig(const fs::path& path) {
  return parseGeometryConfig(readInputFile(path, "geometry file", kRaise), path.string(), path.parent_path());
}

}  // namespace ejecta::radiation
