// Geometry files: TOML parsed by toml++, every key checked against the allowed keys of its table,
// messages "FILE:LINE: key 'a.b': reason". Then the scene is built and run (computeViewFactors)
// and the report printed as text or JSON.
#include "radiation/geometry_file.hpp"

#include <omp.h>
#include <toml++/toml.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <numbers>
#include <set>
#include <sstream>

#include "core/json.hpp"
#include "radiation/mesh_io.hpp"

namespace ejecta::radiation {

namespace fs = std::filesystem;

namespace {

using KeyList = std::vector<std::string_view>;

const std::map<std::string_view, KeyList>& allowedKeys() {
  static const std::map<std::string_view, KeyList> keys = {
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

std::string typeName(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a number";
    case toml::node_type::boolean: return "a boolean";
    default: return "a date/time";
  }
}

class Context {
 public:
  Context(std::string source, fs::path base) : source_(std::move(source)), base_(std::move(base)) {}
  const fs::path& base() const { return base_; }
  const std::string& source() const { return source_; }
  std::string where(const toml::node* n) const {
    const int line = n ? static_cast<int>(n->source().begin.line) : 0;
    return source_ + ":" + std::to_string(line > 0 ? line : 1);
  }
  [[noreturn]] void fail(const toml::node* at, const std::string& key, const std::string& reason) const {
    throw GeometryFileError(where(at) + ": key '" + key + "': " + reason);
  }

 private:
  std::string source_;
  fs::path base_;
};

// Checked, typed access to one table.
class Table {
 public:
  Table(const Context& ctx, const toml::table& t, std::string path, std::string_view schema)
      : ctx_(ctx), t_(t), path_(std::move(path)) {
    const auto& keys = allowedKeys();
    const auto it = keys.find(schema);
    for (auto&& [k, v] : t_) {
      bool ok = false;
      if (it != keys.end())
        for (std::string_view a : it->second) ok = ok || a == k.str();
      if (!ok) {
        std::string list;
        if (it != keys.end())
          for (std::string_view a : it->second) {
            if (!list.empty()) list += ", ";
            list.append(a);
          }
        ctx_.fail(&v, key(k.str()), "unknown key; allowed keys here: " + list);
      }
    }
  }

  std::string key(std::string_view k) const {
    std::string out = path_;
    if (!out.empty()) out += '.';
    out.append(k);
    return out;
  }
  const toml::node* find(std::string_view k) const { return t_.get(k); }
  bool has(std::string_view k) const { return find(k) != nullptr; }
  [[noreturn]] void fail(std::string_view k, const std::string& reason) const {
    const toml::node* n = find(k);
    ctx_.fail(n ? n : &t_, key(k), reason);
  }
  const toml::node& require(std::string_view k) const {
    const toml::node* n = find(k);
    if (!n) ctx_.fail(&t_, key(k), "required key is missing");
    return *n;
  }

  double numberOf(const toml::node& n, const std::string& fullKey) const {
    if (!n.is_integer() && !n.is_floating_point())
      ctx_.fail(&n, fullKey, "expected a number, got " + typeName(n));
    const double x = *n.value<double>();
    if (!std::isfinite(x)) ctx_.fail(&n, fullKey, "must be finite");
    return x;
  }
  std::optional<double> optNumber(std::string_view k) const {
    const toml::node* n = find(k);
    if (!n) return std::nullopt;
    return numberOf(*n, key(k));
  }
  double number(std::string_view k) const { return numberOf(require(k), key(k)); }
  double positive(std::string_view k) const {
    const double x = number(k);
    if (!(x > 0.0)) fail(k, "must be > 0");
    return x;
  }
  double optPositive(std::string_view k, double fallback) const {
    if (!has(k)) return fallback;
    return positive(k);
  }

  std::optional<long long> optInteger(std::string_view k) const {
    const toml::node* n = find(k);
    if (!n) return std::nullopt;
    if (!n->is_integer()) fail(k, "expected an integer, got " + typeName(*n));
    return *n->value<std::int64_t>();
  }
  int integerIn(std::string_view k, int fallback, long long lo, long long hi) const {
    const auto v = optInteger(k);
    if (!v) return fallback;
    if (*v < lo || *v > hi) fail(k, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return static_cast<int>(*v);
  }

  std::optional<std::string> optString(std::string_view k) const {
    const toml::node* n = find(k);
    if (!n) return std::nullopt;
    if (!n->is_string()) fail(k, "expected a string, got " + typeName(*n));
    return *n->value<std::string>();
  }
  std::string string(std::string_view k) const {
    require(k);
    return *optString(k);
  }
  std::optional<bool> optBool(std::string_view k) const {
    const toml::node* n = find(k);
    if (!n) return std::nullopt;
    if (!n->is_boolean()) fail(k, "expected true or false, got " + typeName(*n));
    return *n->value<bool>();
  }

  Vec3 vectorOf(const toml::node& n, const std::string& fullKey) const {
    const toml::array* a = n.as_array();
    if (!a || a->size() != 3) ctx_.fail(&n, fullKey, "expected an array of 3 numbers [x, y, z]");
    Vec3 v{};
    for (std::size_t i = 0; i < 3; ++i) v[i] = numberOf(*a->get(i), fullKey + "[" + std::to_string(i) + "]");
    return v;
  }
  std::optional<Vec3> optVector(std::string_view k) const {
    const toml::node* n = find(k);
    if (!n) return std::nullopt;
    return vectorOf(*n, key(k));
  }
  Vec3 vector(std::string_view k) const { return vectorOf(require(k), key(k)); }
  Vec3 direction(std::string_view k, const Vec3& fallback) const {
    const auto v = optVector(k);
    if (!v) return fallback;
    if (vec3::norm(*v) == 0.0) fail(k, "must not be the zero vector");
    return *v;
  }

  const toml::array* optArray(std::string_view k) const {
    const toml::node* n = find(k);
    if (!n) return nullptr;
    if (!n->is_array()) fail(k, "expected an array, got " + typeName(*n));
    return n->as_array();
  }
  std::vector<double> numbers(std::string_view k) const {
    std::vector<double> out;
    if (const toml::array* a = optArray(k))
      for (std::size_t i = 0; i < a->size(); ++i)
        out.push_back(numberOf(*a->get(i), key(k) + "[" + std::to_string(i) + "]"));
    return out;
  }
  std::vector<std::string> strings(std::string_view k) const {
    std::vector<std::string> out;
    if (const toml::array* a = optArray(k))
      for (std::size_t i = 0; i < a->size(); ++i) {
        const toml::node* e = a->get(i);
        if (!e->is_string())
          ctx_.fail(e, key(k) + "[" + std::to_string(i) + "]", "expected a string, got " + typeName(*e));
        out.push_back(*e->value<std::string>());
      }
    return out;
  }
  const toml::table* optTable(std::string_view k) const {
    const toml::node* n = find(k);
    if (!n) return nullptr;
    if (!n->is_table()) fail(k, "expected a table, got " + typeName(*n));
    return n->as_table();
  }
  std::vector<const toml::table*> tableArray(std::string_view k) const {
    std::vector<const toml::table*> out;
    const toml::array* a = optArray(k);
    if (!a) return out;
    for (std::size_t i = 0; i < a->size(); ++i) {
      const toml::node* e = a->get(i);
      if (!e->is_table())
        ctx_.fail(e, key(k) + "[" + std::to_string(i) + "]", "expected a table ([[" + std::string(k) + "]])");
      out.push_back(e->as_table());
    }
    return out;
  }

  template <typename E>
  E choice(std::string_view k, const std::vector<std::pair<std::string_view, E>>& names) const {
    const std::string s = string(k);
    std::string list;
    for (const auto& [name, value] : names) {
      if (name == s) return value;
      list += (list.empty() ? "'" : ", '");
      list.append(name);
      list += "'";
    }
    fail(k, "unknown value '" + s + "'; allowed: " + list);
  }

  const Context& context() const { return ctx_; }

 private:
  const Context& ctx_;
  const toml::table& t_;
  std::string path_;
};

// Keys that only some shapes take: reject the others, so a typo'd shape cannot silently drop
// dimensions.
void onlyFor(const Table& t, std::initializer_list<std::string_view> keys, bool allowed,
             const std::string& shape) {
  if (allowed) return;
  for (std::string_view k : keys)
    if (t.has(k)) t.fail(k, "not used by shape '" + shape + "'");
}

fs::path resolveMesh(const Table& t) {
  const fs::path p = t.string("mesh");
  if (p.empty()) t.fail("mesh", "must not be empty");
  return p.is_absolute() ? p : t.context().base() / p;
}

ShapeSpec readShape(const Table& t, bool spacecraft) {
  ShapeSpec s;
  using K = ShapeSpec::Kind;
  s.kind = spacecraft ? t.choice<K>("shape", {{"box", K::Box}, {"cylinder", K::Cylinder}, {"mesh", K::Mesh}})
                      : t.choice<K>("shape", {{"rectangle", K::Rectangle}, {"disc", K::Disc},
                                              {"sphere", K::Sphere}, {"mesh", K::Mesh}});
  const std::string shape = t.string("shape");
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
      s.size = t.vector("size");
      for (int k = 0; k < 3; ++k)
        if (!(s.size[k] > 0.0)) t.fail("size", "every size must be > 0 ([depth, height, width] in m)");
      break;
    }
    case K::Cylinder:
      s.radius = t.positive("radius");
      s.length = t.positive("length");
      s.segments = t.integerIn("segments", 64, 3, 1 << 16);
      s.sectors = t.integerIn("sectors", 1, 1, s.segments);
      if (s.segments % s.sectors != 0) t.fail("sectors", "must divide segments");
      break;
    case K::Rectangle:
      s.corner = t.vector("corner");
      s.edge1 = t.vector("edge1");
      s.edge2 = t.vector("edge2");
      if (vec3::norm(vec3::cross(s.edge1, s.edge2)) == 0.0) t.fail("edge2", "edges must not be zero or parallel");
      break;
    case K::Disc:
      s.center = t.vector("center");
      s.normal = t.direction("normal", {0, 0, 1});
      s.radius = t.positive("radius");
      s.segments = t.integerIn("segments", 256, 3, 1 << 16);
      break;
    case K::Sphere:
      s.center = t.vector("center");
      s.radius = t.positive("radius");
      s.subdivisions = t.integerIn("subdivisions", 4, 0, 7);
      break;
    case K::Mesh:
      s.mesh = resolveMesh(t);
      s.scale = t.optPositive("scale", 1.0);
      break;
  }
  // Plates are named by `name` (a mesh plate: the name of its faces outside any group); a
  // spacecraft mesh may name its ungrouped faces by `patch`.
  if (!spacecraft) s.name = t.string("name");
  else if (s.kind == K::Mesh && t.has("patch")) s.name = t.string("patch");
  return s;
}

SpacecraftSpec readSpacecraft(const Table& t) {
  SpacecraftSpec sc;
  sc.body = readShape(t, true);
  sc.pose.position = t.optVector("position").value_or(Vec3{});
  sc.pose.velocity = t.optVector("velocity").value_or(Vec3{});
  const bool byAxis = t.has("rotation_axis") || t.has("rotation_angle");
  if (byAxis && (t.has("forward") || t.has("up")))
    t.fail("rotation_axis", "give the attitude as forward/up or as rotation_axis/rotation_angle, not both");
  if (byAxis) {
    const Vec3 axis = t.direction("rotation_axis", {0, 0, 1});
    const double degrees = t.number("rotation_angle");
    sc.pose.attitude = Rotation::fromAxisAngle(axis, degrees * std::numbers::pi / 180.0);
  } else {
    const Vec3 forward = t.direction("forward", {1, 0, 0}), up = t.direction("up", {0, 1, 0});
    try {
      sc.pose.attitude = Rotation::fromForwardUp(forward, up);
    } catch (const std::invalid_argument& e) {
      t.fail("up", e.what());
    }
  }
  if (t.has("times")) {
    sc.times = t.numbers("times");
    if (sc.times.empty()) t.fail("times", "must list at least one time");
  }
  return sc;
}

EmitterSpec readEmitter(const Table& t) {
  EmitterSpec e;
  using K = EmitterSpec::Kind;
  e.kind = t.choice<K>("shape", {{"sphere", K::Sphere}, {"box", K::Box}, {"disc", K::Disc}, {"points", K::Points}});
  const std::string shape = t.string("shape");
  e.name = t.string("name");
  onlyFor(t, {"center", "radius"}, e.kind == K::Sphere || e.kind == K::Disc, shape);
  onlyFor(t, {"normal"}, e.kind == K::Disc, shape);
  onlyFor(t, {"min", "max"}, e.kind == K::Box, shape);
  onlyFor(t, {"spacing"}, e.kind != K::Points, shape);
  onlyFor(t, {"points", "radii"}, e.kind == K::Points, shape);
  e.emissivity = t.has("emissivity") ? t.number("emissivity") : kGraniteEmissivity;
  if (!(e.emissivity > 0.0 && e.emissivity <= 1.0)) t.fail("emissivity", "must be in (0, 1]");
  if (t.has("emitter_radius")) e.emitterRadius = t.positive("emitter_radius");
  // One temperature, or (points) one per point.
  const toml::node& temp = t.require("temperature");
  if (temp.is_array()) {
    if (e.kind != K::Points) t.fail("temperature", "an array of temperatures needs shape 'points'");
    e.temperatures = t.numbers("temperature");
  } else {
    e.temperatures = {t.number("temperature")};
  }
  for (double T : e.temperatures)
    if (!(T >= 0.0)) t.fail("temperature", "must be >= 0 K");
  switch (e.kind) {
    case K::Sphere:
    case K::Disc:
      e.center = t.vector("center");
      e.radius = t.positive("radius");
      e.spacing = t.positive("spacing");
      if (e.kind == K::Disc) e.normal = t.direction("normal", {0, 0, 1});
      break;
    case K::Box:
      e.min = t.vector("min");
      e.max = t.vector("max");
      for (int k = 0; k < 3; ++k)
        if (!(e.max[k] > e.min[k])) t.fail("max", "must exceed min in every component");
      e.spacing = t.positive("spacing");
      break;
    case K::Points: {
      const toml::array* a = t.optArray("points");
      if (!a || a->empty()) t.fail("points", "list at least one point [[x, y, z], ...]");
      for (std::size_t i = 0; i < a->size(); ++i)
        e.points.push_back(t.vectorOf(*a->get(i), t.key("points") + "[" + std::to_string(i) + "]"));
      e.radii = t.numbers("radii");
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

SamplingOptions readSampling(const Table& t) {
  SamplingOptions o;
  auto count = [&t](std::string_view k, std::uint64_t fallback) -> std::uint64_t {
    const auto v = t.optInteger(k);
    if (!v) return fallback;
    if (*v < 1 || *v > (1ll << 40)) t.fail(k, "must be in [1, 2^40]");
    return static_cast<std::uint64_t>(*v);
  };
  o.rays = count("rays", 0);
  if (t.has("tolerance")) {
    o.absoluteTolerance = t.number("tolerance");
    if (!(o.absoluteTolerance > 0.0)) t.fail("tolerance", "must be > 0");
  }
  if (t.has("relative_tolerance")) {
    o.relativeTolerance = t.number("relative_tolerance");
    if (!(o.relativeTolerance > 0.0)) t.fail("relative_tolerance", "must be > 0");
  }
  if (t.has("rays") && (t.has("tolerance") || t.has("relative_tolerance")))
    t.fail("rays", "give a fixed ray count or tolerances, not both");
  o.minRays = count("min_rays", o.minRays);
  o.maxRays = count("max_rays", o.maxRays);
  if (o.maxRays < o.minRays) t.fail("max_rays", "must be >= min_rays");
  o.replicates = t.integerIn("replicates", o.replicates, 2, 1024);
  if (const auto seed = t.optInteger("seed")) o.seed = static_cast<std::uint64_t>(*seed);
  if (t.has("sampler"))
    o.sampler = t.choice<sampling::Sampler>("sampler", {{"sobol", sampling::Sampler::Sobol},
                                                        {"random", sampling::Sampler::Random}});
  return o;
}

GeometryConfig validate(const toml::table& root, const Context& ctx) {
  GeometryConfig c;
  c.source = ctx.source();
  const Table top(ctx, root, "", "");
  if (const toml::table* g = top.optTable("geometry")) {
    const Table t(ctx, *g, "geometry", "geometry");
    c.name = t.optString("name").value_or("");
    c.description = t.optString("description").value_or("");
  }
  if (const toml::table* s = top.optTable("spacecraft")) c.spacecraft = readSpacecraft(Table(ctx, *s, "spacecraft", "spacecraft"));
  const auto surfaces = top.tableArray("surfaces");
  for (std::size_t i = 0; i < surfaces.size(); ++i)
    c.surfaces.push_back(readShape(Table(ctx, *surfaces[i], "surfaces[" + std::to_string(i) + "]", "surfaces[]"), false));
  const auto emitters = top.tableArray("emitters");
  for (std::size_t i = 0; i < emitters.size(); ++i)
    c.emitters.push_back(readEmitter(Table(ctx, *emitters[i], "emitters[" + std::to_string(i) + "]", "emitters[]")));
  if (const toml::table* h = top.optTable("hot_material")) {
    const Table t(ctx, *h, "hot_material", "hot_material");
    if (t.has("min_temperature")) c.minTemperature = t.number("min_temperature");
  }
  if (const toml::table* o = top.optTable("occluder")) {
    const Table t(ctx, *o, "occluder", "occluder");
    OccluderSpec occ;
    using K = ShapeSpec::Kind;
    occ.shape.kind = t.choice<K>("shape", {{"sphere", K::Sphere}, {"mesh", K::Mesh}});
    occ.shape.name = "occluder";
    if (occ.shape.kind == K::Sphere) {
      onlyFor(t, {"mesh", "scale"}, false, "sphere");
      occ.shape.center = t.vector("center");
      occ.shape.radius = t.positive("radius");
      occ.shape.subdivisions = t.integerIn("subdivisions", 5, 0, 7);
    } else {
      onlyFor(t, {"center", "radius", "subdivisions"}, false, "mesh");
      occ.shape.mesh = resolveMesh(t);
      occ.shape.scale = t.optPositive("scale", 1.0);
    }
    if (t.has("temperature")) occ.temperature = t.number("temperature");
    if (!(occ.temperature >= 0.0)) t.fail("temperature", "must be >= 0 K");
    if (t.has("emissivity")) occ.emissivity = t.number("emissivity");
    if (!(occ.emissivity > 0.0 && occ.emissivity <= 1.0)) t.fail("emissivity", "must be in (0, 1]");
    c.occluder = occ;
  }
  if (const toml::table* r = top.optTable("receivers")) {
    const Table t(ctx, *r, "receivers", "receivers");
    c.receiverPatches = t.strings("patches");
    if (t.has("baseline_length")) c.baseline.receiverSide = t.positive("baseline_length");
    if (t.optBool("baseline_uses_emitter_size").value_or(false)) c.baseline.length = BaselineLength::EmitterDiameter;
  }
  const auto points = top.tableArray("points");
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Table t(ctx, *points[i], "points[" + std::to_string(i) + "]", "points[]");
    c.points.push_back({t.string("name"), t.vector("position"), t.direction("normal", {0, 0, 1})});
  }
  if (const toml::table* s = top.optTable("sampling")) c.sampling = readSampling(Table(ctx, *s, "sampling", "sampling"));
  const auto references = top.tableArray("references");
  for (std::size_t i = 0; i < references.size(); ++i) {
    const Table t(ctx, *references[i], "references[" + std::to_string(i) + "]", "references[]");
    ReferenceFactor r;
    r.from = t.string("from");
    r.to = t.string("to");
    r.value = t.number("value");
    if (!(r.value >= 0.0 && r.value <= 1.0)) t.fail("value", "a view factor is between 0 and 1");
    r.source = t.optString("source").value_or("");
    r.line = static_cast<int>(references[i]->source().begin.line);
    c.references.push_back(std::move(r));
  }
  if (!c.spacecraft && c.surfaces.empty() && c.points.empty())
    throw GeometryFileError(ctx.source() + ":1: nothing to receive radiation: give [spacecraft], [[surfaces]] or [[points]]");
  return c;
}

// -------------------------------------------------------------------------------- building

TriangleMesh buildShape(const ShapeSpec& s, const std::string& source) {
  using K = ShapeSpec::Kind;
  switch (s.kind) {
    case K::Box: return makeBox(s.size[0], s.size[1], s.size[2]);
    case K::Cylinder: return makeCylinder(s.radius, s.length, s.segments, s.sectors);
    case K::Rectangle: return makeRectangle(s.name, s.corner, s.edge1, s.edge2);
    case K::Disc: return makeDisc(s.name, s.center, s.normal, s.radius, s.segments);
    case K::Sphere: return makeSphere(s.name, s.center, s.radius, s.subdivisions);
    case K::Mesh:
      try {
        return readMesh(s.mesh, {s.name, s.scale});
      } catch (const MeshError& e) {
        throw GeometryFileError(source + ": " + e.what());
      }
  }
  return {};
}

// Lattice points of an emitter region (spacing s, centred on the region).
std::vector<Vec3> latticePoints(const EmitterSpec& e) {
  std::vector<Vec3> pts;
  using K = EmitterSpec::Kind;
  const double s = e.spacing;
  if (e.kind == K::Box) {
    int n[3];
    for (int k = 0; k < 3; ++k) n[k] = std::max(1, static_cast<int>(std::lround((e.max[k] - e.min[k]) / s)));
    for (int i = 0; i < n[0]; ++i)
      for (int j = 0; j < n[1]; ++j)
        for (int k = 0; k < n[2]; ++k)
          pts.push_back({e.min[0] + (i + 0.5) * (e.max[0] - e.min[0]) / n[0],
                         e.min[1] + (j + 0.5) * (e.max[1] - e.min[1]) / n[1],
                         e.min[2] + (k + 0.5) * (e.max[2] - e.min[2]) / n[2]});
  } else if (e.kind == K::Sphere) {
    const int m = static_cast<int>(std::floor(e.radius / s));
    for (int i = -m; i <= m; ++i)
      for (int j = -m; j <= m; ++j)
        for (int k = -m; k <= m; ++k) {
          const Vec3 d{i * s, j * s, k * s};
          if (vec3::norm(d) <= e.radius) pts.push_back(vec3::add(e.center, d));
        }
  } else if (e.kind == K::Disc) {
    const Vec3 n = vec3::normalized(e.normal);
    const Vec3 helper = std::abs(n[0]) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 u = vec3::normalized(vec3::cross(helper, n)), v = vec3::cross(n, u);
    const int m = static_cast<int>(std::floor(e.radius / s));
    for (int i = -m; i <= m; ++i)
      for (int j = -m; j <= m; ++j)
        if (std::hypot(i * s, j * s) <= e.radius)
          pts.push_back(vec3::add(e.center, vec3::add(vec3::scale(u, i * s), vec3::scale(v, j * s))));
  } else {
    pts = e.points;
  }
  return pts;
}

// -------------------------------------------------------------------------------- formatting

std::string fmt(const char* format, double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, x);
  return buf;
}

// The report's numbers: 10 significant digits, null where not finite.
std::string jsonNumber(double x) { return ejecta::jsonNumber(x, 10); }

std::string jsonEstimate(const Estimate& e) {
  return "{\"value\": " + jsonNumber(e.value) + ", \"std_error\": " + jsonNumber(e.standardError) + "}";
}

}  // namespace

GeometryConfig parseGeometryConfig(const std::string& tomlText, const std::string& sourceName,
                                   const fs::path& baseDirectory) {
  toml::table doc;
  try {
    doc = toml::parse(tomlText, sourceName);
  } catch (const toml::parse_error& e) {
    throw GeometryFileError(sourceName + ":" + std::to_string(e.source().begin.line) +
                            ": TOML syntax error: " + std::string(e.description()));
  }
  return validate(doc, Context(sourceName, baseDirectory));
}

GeometryConfig loadGeometryConfig(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw GeometryFileError(path.string() + ": cannot open the geometry file");
  std::ostringstream text;
  text << in.rdbuf();
  return parseGeometryConfig(text.str(), path.string(), path.parent_path());
}

Emitters buildEmitters(const GeometryConfig& config) {
  Emitters all;
  for (const EmitterSpec& e : config.emitters) {
    const std::vector<Vec3> pts = latticePoints(e);
    // Default sphere size of a lattice: just opaque (every point of a 3D region, or of a disc's
    // plane, inside some sphere: sqrt(3)/2 or sqrt(2)/2 spacings).
    double defaultRadius = e.emitterRadius;
    if (defaultRadius == 0.0 && e.kind != EmitterSpec::Kind::Points)
      defaultRadius = e.kind == EmitterSpec::Kind::Disc ? 0.5 * std::sqrt(2.0) * e.spacing
                                                        : opaqueLatticeRadius(e.spacing);
    std::vector<double> x, y, z, r, t;
    for (std::size_t i = 0; i < pts.size(); ++i) {
      x.push_back(pts[i][0]);
      y.push_back(pts[i][1]);
      z.push_back(pts[i][2]);
      r.push_back(e.radii.empty() ? defaultRadius : e.radii[i]);
      t.push_back(e.temperatures.size() == 1 ? e.temperatures[0] : e.temperatures[i]);
    }
    EmitterSource src{x, y, z, r, t, {}};
    EmitterSelection sel;
    sel.minTemperature = config.minTemperature;
    sel.emissivityByMaterial = {e.emissivity};
    sel.materialNames = {e.name};
    try {
      all.append(selectEmitters(src, sel));
    } catch (const std::invalid_argument& err) {
      throw GeometryFileError(config.source + ": emitters '" + e.name + "': " + err.what());
    }
  }
  return all;
}

namespace {

// The parts of a scene that do not move, and the spacecraft in its body frame.
struct SceneParts {
  TriangleMesh body;      // body frame (empty without a spacecraft)
  TriangleMesh plates;
  Emitters emitters;
  Occluder occluder;
};

SceneParts buildParts(const GeometryConfig& config) {
  SceneParts parts;
  try {
    if (config.spacecraft) parts.body = buildShape(config.spacecraft->body, config.source);
    for (const ShapeSpec& s : config.surfaces) {
      const TriangleMesh plate = buildShape(s, config.source);
      for (const std::string& name : plate.patchNames)
        if (parts.body.findPatch(name) >= 0 || parts.plates.findPatch(name) >= 0)
          throw GeometryFileError(config.source + ": surface patch '" + name +
                                  "' has the name of a patch that already exists");
      parts.plates.append(plate);
    }
    parts.emitters = buildEmitters(config);
    if (config.occluder) {
      parts.occluder.mesh = buildShape(config.occluder->shape, config.source);
      parts.occluder.temperature = config.occluder->temperature;
      parts.occluder.emissivity = config.occluder->emissivity;
    }
  } catch (const std::invalid_argument& e) {
    throw GeometryFileError(config.source + ": " + e.what());
  }
  return parts;
}

RadiationScene assemble(const GeometryConfig& config, const SceneParts& parts, double time) {
  RadiationScene scene;
  if (config.spacecraft) scene.surfaces = placeMesh(parts.body, config.spacecraft->pose.at(time));
  scene.surfaces.append(parts.plates);
  scene.emitters = parts.emitters;
  scene.occluder = parts.occluder;
  return scene;
}

}  // namespace

RadiationScene buildRadiationScene(const GeometryConfig& config, double time) {
  return assemble(config, buildParts(config), time);
}

ViewFactorReport computeViewFactors(const GeometryConfig& config, const ViewFactorRunOptions& run) {
  ViewFactorReport report;
  report.name = config.name;
  report.source = config.source;
  report.sampling = config.sampling;
  if (run.rays) {
    report.sampling.rays = *run.rays;
  } else if (run.tolerance) {
    report.sampling.rays = 0;
    report.sampling.absoluteTolerance = *run.tolerance;
  }
  report.threads = omp_get_max_threads();
  const SceneParts parts = buildParts(config);
  // The receivers: the listed patches, else the spacecraft's, else every plate.
  std::vector<std::string> patches = config.receiverPatches;
  if (patches.empty()) patches = config.spacecraft ? parts.body.patchNames : parts.plates.patchNames;
  for (const std::string& p : patches)
    if (parts.body.findPatch(p) < 0 && parts.plates.findPatch(p) < 0)
      throw GeometryFileError(config.source + ": receiver patch '" + p + "' does not exist");
  const std::vector<double> times = config.spacecraft ? config.spacecraft->times : std::vector<double>{0.0};
  const auto start = std::chrono::steady_clock::now();
  for (const double time : times) {
    ViewFactorSolver solver(assemble(config, parts, time));
    const RadiationScene& s = solver.scene();
    report.patchNames = s.surfaces.patchNames;
    report.groupNames = s.emitters.groupNames;
    report.emitterCount = s.emitters.size();
    report.occluder = !s.occluder.mesh.triangles.empty();
    for (const std::string& p : patches) {
      const auto idx = static_cast<std::size_t>(s.surfaces.findPatch(p));
      ReceiverReport r;
      r.receiver = p;
      r.time = time;
      r.area = s.surfaces.patchArea(idx);
      r.result = solver.fromPatch(idx, report.sampling);
      if (!s.emitters.empty()) r.baseline = seedBaseline(s.emitters, s.surfaces, idx, config.baseline);
      report.receivers.push_back(std::move(r));
    }
    for (const PointReceiverSpec& pt : config.points) {
      ReceiverReport r;
      r.receiver = pt.name;
      r.point = true;
      r.time = time;
      r.result = solver.fromPoint(pt.position, pt.normal, report.sampling);
      report.receivers.push_back(std::move(r));
    }
  }
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

std::string formatViewFactorText(const ViewFactorReport& rep) {
  std::ostringstream out;
  out << "view factors: " << (rep.name.empty() ? rep.source : rep.name) << "\n";
  out << "  " << rep.patchNames.size() << " surface patches, " << rep.emitterCount << " emitters in "
      << rep.groupNames.size() << " groups" << (rep.occluder ? ", an occluder" : "") << "\n";
  const SamplingOptions& o = rep.sampling;
  out << "  sampling: " << (o.sampler == sampling::Sampler::Sobol ? "scrambled Sobol'" : "random") << ", "
      << o.replicates << " replicates, "
      << (o.rays > 0 ? "fixed " + std::to_string(o.rays) + " rays"
                     : "adaptive to std error " + fmt("%.2g", o.absoluteTolerance) +
                           (o.relativeTolerance > 0.0 ? " (flux " + fmt("%.2g", o.relativeTolerance) + " relative)" : ""))
      << "; " << rep.threads << " threads, " << fmt("%.2f", rep.seconds) << " s\n";
  for (const ReceiverReport& r : rep.receivers) {
    const ReceiverResult& res = r.result;
    out << "\n" << (r.point ? "point " : "patch ") << r.receiver << "  t = " << fmt("%g", r.time) << " s";
    if (!r.point) out << "  area " << fmt("%.6g", r.area) << " m^2";
    out << "  rays " << res.rays << (res.converged ? "" : "  (NOT converged: max rays reached)") << "\n";
    auto line = [&out](const std::string& label, const Estimate& e, const char* unit) {
      out << "  " << label;
      for (std::size_t k = label.size(); k < 28; ++k) out << ' ';
      out << fmt("%12.6g", e.value) << " +- " << fmt("%.2g", e.standardError) << unit << "\n";
    };
    if (!rep.groupNames.empty() || rep.occluder) {
      line("incident flux", res.flux, " W/m^2");
      if (r.baseline)
        out << "  seed baseline (eq. 4.8)     " << fmt("%12.6g", r.baseline->flux) << " W/m^2 from "
            << r.baseline->counted << " emitters, sum Omega " << fmt("%.4g", r.baseline->solidAngleSum) << "\n";
    }
    for (std::size_t p = 0; p < res.toPatch.size(); ++p)
      if (res.toPatch[p].value > 0.0) line("F -> " + rep.patchNames[p], res.toPatch[p], "");
    for (std::size_t g = 0; g < res.toGroup.size(); ++g)
      line("F -> emitters " + rep.groupNames[g], res.toGroup[g], "");
    if (rep.occluder) line("F -> occluder", res.toOccluder, "");
    line("F -> space", res.toSpace, "");
    if (res.toBackFace.value > 0.0) line("F -> back faces (check!)", res.toBackFace, "");
  }
  return out.str();
}

std::string formatViewFactorJson(const ViewFactorReport& rep) {
  std::ostringstream out;
  const SamplingOptions& o = rep.sampling;
  out << "{\n  \"name\": " << jsonString(rep.name) << ",\n  \"source\": " << jsonString(rep.source) << ",\n";
  out << "  \"patches\": [";
  for (std::size_t i = 0; i < rep.patchNames.size(); ++i) out << (i ? ", " : "") << jsonString(rep.patchNames[i]);
  out << "],\n  \"emitter_groups\": [";
  for (std::size_t i = 0; i < rep.groupNames.size(); ++i) out << (i ? ", " : "") << jsonString(rep.groupNames[i]);
  out << "],\n  \"emitters\": " << rep.emitterCount << ",\n  \"occluder\": " << (rep.occluder ? "true" : "false")
      << ",\n  \"sampling\": {\"sampler\": " << jsonString(o.sampler == sampling::Sampler::Sobol ? "sobol" : "random")
      << ", \"replicates\": " << o.replicates << ", \"rays\": " << o.rays
      << ", \"tolerance\": " << jsonNumber(o.absoluteTolerance)
      << ", \"relative_tolerance\": " << jsonNumber(o.relativeTolerance) << ", \"seed\": " << o.seed
      << "},\n  \"threads\": " << rep.threads << ",\n  \"seconds\": " << jsonNumber(rep.seconds)
      << ",\n  \"receivers\": [";
  for (std::size_t i = 0; i < rep.receivers.size(); ++i) {
    const ReceiverReport& r = rep.receivers[i];
    const ReceiverResult& res = r.result;
    out << (i ? "," : "") << "\n    {\"name\": " << jsonString(r.receiver) << ", \"kind\": "
        << jsonString(r.point ? "point" : "patch") << ", \"time\": " << jsonNumber(r.time)
        << ", \"area\": " << jsonNumber(r.area) << ", \"rays\": " << res.rays
        << ", \"converged\": " << (res.converged ? "true" : "false") << ",\n     \"flux\": " << jsonEstimate(res.flux);
    out << ",\n     \"view_factors\": {";
    bool first = true;
    auto entry = [&](const std::string& key, const Estimate& e) {
      out << (first ? "" : ", ") << jsonString(key) << ": " << jsonEstimate(e);
      first = false;
    };
    for (std::size_t p = 0; p < res.toPatch.size(); ++p) entry("patch:" + rep.patchNames[p], res.toPatch[p]);
    for (std::size_t g = 0; g < res.toGroup.size(); ++g) entry("emitters:" + rep.groupNames[g], res.toGroup[g]);
    entry("occluder", res.toOccluder);
    entry("space", res.toSpace);
    entry("back_faces", res.toBackFace);
    out << "},\n     \"flux_by_group\": {";
    for (std::size_t g = 0; g < res.fluxFromGroup.size(); ++g)
      out << (g ? ", " : "") << jsonString(rep.groupNames[g]) << ": " << jsonEstimate(res.fluxFromGroup[g]);
    out << "}, \"flux_from_occluder\": " << jsonEstimate(res.fluxFromOccluder);
    if (r.baseline)
      out << ",\n     \"seed_baseline\": {\"flux\": " << jsonNumber(r.baseline->flux)
          << ", \"solid_angle_sum\": " << jsonNumber(r.baseline->solidAngleSum)
          << ", \"emitters\": " << r.baseline->counted << "}";
    out << "}";
  }
  out << "\n  ]\n}\n";
  return out.str();
}

std::string formatFluxSeriesCsv(const ViewFactorReport& rep) {
  std::vector<std::string> patches;
  std::vector<double> times;
  for (const ReceiverReport& r : rep.receivers) {
    if (r.point) continue;
    if (std::find(patches.begin(), patches.end(), r.receiver) == patches.end()) patches.push_back(r.receiver);
    if (std::find(times.begin(), times.end(), r.time) == times.end()) times.push_back(r.time);
  }
  std::string out = "time_s";
  for (const std::string& p : patches) {
    out += ',';  // appended stepwise: GCC 12 warns falsely (-Wrestrict) on "," + s
    out += p;
  }
  out += "\n";
  for (const double t : times) {
    out += fmt("%.10g", t);
    for (const std::string& p : patches) {
      double q = 0.0;
      for (const ReceiverReport& r : rep.receivers)
        if (!r.point && r.time == t && r.receiver == p) q = r.result.flux.value;
      out += ',';
      out += fmt("%.10g", q);
    }
    out += "\n";
  }
  return out;
}

}  // namespace ejecta::radiation
