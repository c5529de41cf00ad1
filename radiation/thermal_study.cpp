// The thermal study file (TOML, toml++) and the chain it drives: flux along the pass, eq. 4.8,
// the transient wall and the shield sizing. docs/thermal.md.
#include "radiation/thermal_study.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

#include "core/json.hpp"
#include "core/units.hpp"
#include "radiation/radiative_balance.hpp"
#include "radiation/wall_implicit.hpp"

namespace ejecta::radiation {

namespace fs = std::filesystem;

namespace {

using KeyList = std::vector<std::string_view>;

const std::map<std::string_view, KeyList>& allowedKeys() {
  static const std::map<std::string_view, KeyList> keys = {
      {"", {"study", "spacecraft", "approach", "emitters", "walls", "wall", "limit", "sizing", "sampling",
            "baseline"}},
      {"study", {"name", "description"}},
      {"spacecraft", {"shape", "size", "radius", "length", "segments", "sectors", "mesh", "patch", "scale",
                      "forward", "up"}},
      {"approach", {"target", "start", "distance", "direction", "velocity", "speed", "duration", "samples"}},
      {"emitters", {"min_temperature", "default_emissivity", "emissivity"}},
      {"walls[]", {"patch", "patches", "layers", "absorptivity", "emissivity", "cold_emissivity"}},
      {"layers[]", {"material", "thickness", "cells"}},
      {"wall", {"initial_temperature", "time_step"}},
      {"limit", {"kind", "value"}},
      {"sizing", {"coatings", "patches", "max_thickness", "tolerance", "coating_cells"}},
      {"sampling", {"rays", "tolerance", "relative_tolerance", "max_rays", "replicates", "seed"}},
      {"baseline", {"length"}},
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

// Checked access to one table; every failure names the file, the line and the dotted key.
class Table {
 public:
  Table(const std::string& source, const toml::table& t, std::string path, std::string_view schema)
      : source_(source), t_(t), path_(std::move(path)) {
    const KeyList* allowed = nullptr;
    if (const auto it = allowedKeys().find(schema); it != allowedKeys().end()) allowed = &it->second;
    for (auto&& [k, v] : t_) {
      if (allowed && std::find(allowed->begin(), allowed->end(), k.str()) != allowed->end()) continue;
      std::string list;
      if (allowed)
        for (std::string_view a : *allowed) list += std::string(list.empty() ? "" : ", ") + std::string(a);
      failAt(&v, key(k.str()), "unknown key; allowed keys here: " + list);
    }
  }

  std::string key(std::string_view k) const { return path_.empty() ? std::string(k) : path_ + "." + std::string(k); }
  const toml::node* find(std::string_view k) const { return t_.get(k); }
  bool has(std::string_view k) const { return find(k) != nullptr; }
  int line() const { return static_cast<int>(t_.source().begin.line); }

  [[noreturn]] void failAt(const toml::node* n, const std::string& fullKey, const std::string& reason) const {
    const int l = n ? static_cast<int>(n->source().begin.line) : 0;
    throw ThermalStudyError(source_ + ":" + std::to_string(l > 0 ? l : 1) + ": key '" + fullKey + "': " + reason);
  }
  [[noreturn]] void fail(std::string_view k, const std::string& reason) const {
    const toml::node* n = find(k);
    failAt(n ? n : &t_, key(k), reason);
  }
  const toml::node& require(std::string_view k) const {
    const toml::node* n = find(k);
    if (!n) failAt(&t_, key(k), "required key is missing");
    return *n;
  }

  double number(std::string_view k) const {
    const toml::node& n = require(k);
    if (!n.is_integer() && !n.is_floating_point()) fail(k, "expected a number, got " + typeName(n));
    const double x = *n.value<double>();
    if (!std::isfinite(x)) fail(k, "must be finite");
    return x;
  }
  double number(std::string_view k, double fallback) const { return has(k) ? number(k) : fallback; }
  double inRange(std::string_view k, double fallback, double lo, double hi, const char* range) const {
    const double x = number(k, fallback);
    if (!(x >= lo && x <= hi)) fail(k, std::string("must be in ") + range);
    return x;
  }
  // A number (SI) or a string with a unit ("10 km/s"), read by core's parser: a scene's units.
  double quantity(std::string_view k, Dimension kind) const {
    const toml::node& n = require(k);
    if (n.is_string()) {
      try {
        return parseQuantity(*n.value<std::string>(), kind);
      } catch (const UnitError& e) {
        fail(k, e.what());
      }
    }
    return number(k);
  }
  double positiveQuantity(std::string_view k, Dimension kind, double fallback) const {
    if (!has(k)) return fallback;
    const double x = quantity(k, kind);
    if (!(x > 0.0)) fail(k, "must be > 0");
    return x;
  }
  long long integer(std::string_view k, long long fallback, long long lo, long long hi) const {
    const toml::node* n = find(k);
    if (!n) return fallback;
    if (!n->is_integer()) fail(k, "expected an integer, got " + typeName(*n));
    const long long v = *n->value<std::int64_t>();
    if (v < lo || v > hi) fail(k, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return v;
  }
  std::string string(std::string_view k) const {
    const toml::node& n = require(k);
    if (!n.is_string()) fail(k, "expected a string, got " + typeName(n));
    return *n.value<std::string>();
  }
  std::string string(std::string_view k, const std::string& fallback) const {
    return has(k) ? string(k) : fallback;
  }
  Vec3 vector(std::string_view k) const {
    const toml::node& n = require(k);
    const toml::array* a = n.as_array();
    if (!a || a->size() != 3) fail(k, "expected an array of 3 numbers [x, y, z]");
    Vec3 v{};
    for (std::size_t i = 0; i < 3; ++i) {
      const toml::node* e = a->get(i);
      if (!e->is_integer() && !e->is_floating_point())
        failAt(e, key(k) + "[" + std::to_string(i) + "]", "expected a number, got " + typeName(*e));
      v[i] = *e->value<double>();
      if (!std::isfinite(v[i])) failAt(e, key(k) + "[" + std::to_string(i) + "]", "must be finite");
    }
    return v;
  }
  Vec3 direction(std::string_view k, const Vec3& fallback) const {
    if (!has(k)) return fallback;
    const Vec3 v = vector(k);
    if (vec3::norm(v) == 0.0) fail(k, "must not be the zero vector");
    return vec3::scale(v, 1.0 / vec3::norm(v));
  }
  std::vector<std::string> strings(std::string_view k) const {
    std::vector<std::string> out;
    const toml::node* n = find(k);
    if (!n) return out;
    const toml::array* a = n->as_array();
    if (!a) fail(k, "expected an array of strings, got " + typeName(*n));
    for (std::size_t i = 0; i < a->size(); ++i) {
      const toml::node* e = a->get(i);
      if (!e->is_string()) failAt(e, key(k) + "[" + std::to_string(i) + "]", "expected a string, got " + typeName(*e));
      out.push_back(*e->value<std::string>());
    }
    return out;
  }
  const toml::table* table(std::string_view k) const {
    const toml::node* n = find(k);
    if (!n) return nullptr;
    if (!n->is_table()) fail(k, "expected a table, got " + typeName(*n));
    return n->as_table();
  }
  std::vector<const toml::table*> tables(std::string_view k) const {
    std::vector<const toml::table*> out;
    const toml::node* n = find(k);
    if (!n) return out;
    const toml::array* a = n->as_array();
    if (!a) fail(k, "expected an array of tables, got " + typeName(*n));
    for (std::size_t i = 0; i < a->size(); ++i) {
      if (!a->get(i)->is_table()) failAt(a->get(i), key(k) + "[" + std::to_string(i) + "]", "expected a table");
      out.push_back(a->get(i)->as_table());
    }
    return out;
  }
  const std::string& source() const { return source_; }
  const toml::table& raw() const { return t_; }

 private:
  const std::string& source_;
  const toml::table& t_;
  std::string path_;
};

const toml::table kEmpty;

Table sub(const Table& parent, std::string_view k, std::string_view schema) {
  const toml::table* t = parent.table(k);
  return Table(parent.source(), t ? *t : kEmpty, std::string(k), schema);
}

void readSpacecraft(const Table& t, ThermalStudy& s, const fs::path& base, const Vec3& flight) {
  using K = ShapeSpec::Kind;
  ShapeSpec& b = s.spacecraft.body;
  const std::string shape = t.string("shape", "box");
  if (shape == "box") b.kind = K::Box;
  else if (shape == "cylinder") b.kind = K::Cylinder;
  else if (shape == "mesh") b.kind = K::Mesh;
  else t.fail("shape", "unknown value '" + shape + "'; allowed: 'box', 'cylinder', 'mesh'");
  auto only = [&](std::initializer_list<std::string_view> keys, bool ok) {
    if (!ok)
      for (std::string_view k : keys)
        if (t.has(k)) t.fail(k, "not used by shape '" + shape + "'");
  };
  only({"size"}, b.kind == K::Box);
  only({"radius", "length", "segments", "sectors"}, b.kind == K::Cylinder);
  only({"mesh", "patch", "scale"}, b.kind == K::Mesh);
  if (b.kind == K::Box) {
    b.size = t.has("size") ? t.vector("size") : Vec3{1, 1, 1};
    for (int k = 0; k < 3; ++k)
      if (!(b.size[k] > 0.0)) t.fail("size", "every size must be > 0 ([depth, height, width] in m)");
  } else if (b.kind == K::Cylinder) {
    b.radius = t.positiveQuantity("radius", Dimension::Length, 0.0);
    b.length = t.positiveQuantity("length", Dimension::Length, 0.0);
    if (b.radius == 0.0) t.require("radius");
    if (b.length == 0.0) t.require("length");
    b.segments = static_cast<int>(t.integer("segments", 64, 3, 1 << 16));
    b.sectors = static_cast<int>(t.integer("sectors", 1, 1, b.segments));
    if (b.segments % b.sectors != 0) t.fail("sectors", "must divide segments");
  } else {
    const fs::path p = t.string("mesh");
    if (p.empty()) t.fail("mesh", "must not be empty");
    b.mesh = p.is_absolute() ? p : base / p;
    b.scale = t.positiveQuantity("scale", Dimension::Length, 1.0);
    if (t.has("patch")) b.name = t.string("patch");
  }
  // side0 (body +x) leads: by default it points along the flight, towards the crater.
  const Vec3 forward = t.direction("forward", flight);
  const Vec3 up = t.direction("up", std::abs(forward[1]) < 0.99 ? Vec3{0, 1, 0} : Vec3{1, 0, 0});
  try {
    s.spacecraft.pose.attitude = Rotation::fromForwardUp(forward, up);
  } catch (const std::invalid_argument& e) {
    t.fail(t.has("up") ? "up" : "forward", e.what());
  }
}

void readApproach(const Table& t, ApproachSpec& a) {
  a.target = t.has("target") ? t.vector("target") : Vec3{};
  if (t.has("start") == t.has("distance")) {
    if (t.has("start")) t.fail("distance", "give either start or distance (with direction), not both");
    t.require("start");
  }
  if (t.has("direction") && !t.has("distance")) t.fail("direction", "only used with distance");
  if (t.has("start")) {
    a.start = t.vector("start");
  } else {
    const double d = t.positiveQuantity("distance", Dimension::Length, 0.0);
    a.start = vec3::add(a.target, vec3::scale(t.direction("direction", {0, 1, 0}), d));
  }
  const Vec3 towards = vec3::sub(a.target, a.start);
  if (t.has("velocity") == t.has("speed")) {
    if (t.has("velocity")) t.fail("speed", "give either velocity [m/s] or speed (towards the target), not both");
    t.require("speed");
  }
  if (t.has("velocity")) {
    a.velocity = t.vector("velocity");
  } else {
    const double v = t.positiveQuantity("speed", Dimension::Velocity, 0.0);
    if (vec3::norm(towards) == 0.0) t.fail("speed", "the start is the target: no direction to fly in");
    a.velocity = vec3::scale(towards, v / vec3::norm(towards));
  }
  a.duration = t.positiveQuantity("duration", Dimension::Time, 0.0);
  if (a.duration == 0.0) t.require("duration");
  a.samples = static_cast<int>(t.integer("samples", 11, 2, 100000));
}

void readEmitters(const Table& t, EmitterChoice& e) {
  if (t.has("min_temperature")) {
    e.minTemperature = t.quantity("min_temperature", Dimension::Temperature);
    if (!(e.minTemperature >= 0.0)) t.fail("min_temperature", "must be >= 0 K");
  }
  e.defaultEmissivity = t.inRange("default_emissivity", kGraniteEmissivity, 1e-300, 1.0, "(0, 1]");
  if (const toml::table* m = t.table("emissivity")) {
    for (auto&& [k, v] : *m) {
      const std::string full = "emitters.emissivity." + std::string(k.str());
      if (!v.is_integer() && !v.is_floating_point()) t.failAt(&v, full, "expected a number, got " + typeName(v));
      const double x = *v.value<double>();
      if (!(x > 0.0 && x <= 1.0)) t.failAt(&v, full, "must be in (0, 1]");
      e.emissivityByMaterial[std::string(k.str())] = x;
    }
  }
}

WallSpec readWall(const Table& t) {
  WallSpec w;
  w.line = t.line();
  if (t.has("patch") && t.has("patches")) t.fail("patches", "give patch or patches, not both");
  if (t.has("patch")) w.patches = {t.string("patch")};
  else w.patches = t.strings("patches");
  const auto layers = t.tables("layers");
  if (layers.empty()) t.fail("layers", "required: layers from the hot face to the cold one, e.g. "
                                       "[{material = \"tungsten\", thickness = \"0.2 mm\"}, ...]");
  for (std::size_t i = 0; i < layers.size(); ++i) {
    const Table l(t.source(), *layers[i], t.key("layers") + "[" + std::to_string(i) + "]", "layers[]");
    const std::string material = l.string("material");
    const double thickness = l.positiveQuantity("thickness", Dimension::Length, 0.0);
    if (thickness == 0.0) l.require("thickness");
    const int cells = static_cast<int>(l.integer("cells", 20, 1, 100000));
    try {
      w.layers.push_back(wallLayer(material, thickness, cells));
    } catch (const std::invalid_argument& e) {
      l.fail("material", e.what());
    }
  }
  if (t.has("absorptivity")) w.absorptivity = t.inRange("absorptivity", 0, 0.0, 1.0, "[0, 1]");
  if (t.has("emissivity")) w.emissivity = t.inRange("emissivity", 0, 0.0, 1.0, "[0, 1]");
  w.coldEmissivity = t.inRange("cold_emissivity", 0.0, 0.0, 1.0, "[0, 1]");
  return w;
}

void readLimit(const Table& t, ShieldLimit& limit) {
  const std::string kind = t.string("kind", "melting");
  using K = ShieldLimit::Kind;
  if (kind == "melting") {
    limit.kind = K::MeltingPoint;
    if (t.has("value")) t.fail("value", "not used by kind 'melting'");
  } else if (kind == "margin") {
    limit.kind = K::MarginBelowMelting;
    limit.value = t.quantity("value", Dimension::Temperature);
    if (!(limit.value >= 0.0)) t.fail("value", "the margin must be >= 0 K");
  } else if (kind == "temperature") {
    limit.kind = K::Temperature;
    limit.value = t.quantity("value", Dimension::Temperature);
    if (!(limit.value > 0.0)) t.fail("value", "must be > 0 K");
  } else {
    t.fail("kind", "unknown value '" + kind + "'; allowed: 'melting', 'margin', 'temperature'");
  }
}

void readSizing(const Table& t, SizingSpec& s) {
  s.coatings = t.strings("coatings");
  for (std::size_t i = 0; i < s.coatings.size(); ++i) {
    try {
      wallMaterial(s.coatings[i]);
    } catch (const std::invalid_argument& e) {
      t.fail("coatings", e.what());
    }
  }
  s.patches = t.strings("patches");
  s.maxThickness = t.positiveQuantity("max_thickness", Dimension::Length, s.maxThickness);
  s.tolerance = t.inRange("tolerance", s.tolerance, 1e-9, 0.5, "[1e-9, 0.5]");
  s.coatingCells = static_cast<int>(t.integer("coating_cells", s.coatingCells, 1, 100000));
}

void readSampling(const Table& t, SamplingOptions& s) {
  s.absoluteTolerance = 1e-3;
  s.relativeTolerance = 0.0;
  // A relative target applies to every patch, and a face that sees little needs many rays to
  // reach it: a lower cap than the solver's 2^24 bounds that cost (docs/thermal.md).
  s.maxRays = 1u << 22;
  if (t.has("rays")) s.rays = static_cast<std::uint64_t>(t.integer("rays", 0, 256, 1LL << 34));
  s.absoluteTolerance = t.inRange("tolerance", s.absoluteTolerance, 1e-7, 0.5, "[1e-7, 0.5]");
  s.relativeTolerance = t.inRange("relative_tolerance", s.relativeTolerance, 0.0, 1.0, "[0, 1]");
  s.maxRays = static_cast<std::uint64_t>(t.integer("max_rays", static_cast<long long>(s.maxRays), 4096, 1LL << 34));
  s.replicates = static_cast<int>(t.integer("replicates", s.replicates, 2, 1024));
  s.seed = static_cast<std::uint64_t>(t.integer("seed", static_cast<long long>(s.seed), 0,
                                                std::numeric_limits<long long>::max()));
}

// thermal.json's numbers: 12 significant digits, null where not finite.
std::string num(double x) { return jsonNumber(x, 12); }

std::string csvNum(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", x);
  return buf;
}

double seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

}  // namespace

std::vector<double> ApproachSpec::times() const {
  std::vector<double> t(static_cast<std::size_t>(samples));
  for (int i = 0; i < samples; ++i) t[i] = duration * i / (samples - 1);
  return t;
}

ThermalStudy parseThermalStudy(const std::string& tomlText, const std::string& sourceName,
                               const fs::path& baseDirectory) {
  toml::table root;
  try {
    root = toml::parse(tomlText, sourceName);
  } catch (const toml::parse_error& e) {
    throw ThermalStudyError(sourceName + ":" + std::to_string(e.source().begin.line) + ": " +
                            std::string(e.description()));
  }
  ThermalStudy s;
  s.source = sourceName;
  const Table top(s.source, root, "", "");
  const Table study = sub(top, "study", "study");
  s.name = study.string("name", fs::path(sourceName).stem().string());
  s.description = study.string("description", "");
  if (!top.has("approach")) top.fail("approach", "required: the spacecraft's pass ([approach])");
  readApproach(sub(top, "approach", "approach"), s.approach);
  const Vec3 flight = vec3::norm(s.approach.velocity) > 0.0
                          ? vec3::scale(s.approach.velocity, 1.0 / vec3::norm(s.approach.velocity))
                          : Vec3{1, 0, 0};
  readSpacecraft(sub(top, "spacecraft", "spacecraft"), s, baseDirectory, flight);
  s.spacecraft.pose.position = s.approach.start;
  s.spacecraft.pose.velocity = s.approach.velocity;
  s.spacecraft.times = s.approach.times();
  readEmitters(sub(top, "emitters", "emitters"), s.emitters);
  const auto walls = top.tables("walls");
  for (std::size_t i = 0; i < walls.size(); ++i)
    s.walls.push_back(readWall(Table(s.source, *walls[i], "walls[" + std::to_string(i) + "]", "walls[]")));
  const Table wall = sub(top, "wall", "wall");
  if (wall.has("initial_temperature")) {
    s.initialTemperature = wall.quantity("initial_temperature", Dimension::Temperature);
    if (!(s.initialTemperature > 0.0)) wall.fail("initial_temperature", "must be > 0 K");
  }
  s.timeStep = wall.positiveQuantity("time_step", Dimension::Time, 0.0);
  readLimit(sub(top, "limit", "limit"), s.limit);
  const Table sizing = sub(top, "sizing", "sizing");
  readSizing(sizing, s.sizing);
  if (!s.sizing.coatings.empty() && s.walls.empty())
    sizing.fail("coatings", "sizing needs a structure: give [[walls]] (its last layer is the structure)");
  readSampling(sub(top, "sampling", "sampling"), s.sampling);
  const Table baseline = sub(top, "baseline", "baseline");
  s.baseline.receiverSide = baseline.positiveQuantity("length", Dimension::Length, 0.0);
  return s;
}

ThermalStudy loadThermalStudy(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ThermalStudyError(path.string() + ": cannot open the thermal study file");
  std::stringstream text;
  text << in.rdbuf();
  return parseThermalStudy(text.str(), path.string(), path.parent_path());
}

namespace {

// The wall that applies to a patch: the first naming it, else the first with no patch list.
const WallSpec* wallFor(const ThermalStudy& s, const std::string& patch) {
  for (const WallSpec& w : s.walls)
    if (std::find(w.patches.begin(), w.patches.end(), patch) != w.patches.end()) return &w;
  for (const WallSpec& w : s.walls)
    if (w.patches.empty()) return &w;
  return nullptr;
}

FaceCondition coldFace(const WallSpec& w) {
  return w.coldEmissivity > 0.0 ? FaceCondition::radiating(w.coldEmissivity) : FaceCondition::insulated();
}

}  // namespace

ThermalResult runThermalStudy(const ThermalStudy& study, const Emitters& emitters) {
  return runThermalStudy(study, emitters, nullptr);
}

ThermalResult runThermalStudy(const ThermalStudy& study, const Emitters& emitters,
                              const TriangleMesh* occluder) {
  const std::vector<PassFrame> frames(study.approach.times().size(), PassFrame{&emitters, occluder});
  return runThermalStudy(study, frames);
}

ThermalResult runThermalStudy(const ThermalStudy& study, const std::vector<PassFrame>& frames) {
  ThermalResult r;
  r.name = study.name;
  r.source = study.source;
  r.times = study.approach.times();
  if (frames.size() != r.times.size())
    throw ThermalStudyError(study.source + ": " + std::to_string(frames.size()) +
                            " frames of hot material for " + std::to_string(r.times.size()) +
                            " sample times of the approach");
  for (const PassFrame& f : frames) {
    if (!f.emitters) throw ThermalStudyError(study.source + ": a frame of the pass has no emitters");
    const bool occluded = f.occluder && !f.occluder->triangles.empty();
    if (occluded && (&f == &frames.front() || f.occluder != (&f - 1)->occluder))
      validateMesh(*f.occluder, study.source + ": occluder");
    r.occluderTriangles = std::max(r.occluderTriangles, occluded ? f.occluder->triangleCount() : 0);
    if (f.emitters->size() >= r.emitterCount) {
      r.emitterCount = f.emitters->size();
      r.groupNames = f.emitters->groupNames;
    }
  }
  const bool occluded = r.occluderTriangles > 0;

  // The spacecraft's patches, in the body frame placed at t = 0 (to read names and areas).
  GeometryConfig craft;
  craft.source = study.source;
  craft.spacecraft = study.spacecraft;
  TriangleMesh mesh0;
  try {
    mesh0 = buildRadiationScene(craft, 0.0).surfaces;
  } catch (const GeometryFileError& e) {
    throw ThermalStudyError(e.what());
  }
  for (std::size_t p = 0; p < mesh0.patchCount(); ++p) {
    PatchThermal pt;
    pt.patch = mesh0.patchNames[p];
    pt.area = mesh0.patchArea(p);
    r.patches.push_back(std::move(pt));
  }
  auto checkPatches = [&](const std::vector<std::string>& names, const std::string& where) {
    for (const std::string& n : names)
      if (mesh0.findPatch(n) < 0) {
        std::string list;
        for (const std::string& p : mesh0.patchNames) list += std::string(list.empty() ? "" : ", ") + p;
        throw ThermalStudyError(study.source + ": " + where + ": the spacecraft has no patch '" + n +
                                "'; its patches: " + list);
      }
  };
  for (const WallSpec& w : study.walls)
    checkPatches(w.patches, "line " + std::to_string(w.line) + ", walls");
  checkPatches(study.sizing.patches, "sizing.patches");

  // 1. Flux along the pass: the spacecraft moves, the hot material is the frame's.
  auto t0 = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < r.times.size(); ++i) {
    const double t = r.times[i];
    const Emitters& emitters = *frames[i].emitters;
    const TriangleMesh* occluder = frames[i].occluder;
    RadiationScene scene;
    scene.surfaces = buildRadiationScene(craft, t).surfaces;
    scene.emitters = emitters;
    if (occluder && !occluder->triangles.empty() && !emitters.empty())
      scene.occluder.mesh = *occluder;  // opaque, cold (T = 0)
    const ViewFactorSolver solver(std::move(scene));
    for (std::size_t p = 0; p < r.patches.size(); ++p) {
      PatchThermal& pt = r.patches[p];
      if (emitters.empty()) {
        pt.flux.push_back({});
        pt.seedFlux.push_back(0.0);
        if (occluded) pt.toOccluder.push_back({});
        continue;
      }
      const ReceiverResult rr = solver.fromPatch(p, study.sampling);
      r.rays += rr.rays;
      pt.flux.push_back(rr.flux);
      if (occluded) pt.toOccluder.push_back(rr.toOccluder);  // zero in a frame without one
      pt.seedFlux.push_back(seedBaseline(emitters, solver.scene().surfaces, p, study.baseline).flux);
    }
  }
  r.raySeconds = seconds(t0);

  // 2. Peaks and the steady face temperature (eq. 4.8).
  for (PatchThermal& pt : r.patches) {
    for (std::size_t i = 0; i < pt.flux.size(); ++i) {
      if (i == 0 || pt.flux[i].value > pt.peakFlux) {
        pt.peakFlux = pt.flux[i].value;
        pt.peakFluxError = pt.flux[i].standardError;
        pt.peakTime = r.times[i];
        if (!pt.toOccluder.empty()) pt.peakOccluderFactor = pt.toOccluder[i].value;
      }
      pt.peakSeedFlux = std::max(pt.peakSeedFlux, pt.seedFlux[i]);
    }
    const WallSpec* w = wallFor(study, pt.patch);
    // Without a wall, a black face (alpha = eps = 1) stands for the face's own optics.
    pt.absorptivity = 1.0;
    pt.emissivity = 1.0;
    if (w) {
      const WallMaterial& outer = w->layers.front().material;
      pt.absorptivity = w->absorptivity.value_or(outer.absorptivity);
      pt.emissivity = w->emissivity.value_or(outer.emissivity);
    }
    pt.steadyTemperature = pt.emissivity > 0.0
                               ? equilibriumTemperature(pt.peakFlux, pt.absorptivity, pt.emissivity)
                               : std::numeric_limits<double>::infinity();
    pt.seedSteadyTemperature = equilibriumTemperature(pt.peakSeedFlux, kSeedAluminiumAbsorptivity,
                                                      kSeedAluminiumEmissivity);
  }

  // 3. The transient wall of every patch that has one, through its flux history.
  const double dt = study.timeStep > 0.0 ? study.timeStep : study.approach.duration / 2000.0;
  t0 = std::chrono::steady_clock::now();
  for (PatchThermal& pt : r.patches) {
    const WallSpec* w = wallFor(study, pt.patch);
    if (!w) continue;
    std::vector<double> q;
    for (const Estimate& e : pt.flux) q.push_back(e.value);
    WallGrid grid{LayeredWall(w->layers)};
    WallBoundaries bc;
    bc.hot = FaceCondition::irradiated(uniformFlux(FluxSeries(r.times, q)), pt.absorptivity, pt.emissivity);
    bc.cold = coldFace(*w);
    CrankNicolsonWallSolver solver(grid, bc, study.initialTemperature);
    WallHistory history(grid);
    solver.run(study.approach.duration, dt, &history);
    for (std::size_t l = 0; l < grid.wall().layerCount(); ++l) {
      pt.layerPeak.push_back(history.peakTemperature(l));
      pt.layerMeltTime.push_back(history.meltTime(l));
    }
    pt.structureLimit = study.limit.temperatureFor(w->layers.back().material);
    pt.structureWithinLimit = pt.layerPeak.back() < pt.structureLimit;
    pt.wall.emplace(std::move(history));
  }
  r.wallSeconds = seconds(t0);

  // 4. Sizing: each candidate coating on the structural (last) layer, per patch.
  t0 = std::chrono::steady_clock::now();
  if (!study.sizing.coatings.empty()) {
    std::vector<WallMaterial> candidates;
    for (const std::string& c : study.sizing.coatings) candidates.push_back(wallMaterial(c));
    for (const std::string& c : study.sizing.coatings) r.totalAddedMass[wallMaterial(c).name] = 0.0;
    for (PatchThermal& pt : r.patches) {
      const WallSpec* w = wallFor(study, pt.patch);
      const auto& only = study.sizing.patches;
      if (!w || (!only.empty() && std::find(only.begin(), only.end(), pt.patch) == only.end())) continue;
      std::vector<double> q;
      for (const Estimate& e : pt.flux) q.push_back(e.value);
      ShieldSizingProblem p;
      p.structure = w->layers.back();
      p.hotFace = FaceCondition::irradiated(uniformFlux(FluxSeries(r.times, q)), 1.0, 0.0);
      p.useCoatingOptics = true;
      p.coldFace = coldFace(*w);
      p.initialTemperature = study.initialTemperature;
      p.duration = study.approach.duration;
      p.timeStep = dt;
      p.limit = study.limit;
      p.patchArea = pt.area;
      p.maxThickness = study.sizing.maxThickness;
      p.tolerance = study.sizing.tolerance;
      p.coatingCells = study.sizing.coatingCells;
      pt.sizing = sizeShield(p, candidates);
      for (const ShieldSizing& z : pt.sizing)
        r.totalAddedMass[z.material] += z.feasible ? z.addedMass : std::numeric_limits<double>::quiet_NaN();
    }
  }
  r.sizingSeconds = seconds(t0);
  return r;
}

std::string formatThermalFluxCsv(const ThermalResult& r) {
  std::string out = "time_s";
  for (const PatchThermal& p : r.patches) out += std::string(",") + p.patch + "_W_m2," + p.patch + "_se_W_m2";
  out += "\n";
  for (std::size_t i = 0; i < r.times.size(); ++i) {
    out += csvNum(r.times[i]);
    for (const PatchThermal& p : r.patches) {
      out += ',';
      out += csvNum(p.flux[i].value);
      out += ',';
      out += csvNum(p.flux[i].standardError);
    }
    out += "\n";
  }
  return out;
}

std::string formatThermalSizingCsv(const ThermalResult& r) {
  std::string out =
      "patch,area_m2,coating,feasible,thickness_m,added_mass_kg,structure_peak_K,coating_peak_K,"
      "coating_melts,limit_K,runs,note\n";
  for (const PatchThermal& p : r.patches)
    for (const ShieldSizing& z : p.sizing) {
      std::string note = z.note;
      std::replace(note.begin(), note.end(), '"', '\'');
      out += p.patch + "," + csvNum(p.area) + "," + z.material + "," + (z.feasible ? "1" : "0") + "," +
             csvNum(z.thickness) + "," + csvNum(z.addedMass) + "," + csvNum(z.structurePeak) + "," +
             csvNum(z.coatingPeak) + "," + (z.coatingMelts ? "1" : "0") + "," + csvNum(z.limit) + "," +
             std::to_string(z.runs) + ",\"" + note + "\"\n";
    }
  return out;
}

std::string formatThermalJson(const ThermalResult& r, const std::string& extra) {
  std::string o = "{\n  \"name\": " + jsonString(r.name) + ",\n  \"source\": " + jsonString(r.source) + ",\n";
  if (!extra.empty()) o += extra + ",\n";
  o += "  \"emitters\": " + std::to_string(r.emitterCount) +
       ",\n  \"occluder_triangles\": " + std::to_string(r.occluderTriangles) + ",\n  \"groups\": [";
  for (std::size_t g = 0; g < r.groupNames.size(); ++g) o += std::string(g ? ", " : "") + jsonString(r.groupNames[g]);
  o += "],\n  \"times_s\": [";
  for (std::size_t i = 0; i < r.times.size(); ++i) o += std::string(i ? ", " : "") + num(r.times[i]);
  o += "],\n  \"rays\": " + std::to_string(r.rays) + ",\n  \"seconds\": {\"rays\": " + num(r.raySeconds) +
       ", \"wall\": " + num(r.wallSeconds) + ", \"sizing\": " + num(r.sizingSeconds) + "},\n  \"patches\": [";
  for (std::size_t k = 0; k < r.patches.size(); ++k) {
    const PatchThermal& p = r.patches[k];
    o += std::string(k ? "," : "") + "\n    {\"patch\": " + jsonString(p.patch) + ", \"area_m2\": " + num(p.area) +
         ",\n     \"peak_flux_W_m2\": " + num(p.peakFlux) + ", \"peak_flux_se_W_m2\": " + num(p.peakFluxError) +
         ", \"peak_time_s\": " + num(p.peakTime) + ",\n     \"absorptivity\": " + num(p.absorptivity) +
         ", \"emissivity\": " + num(p.emissivity) + ", \"steady_temperature_K\": " + num(p.steadyTemperature) +
         ",\n     \"seed_baseline\": {\"peak_flux\": " + num(p.peakSeedFlux) +
         ", \"steady_temperature_K\": " + num(p.seedSteadyTemperature) + ", \"absorptivity\": " +
         num(kSeedAluminiumAbsorptivity) + ", \"emissivity\": " + num(kSeedAluminiumEmissivity) + "}";
    if (!p.toOccluder.empty()) o += ",\n     \"occluder_view_factor_at_peak\": " + num(p.peakOccluderFactor);
    if (p.wall) {
      o += ",\n     \"wall\": {\"layers\": [";
      const auto& layers = p.wall->wall().layers();
      for (std::size_t l = 0; l < layers.size(); ++l)
        o += std::string(l ? ", " : "") + "{\"material\": " + jsonString(layers[l].material.name) +
             ", \"thickness_m\": " + num(layers[l].thickness) + ", \"peak_K\": " + num(p.layerPeak[l]) +
             ", \"melting_point_K\": " + num(layers[l].material.meltingPoint) +
             ", \"melt_time_s\": " + num(p.layerMeltTime[l]) + "}";
      o += "], \"structure_limit_K\": " + num(p.structureLimit) +
           ", \"structure_within_limit\": " + (p.structureWithinLimit ? "true" : "false") + "}";
    }
    if (!p.sizing.empty()) {
      o += ",\n     \"sizing\": [";
      for (std::size_t z = 0; z < p.sizing.size(); ++z) {
        const ShieldSizing& s = p.sizing[z];
        o += std::string(z ? ", " : "") + "{\"coating\": " + jsonString(s.material) +
             ", \"feasible\": " + (s.feasible ? "true" : "false") + ", \"thickness_m\": " + num(s.thickness) +
             ", \"added_mass_kg\": " + num(s.addedMass) + ", \"structure_peak_K\": " + num(s.structurePeak) +
             ", \"coating_melts\": " + (s.coatingMelts ? "true" : "false") + "}";
      }
      o += "]";
    }
    o += "}";
  }
  o += "\n  ],\n  \"total_added_mass_kg\": {";
  bool first = true;
  for (const auto& [coating, mass] : r.totalAddedMass) {
    o += std::string(first ? "" : ", ") + jsonString(coating) + ": " + num(mass);
    first = false;
  }
  return o + "}\n}\n";
}

std::string formatThermalText(const ThermalResult& r) {
  std::string o = "thermal study '" + r.name + "' (" + r.source + "): " + std::to_string(r.emitterCount) +
                  " emitters, " +
                  (r.occluderTriangles ? "an occluder of " + std::to_string(r.occluderTriangles) + " triangles, " : "") +
                  std::to_string(r.times.size()) + " flux samples over " +
                  num(r.times.back()) + " s, " + std::to_string(r.rays) + " rays in " + num(r.raySeconds) + " s\n";
  char line[512];
  std::snprintf(line, sizeof line, "%-10s %10s %12s %10s %11s %12s %11s %9s\n", "patch", "area m2",
                "peak q W/m2", "+- se", "T_eq(4.8) K", "seed q", "seed T_eq K", "wall max K");
  o += line;
  for (const PatchThermal& p : r.patches) {
    double wallMax = 0.0;
    for (double t : p.layerPeak) wallMax = std::max(wallMax, t);
    std::snprintf(line, sizeof line, "%-10s %10.4g %12.5g %10.3g %11.5g %12.5g %11.5g %9.5g\n", p.patch.c_str(),
                  p.area, p.peakFlux, p.peakFluxError, p.steadyTemperature, p.peakSeedFlux,
                  p.seedSteadyTemperature, p.wall ? wallMax : std::nan(""));
    o += line;
  }
  if (!r.totalAddedMass.empty()) {
    o += "coating sizing (added mass over the sized patches):\n";
    for (const auto& [coating, mass] : r.totalAddedMass) {
      double thickest = 0.0;
      for (const PatchThermal& p : r.patches)
        for (const ShieldSizing& z : p.sizing)
          if (z.material == coating) thickest = std::max(thickest, z.feasible ? z.thickness : std::nan(""));
      std::snprintf(line, sizeof line, "  %-18s thickest %10.4g mm   added %10.4g kg\n", coating.c_str(),
                    thickest * 1e3, mass);
      o += line;
    }
  }
  return o;
}

}  // namespace ejecta::radiation
