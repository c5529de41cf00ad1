// Scene files: TOML parsed by toml++, overrides applied to the tree, then every key checked
// against the schema below and converted to SI. Messages follow "FILE:LINE: key 'a.b': reason".
#include "sim/setup/scene.hpp"

#include <cctype>
#include <toml++/toml.h>

#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <utility>

#include "core/json.hpp"
#include "core/units.hpp"
#include "sim/eos/eos_catalog.hpp"
#include "sim/state/particle_fields.hpp"

namespace ejecta {

namespace {

using KeyList = std::vector<std::string_view>;

// The schema: allowed keys of every table, by schema path ("bodies[]" = any element).
const std::map<std::string_view, KeyList>& schemaTables() {
  static const std::map<std::string_view, KeyList> tables = [] {
    const KeyList axis{"min", "max", "boundary", "lower", "upper"};
    return std::map<std::string_view, KeyList>{
        {"",
         {"scene", "domain", "sph", "time", "output", "fields", "crater", "materials", "bodies",
          "energy_deposits", "detonations", "gauges", "images", "thermal"}},
        {"scene", {"name", "description", "dimension"}},
        {"domain", {"x", "y", "z"}},
        {"domain.x", axis},
        {"domain.y", axis},
        {"domain.z", axis},
        {"sph",
         {"kernel", "density", "smoothing_length", "eta", "relaxation", "courant", "force_factor",
          "h_min_factor", "viscosity", "conductivity", "form", "artificial_stress"}},
        {"sph.viscosity", {"alpha", "beta", "epsilon", "balsara", "switch", "alpha_min", "decay",
                            "reconstruction"}},
        {"sph.conductivity", {"alpha"}},
        {"sph.artificial_stress", {"epsilon", "n"}},
        {"time", {"t_end", "dt_max", "dt_min", "max_steps"}},
        {"output", {"snapshot_interval", "snapshots"}},
        {"fields",
         {"grids", "voxel", "normalise", "every", "level_set", "extrude", "region_min",
          "region_max"}},
        {"crater", {"enabled", "materials", "resolution"}},
        {"materials[]",
         {"name", "eos", "gamma", "library", "parameters", "thermal", "strength", "fracture"}},
        {"materials[].parameters", {"*"}},  // keys depend on the eos: checked in readMaterials
        {"materials[].thermal",
         {"library", "specific_heat", "mean_atomic_mass", "molar_mass", "initial_temperature",
          "melt_temperature"}},
        {"materials[].strength",
         {"model", "library", "shear_modulus", "yield_stress", "A", "B", "n", "C", "m",
          "reference_strain_rate", "room_temperature", "cohesion", "friction_intact",
          "strength_limit", "friction_damaged", "cohesion_damaged"}},
        {"materials[].fracture",
         {"model", "weibull_k", "weibull_m", "tensile_strength", "erosion_strain",
          "crack_speed_factor", "max_crack_increment", "seed"}},
        {"bodies[]",
         {"name", "material", "shape", "min", "max", "center", "radius", "inner_radius",
          "outer_radius", "point", "normal", "lattice", "spacing", "density", "pressure",
          "internal_energy", "velocity", "damage", "void", "depth"}},
        {"energy_deposits[]",
         {"name", "energy", "body", "center", "radius", "profile", "width", "time"}},
        {"detonations[]", {"name", "material", "point", "line_to", "time", "velocity"}},
        {"gauges[]", {"name", "position"}},
        {"images", {"fields", "log", "every", "size", "cut", "cut_at", "camera", "grids", "surface"}},
        {"images.camera", {"position", "target", "up", "fov_degrees"}},
        {"thermal", {"study", "times", "hot_material"}},
    };
  }();
  return tables;
}

const KeyList* allowedKeys(std::string_view schemaPath) {
  const auto& tables = schemaTables();
  const auto it = tables.find(schemaPath);
  return it == tables.end() ? nullptr : &it->second;
}

bool contains(const KeyList& keys, std::string_view k) {
  for (std::string_view a : keys)
    if (a == k || a == "*") return true;
  return false;
}

std::string joinKeys(const KeyList& keys) {
  std::string out;
  for (std::string_view k : keys) out += (out.empty() ? "" : ", ") + std::string(k);
  return out;
}

std::string typeName(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a floating-point number";
    case toml::node_type::boolean: return "a boolean";
    default: return "a date/time";
  }
}

// Enum spellings in scene files.
template <typename E>
using EnumNames = std::vector<std::pair<std::string_view, E>>;

template <typename E>
std::string enumList(const EnumNames<E>& names) {
  std::string out;
  for (const auto& [name, value] : names)
    out += (out.empty() ? "'" : ", '") + std::string(name) + "'";
  return out;
}

// Where messages point. Values set by --set carry their own source name (see applyOverride).
class Context {
 public:
  Context(std::string sourceName, const toml::table& root)
      : source_(std::move(sourceName)), root_(&root) {}
  const std::string& source() const { return source_; }

  std::string where(const toml::node* n) const {
    if (n && n != root_) {
      const auto& src = n->source();
      if (src.path && *src.path != source_) return source_ + ": " + *src.path;
      if (src.begin.line > 0) return source_ + ":" + std::to_string(src.begin.line);
    }
    return source_ + ":1";  // the document itself (e.g. a missing top-level table)
  }

  [[noreturn]] void fail(const toml::node* at, std::string_view key,
                         const std::string& reason) const {
    throw SceneError(where(at) + ": key '" + std::string(key) + "': " + reason);
  }

 private:
  std::string source_;
  const toml::table* root_;
};

// Typed, checked access to one table of the scene. Unknown keys are rejected on construction.
class TableReader {
 public:
  TableReader(const Context& ctx, const toml::table& tbl, std::string path, std::string schema)
      : ctx_(ctx), tbl_(tbl), path_(std::move(path)) {
    const KeyList* allowed = allowedKeys(schema);
    for (auto&& [k, v] : tbl_) {
      if (!allowed || !contains(*allowed, k.str()))
        ctx_.fail(&v, key(k.str()),
                  "unknown key; allowed keys here: " + (allowed ? joinKeys(*allowed) : "none"));
    }
  }

  const toml::table& table() const { return tbl_; }
  std::string key(std::string_view k) const {
    return path_.empty() ? std::string(k) : path_ + "." + std::string(k);
  }
  const toml::node* find(std::string_view k) const { return tbl_.get(k); }
  bool has(std::string_view k) const { return find(k) != nullptr; }

  [[noreturn]] void fail(std::string_view k, const std::string& reason) const {
    const toml::node* n = find(k);
    ctx_.fail(n ? n : &tbl_, key(k), reason);
  }
  void check(bool ok, std::string_view k, const std::string& reason) const {
    if (!ok) fail(k, reason);
  }
  const toml::node& require(std::string_view k) const {
    const toml::node* n = find(k);
    if (!n) ctx_.fail(&tbl_, key(k), "required key is missing");
    return *n;
  }

  std::optional<std::string> optString(std::string_view k) const {
    const toml::node* n = find(k);
    if (!n) return std::nullopt;
    if (!n->is_string()) fail(k, "expected a string, got " + typeName(*n));
    return n->value<std::string>();
  }
  std::string requireString(std::string_view k) const {
    require(k);
    return *optString(k);
  }

  std::optional<bool> optBool(std::string_view k) const {
    const toml::node* n = find(k);
    if (!n) return std::nullopt;
    if (!n->is_boolean()) fail(k, "expected true or false, got " + typeName(*n));
    return n->value<bool>();
  }

  std::optional<long> optInteger(std::string_view k) const {
    const toml::node* n = find(k);
    if (!n) return std::nullopt;
    if (!n->is_integer()) fail(k, "expected an integer, got " + typeName(*n));
    return static_cast<long>(*n->value<std::int64_t>());
  }

  // A number (SI) or a quantity string ("10 km/s") of dimension `dim`.
  double quantityOf(const toml::node& n, const std::string& fullKey, Dimension dim) const {
    if (n.is_integer() || n.is_floating_point()) {
      const double x = *n.value<double>();
      if (!std::isfinite(x)) ctx_.fail(&n, fullKey, "must be finite");
      return x;
    }
    if (n.is_string()) {
      try {
        return parseQuantity(*n.value<std::string>(), dim);
      } catch (const UnitError& e) {
        ctx_.fail(&n, fullKey, e.what());
      }
    }
    const std::string unit = siUnit(dim);
    ctx_.fail(&n, fullKey,
              "expected " + describeDimension(dim) + " as a number" +
                  (unit.empty() ? "" : " (SI) or a string such as \"1 " + unit + "\"") + ", got " +
                  typeName(n));
  }
  std::optional<double> optQuantity(std::string_view k, Dimension dim) const {
    const toml::node* n = find(k);
    if (!n) return std::nullopt;
    return quantityOf(*n, key(k), dim);
  }
  double requireQuantity(std::string_view k, Dimension dim) const {
    return quantityOf(require(k), key(k), dim);
  }

  // A vector with exactly `n` components (the scene's dimension); unused components are 0.
  std::optional<std::array<double, 3>> optVector(std::string_view k, Dimension dim, int n,
                                                 std::string_view layout) const {
    const toml::node* node = find(k);
    if (!node) return std::nullopt;
    const toml::array* arr = node->as_array();
    if (!arr) fail(k, "expected an array " + std::string(layout) + ", got " + typeName(*node));
    if (static_cast<int>(arr->size()) != n)
      fail(k, "expected " + std::to_string(n) + " component" + (n == 1 ? "" : "s") + " " +
                  std::string(layout) + ", got " + std::to_string(arr->size()));
    std::array<double, 3> out{};
    for (int i = 0; i < n; ++i)
      out[i] = quantityOf(*arr->get(static_cast<std::size_t>(i)),
                          key(k) + "[" + std::to_string(i) + "]", dim);
    return out;
  }

  std::optional<std::vector<std::string>> optStringArray(std::string_view k) const {
    const toml::node* node = find(k);
    if (!node) return std::nullopt;
    const toml::array* arr = node->as_array();
    if (!arr) fail(k, "expected an array of strings, got " + typeName(*node));
    std::vector<std::string> out;
    for (std::size_t i = 0; i < arr->size(); ++i) {
      const toml::node* e = arr->get(i);
      if (!e->is_string())
        ctx_.fail(e, key(k) + "[" + std::to_string(i) + "]", "expected a string, got " + typeName(*e));
      out.push_back(*e->value<std::string>());
    }
    return out;
  }

  template <typename E>
  std::optional<E> optEnum(std::string_view k, const EnumNames<E>& names) const {
    const std::optional<std::string> text = optString(k);
    if (!text) return std::nullopt;
    for (const auto& [name, value] : names)
      if (name == *text) return value;
    fail(k, "unknown value '" + *text + "'; allowed: " + enumList(names));
  }

  const toml::table* optTable(std::string_view k) const {
    const toml::node* n = find(k);
    if (!n) return nullptr;
    if (!n->is_table()) fail(k, "expected a table, got " + typeName(*n));
    return n->as_table();
  }

  // An array of tables ([[k]]); each element is returned with its index.
  std::vector<const toml::table*> tableArray(std::string_view k) const {
    std::vector<const toml::table*> out;
    const toml::node* n = find(k);
    if (!n) return out;
    const toml::array* arr = n->as_array();
    if (!arr)
      fail(k, "expected an array of tables ([[" + std::string(k) + "]]), got " + typeName(*n));
    for (std::size_t i = 0; i < arr->size(); ++i) {
      const toml::node* e = arr->get(i);
      if (!e->is_table())
        ctx_.fail(e, key(k) + "[" + std::to_string(i) + "]",
                  "expected a table, got " + typeName(*e));
      out.push_back(e->as_table());
    }
    return out;
  }

  const Context& context() const { return ctx_; }

 private:
  const Context& ctx_;
  const toml::table& tbl_;
  std::string path_;
};

std::string positiveMessage(double v, Dimension d) {
  return "must be positive (got " + formatQuantity(v, d) + ")";
}
std::string nonNegativeMessage(double v, Dimension d) {
  return "must not be negative (got " + formatQuantity(v, d) + ")";
}

// ---------------------------------------------------------------------------------------------
// --set overrides

struct PathPart {
  std::string key;                   // empty for an index
  std::optional<std::size_t> index;  // "[i]"
};

std::vector<PathPart> splitKeyPath(std::string_view path) {
  std::vector<PathPart> parts;
  std::size_t pos = 0;
  while (pos < path.size()) {
    if (path[pos] == '[') {
      const std::size_t close = path.find(']', pos);
      if (close == std::string_view::npos || close == pos + 1 || close > pos + 9 || parts.empty())
        return {};
      std::size_t idx = 0;
      for (std::size_t i = pos + 1; i < close; ++i) {
        if (path[i] < '0' || path[i] > '9') return {};
        idx = idx * 10 + static_cast<std::size_t>(path[i] - '0');
      }
      parts.push_back({"", idx});
      pos = close + 1;
      if (pos < path.size() && path[pos] == '.') ++pos;
      continue;
    }
    std::size_t end = pos;
    while (end < path.size() && path[end] != '.' && path[end] != '[') ++end;
    if (end == pos) return {};
    parts.push_back({std::string(path.substr(pos, end - pos)), std::nullopt});
    pos = end;
    if (pos < path.size() && path[pos] == '.') {
      ++pos;
      if (pos == path.size()) return {};
    }
  }
  return parts;
}

std::string trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return std::string(s);
}

// The override's value as a TOML node if the text is a TOML value, else as a string. Parsing
// with `label` as the source path makes every message about this value name the --set.
toml::table parseOverrideValue(const std::string& text, const std::string& label) {
  try {
    toml::table doc = toml::parse("v = " + text, label);
    if (doc.size() == 1 && doc.contains("v")) return doc;
  } catch (const toml::parse_error&) {
    // not a TOML value: fall through to a string
  }
  // A JSON string literal is a TOML basic string too (the same escapes: \" \\ \n \uXXXX).
  return toml::parse("v = " + jsonString(text), label);
}

void applyOverride(toml::table& root, const std::string& text, const std::string& sourceName) {
  const std::string label = "--set '" + text + "'";
  auto bad = [&](const std::string& reason) -> SceneError {
    return SceneError(sourceName + ": " + label + ": " + reason);
  };
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos) throw bad("expected KEY=VALUE");
  const std::string keyPath = trimmed(std::string_view(text).substr(0, eq));
  const std::vector<PathPart> parts = splitKeyPath(keyPath);
  if (parts.empty())
    throw bad("malformed key '" + keyPath + "' (use e.g. sph.kernel or bodies[0].spacing)");
  toml::table valueDoc = parseOverrideValue(trimmed(std::string_view(text).substr(eq + 1)), label);
  toml::node& value = *valueDoc.get("v");

  toml::node* cur = &root;
  std::string schema;  // schema path of `cur`
  std::string dotted;  // key path of `cur`, for messages
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const PathPart& part = parts[i];
    const bool last = (i + 1 == parts.size());
    if (part.index) {
      toml::array* arr = cur->as_array();
      if (!arr) throw bad("key '" + dotted + "' is not an array");
      if (*part.index >= arr->size())
        throw bad("key '" + dotted + "' has " + std::to_string(arr->size()) +
                  " element(s); no index " + std::to_string(*part.index));
      dotted += "[" + std::to_string(*part.index) + "]";
      if (allowedKeys(schema + "[]")) schema += "[]";
      if (last) {
        arr->replace(arr->cbegin() + static_cast<std::ptrdiff_t>(*part.index), std::move(value));
        return;
      }
      cur = arr->get(*part.index);
      continue;
    }
    const KeyList* allowed = allowedKeys(schema);
    const std::string childKey = dotted.empty() ? part.key : dotted + "." + part.key;
    if (!allowed) throw bad("key '" + dotted + "' has no sub-keys");
    if (!contains(*allowed, part.key))
      throw bad("unknown key '" + childKey + "'; allowed keys " +
                (dotted.empty() ? std::string("at the top level") : "in '" + dotted + "'") + ": " +
                joinKeys(*allowed));
    toml::table* tbl = cur->as_table();
    if (!tbl) throw bad("key '" + dotted + "' is not a table");
    const std::string childSchema = schema.empty() ? part.key : schema + "." + part.key;
    if (last) {
      tbl->insert_or_assign(part.key, std::move(value));
      return;
    }
    if (!tbl->contains(part.key)) {
      if (!allowedKeys(childSchema)) throw bad("key '" + childKey + "' does not exist");
      // Parsed rather than constructed so that the new table's source names this --set.
      toml::table empty = toml::parse("t = {}", label);
      tbl->insert_or_assign(part.key, std::move(*empty.get("t")));
    }
    cur = tbl->get(part.key);
    schema = childSchema;
    dotted = childKey;
  }
}

// ---------------------------------------------------------------------------------------------
// Sections

const EnumNames<BoundaryKind> kBoundaryNames{{"open", BoundaryKind::Open},
                                             {"periodic", BoundaryKind::Periodic},
                                             {"wall", BoundaryKind::Wall}};

void readScene(const TableReader& root, Scene& scene) {
  const toml::table* t = root.optTable("scene");
  if (!t) root.fail("scene", "required table [scene] is missing");
  const TableReader r(root.context(), *t, "scene", "scene");
  scene.name = r.requireString("name");
  r.check(!scene.name.empty(), "name", "must not be empty");
  scene.description = r.optString("description").value_or("");
  const std::string dim = r.requireString("dimension");
  if (!parseGeometry(dim, scene.geometry))
    r.fail("dimension", "unknown value '" + dim + "'; allowed: '1d', '2d', 'rz', '3d'");
}

void readAxis(const TableReader& domain, int axis, Geometry geometry, AxisBounds& out) {
  static constexpr std::string_view kAxisNames[3] = {"x", "y", "z"};
  const std::string_view name = kAxisNames[axis];
  const toml::table* t = domain.optTable(name);
  if (!t) return;  // unbounded and open
  const int dim = spatialDimension(geometry);
  if (axis >= dim)
    domain.fail(name, "axis not used in a " + std::string(geometryName(geometry)) +
                          " scene (allowed: " + (dim == 1 ? "x" : "x, y") + ")");
  const bool rAxis = (geometry == Geometry::Axisymmetric && axis == 0);
  const TableReader r(domain.context(), *t, domain.key(name), "domain." + std::string(name));

  out.min = r.requireQuantity("min", Dimension::Length);
  out.max = r.requireQuantity("max", Dimension::Length);
  r.check(out.min < out.max, "max",
          "max must exceed min (got min " + formatQuantity(out.min, Dimension::Length) + ", max " +
              formatQuantity(out.max, Dimension::Length) + ")");
  if (r.has("boundary") && (r.has("lower") || r.has("upper")))
    r.fail("boundary", "give either 'boundary' or 'lower'/'upper', not both");

  if (rAxis) {
    r.check(out.min == 0.0, "min", "must be 0 in an rz scene (r starts at the axis)");
    if (const auto lower = r.optString("lower"))
      r.check(*lower == "axis", "lower",
              "the lower r boundary is the axis; write 'axis' or omit it");
    const std::string_view side = r.has("boundary") ? "boundary" : "upper";
    out.upper = r.optEnum(side, kBoundaryNames).value_or(BoundaryKind::Open);
    r.check(out.upper != BoundaryKind::Periodic, side, "r cannot be periodic (r = 0 is the axis)");
    out.lower = BoundaryKind::Wall;  // the axis: mirror images, as at a wall
  } else {
    const auto both = r.optEnum("boundary", kBoundaryNames);
    out.lower = both ? *both : r.optEnum("lower", kBoundaryNames).value_or(BoundaryKind::Open);
    out.upper = both ? *both : r.optEnum("upper", kBoundaryNames).value_or(BoundaryKind::Open);
    if ((out.lower == BoundaryKind::Periodic) != (out.upper == BoundaryKind::Periodic))
      r.fail(r.has("upper") ? "upper" : "lower", "periodic must be on both sides");
  }
  out.bounded = true;
}

void readDomain(const TableReader& root, Scene& scene) {
  const toml::table* t = root.optTable("domain");
  if (!t) return;
  const TableReader r(root.context(), *t, "domain", "domain");
  for (int axis = 0; axis < 3; ++axis) readAxis(r, axis, scene.geometry, scene.domain[axis]);
}

void readSph(const TableReader& root, SphOptions& sph) {
  const toml::table* t = root.optTable("sph");
  if (!t) return;
  const TableReader r(root.context(), *t, "sph", "sph");
  const Dimension one = Dimension::None;
  sph.kernel = r.optEnum<KernelKind>("kernel", {{"cubic_spline", KernelKind::CubicSpline},
                                                {"wendland_c2", KernelKind::WendlandC2},
                                                {"wendland_c4", KernelKind::WendlandC4}})
                   .value_or(sph.kernel);
  sph.density = r.optEnum<DensityMethod>("density", {{"summation", DensityMethod::Summation},
                                                     {"continuity", DensityMethod::Continuity}})
                    .value_or(sph.density);
  sph.smoothingLength = r.optEnum<SmoothingLengthMethod>(
                             "smoothing_length", {{"neighbours", SmoothingLengthMethod::Neighbours},
                                                  {"seed", SmoothingLengthMethod::Seed},
                                                  {"constant", SmoothingLengthMethod::Constant}})
                            .value_or(sph.smoothingLength);
  sph.eta = r.optQuantity("eta", one).value_or(sph.eta);
  r.check(sph.eta > 0.0, "eta", positiveMessage(sph.eta, one));
  sph.relaxation = r.optQuantity("relaxation", one).value_or(sph.relaxation);
  r.check(sph.relaxation > 0.0 && sph.relaxation <= 1.0, "relaxation", "must be in (0, 1]");
  sph.courant = r.optQuantity("courant", one).value_or(sph.courant);
  r.check(sph.courant > 0.0 && sph.courant <= 1.0, "courant", "must be in (0, 1]");
  sph.forceFactor = r.optQuantity("force_factor", one).value_or(sph.forceFactor);
  r.check(sph.forceFactor > 0.0, "force_factor", positiveMessage(sph.forceFactor, one));
  sph.hMinFactor = r.optQuantity("h_min_factor", one).value_or(sph.hMinFactor);
  r.check(sph.hMinFactor >= 0.0 && sph.hMinFactor < 1.0, "h_min_factor", "must be in [0, 1)");

  if (const toml::table* vt = r.optTable("viscosity")) {
    const TableReader v(root.context(), *vt, "sph.viscosity", "sph.viscosity");
    sph.alpha = v.optQuantity("alpha", one).value_or(sph.alpha);
    v.check(sph.alpha >= 0.0, "alpha", nonNegativeMessage(sph.alpha, one));
    sph.beta = v.optQuantity("beta", one).value_or(sph.beta);
    v.check(sph.beta >= 0.0, "beta", nonNegativeMessage(sph.beta, one));
    sph.epsilon = v.optQuantity("epsilon", one).value_or(sph.epsilon);
    v.check(sph.epsilon > 0.0, "epsilon",
            positiveMessage(sph.epsilon, one) + "; it keeps the viscosity finite as r -> 0");
    sph.balsara = v.optBool("balsara").value_or(sph.balsara);
    sph.viscositySwitch = v.optEnum<ViscositySwitch>(
                               "switch", {{"none", ViscositySwitch::None},
                                          {"morris_monaghan", ViscositySwitch::MorrisMonaghan}})
                              .value_or(sph.viscositySwitch);
    sph.alphaMin = v.optQuantity("alpha_min", one).value_or(sph.alphaMin);
    v.check(sph.alphaMin >= 0.0, "alpha_min", nonNegativeMessage(sph.alphaMin, one));
    v.check(sph.viscositySwitch == ViscositySwitch::None || sph.alphaMin <= sph.alpha,
            "alpha_min", "must not exceed alpha (the switch keeps alpha_i between them)");
    sph.alphaDecay = v.optQuantity("decay", one).value_or(sph.alphaDecay);
    v.check(sph.alphaDecay > 0.0, "decay",
            positiveMessage(sph.alphaDecay, one) + "; alpha decays over h / (decay c)");
    sph.viscosityReconstruction =
        v.optEnum<ViscosityReconstruction>(
             "reconstruction", {{"none", ViscosityReconstruction::None},
                                {"van_leer", ViscosityReconstruction::VanLeer},
                                {"monotone", ViscosityReconstruction::Monotone}})
            .value_or(sph.viscosityReconstruction);
  }
  if (const toml::table* ct = r.optTable("conductivity")) {
    const TableReader c(root.context(), *ct, "sph.conductivity", "sph.conductivity");
    sph.conductivity = c.optQuantity("alpha", one).value_or(sph.conductivity);
    c.check(sph.conductivity >= 0.0, "alpha", nonNegativeMessage(sph.conductivity, one));
  }
  sph.form = r.optEnum<MomentumForm>("form", {{"lagrangian", MomentumForm::Lagrangian},
                                              {"interface", MomentumForm::Interface}})
                 .value_or(sph.form);
  if (const toml::table* at = r.optTable("artificial_stress")) {
    const TableReader a(root.context(), *at, "sph.artificial_stress", "sph.artificial_stress");
    sph.artificialStress = a.optQuantity("epsilon", one).value_or(sph.artificialStress);
    a.check(sph.artificialStress >= 0.0, "epsilon",
            nonNegativeMessage(sph.artificialStress, one) + " (0 switches it off)");
    sph.artificialStressExponent = a.optQuantity("n", one).value_or(sph.artificialStressExponent);
    a.check(sph.artificialStressExponent > 0.0, "n",
            positiveMessage(sph.artificialStressExponent, one));
  }
}

void readTime(const TableReader& root, TimeOptions& time) {
  const toml::table* t = root.optTable("time");
  if (!t) root.fail("time", "required table [time] is missing (it must give t_end)");
  const TableReader r(root.context(), *t, "time", "time");
  const Dimension s = Dimension::Time;
  time.tEnd = r.requireQuantity("t_end", s);
  r.check(time.tEnd > 0.0, "t_end", positiveMessage(time.tEnd, s));
  time.dtMax = r.optQuantity("dt_max", s).value_or(time.dtMax);
  r.check(time.dtMax >= 0.0, "dt_max", nonNegativeMessage(time.dtMax, s) + "; 0 = unlimited");
  time.dtMin = r.optQuantity("dt_min", s).value_or(time.dtMin);
  r.check(time.dtMin >= 0.0, "dt_min", nonNegativeMessage(time.dtMin, s));
  if (time.dtMax > 0.0) r.check(time.dtMin < time.dtMax, "dt_min", "must be below dt_max");
  time.maxSteps = r.optInteger("max_steps").value_or(time.maxSteps);
  r.check(time.maxSteps >= 0, "max_steps", "must not be negative; 0 = unlimited");
}

void readOutput(const TableReader& root, OutputOptions& out) {
  const toml::table* t = root.optTable("output");
  if (!t) return;
  const TableReader r(root.context(), *t, "output", "output");
  out.snapshotInterval = r.optQuantity("snapshot_interval", Dimension::Time).value_or(0.0);
  r.check(out.snapshotInterval >= 0.0, "snapshot_interval",
          nonNegativeMessage(out.snapshotInterval, Dimension::Time) + "; 0 = first and last only");
  out.snapshots = r.optBool("snapshots").value_or(out.snapshots);
}

// A grid name of [fields]: a particle field, "fractions", or "fraction_<material>".
void checkGridName(const TableReader& r, const Scene& scene, const std::string& name) {
  if (findParticleScalarField(name) || name == "fractions") return;
  const std::string prefix = "fraction_";
  if (name.rfind(prefix, 0) == 0) {
    for (const MaterialSpec& m : scene.materials)
      if (m.name == name.substr(prefix.size())) return;
    r.fail("grids", "'" + name + "': no material named '" + name.substr(prefix.size()) + "'");
  }
  r.fail("grids", "unknown grid '" + name + "'; allowed: " + particleScalarFieldList() +
                      ", 'fractions', 'fraction_<material>'");
}

// [fields] and [crater] come after the materials: their names are checked against them.
void readFields(const TableReader& root, Scene& scene) {
  const toml::table* t = root.optTable("fields");
  if (!t) return;
  const TableReader r(root.context(), *t, "fields", "fields");
  FieldsOutputOptions& f = scene.fields;
  f.enabled = true;
  if (auto grids = r.optStringArray("grids")) {
    r.check(!grids->empty(), "grids", "must name at least one grid");
    for (const std::string& g : *grids) checkGridName(r, scene, g);
    f.grids = *grids;
  }
  const Dimension m = Dimension::Length;
  f.voxel = r.optQuantity("voxel", m).value_or(0.0);
  r.check(f.voxel >= 0.0, "voxel", nonNegativeMessage(f.voxel, m) + "; 0 = the median h");
  static const EnumNames<FieldNormalisation> kNorm{{"auto", FieldNormalisation::Auto},
                                                   {"shepard", FieldNormalisation::Shepard},
                                                   {"none", FieldNormalisation::None}};
  f.normalise = r.optEnum("normalise", kNorm).value_or(f.normalise);
  f.every = static_cast<int>(r.optInteger("every").value_or(1));
  r.check(f.every >= 1, "every", "must be at least 1 (every Nth snapshot)");
  f.levelSet = r.optBool("level_set").value_or(true);
  f.extrude = r.optQuantity("extrude", m).value_or(0.0);
  r.check(f.extrude >= 0.0, "extrude", nonNegativeMessage(f.extrude, m));
  r.check(f.extrude == 0.0 || scene.geometry == Geometry::Planar, "extrude",
          "only 2D planar runs are extruded");
  const auto lo = r.optVector("region_min", m, 3, "[x, y, z] (RZ grids: revolved about y)");
  const auto hi = r.optVector("region_max", m, 3, "[x, y, z] (RZ grids: revolved about y)");
  r.check(lo.has_value() == hi.has_value(), lo ? "region_max" : "region_min",
          "give both region_min and region_max");
  if (lo) {
    f.clip = true;
    f.regionMin = *lo;
    f.regionMax = *hi;
    for (int d = 0; d < 3; ++d)
      r.check(f.regionMax[d] > f.regionMin[d], "region_max", "must exceed region_min in every component");
  }
}

void readCrater(const TableReader& root, Scene& scene) {
  const toml::table* t = root.optTable("crater");
  if (!t) return;
  const TableReader r(root.context(), *t, "crater", "crater");
  CraterAnalysisOptions& c = scene.crater;
  c.enabled = r.optBool("enabled").value_or(true);
  if (auto names = r.optStringArray("materials")) {
    for (const std::string& n : *names) {
      bool known = false;
      for (const MaterialSpec& m : scene.materials) known = known || m.name == n;
      r.check(known, "materials", "no material named '" + n + "'");
    }
    c.materials = *names;
  }
  c.resolution = r.optQuantity("resolution", Dimension::Length).value_or(0.0);
  r.check(c.resolution >= 0.0, "resolution",
          nonNegativeMessage(c.resolution, Dimension::Length) + "; 0 = half the median h");
}

// [images] grids and surface: pictures of the grid files [fields] writes, so the names must be
// grids it writes (docs/fields.md): its grids with "fractions" spelled out, and with the level
// set, "surface" and "surface_<material>".
void readGridImages(const TableReader& r, Scene& scene) {
  ImageOutputOptions& im = scene.images;
  const FieldsOutputOptions& f = scene.fields;
  const bool grids = f.enabled && scene.geometry != Geometry::Line;
  if (auto names = r.optStringArray("grids")) {
    r.check(grids, "grids", scene.geometry == Geometry::Line
                                ? "1D runs write no grids"
                                : "needs a [fields] table: the pictures are of the grid files it writes");
    std::vector<std::string> written;
    for (const std::string& g : f.grids) {
      if (g != "fractions") written.push_back(g);
      else
        for (const MaterialSpec& m : scene.materials) written.push_back("fraction_" + m.name);
    }
    if (f.levelSet) {
      written.push_back("surface");
      for (const MaterialSpec& m : scene.materials) written.push_back("surface_" + m.name);
    }
    std::string list;
    for (const std::string& w : written) list += (list.empty() ? "" : ", ") + w;
    for (const std::string& n : *names) {
      bool known = false;
      for (const std::string& w : written) known = known || w == n;
      r.check(known, "grids", "'" + n + "' is not a grid the run writes (" + list + ")");
    }
    im.grids = *names;
  }
  im.surface = r.optBool("surface").value_or(false);
  if (im.surface) {
    r.check(grids && f.levelSet, "surface",
            "needs a [fields] table with level_set = true: the picture is of its surface level set");
    r.check(scene.geometry != Geometry::Planar || f.extrude > 0.0, "surface",
            "a 2D planar run has a surface level set only when [fields] extrude is set");
  }
}

// [images.camera]: a camera the renderer can use (render/view_transform.hpp would reject the
// same, later and without the key's name).
void readImageCamera(const TableReader& r, ImageOutputOptions& im) {
  ImageCamera c;
  const char* layout = "[x, y, z]";
  auto point = [&](const char* k) {
    r.require(k);
    return *r.optVector(k, Dimension::Length, 3, layout);
  };
  c.position = point("position");
  c.target = point("target");
  c.up = r.optVector("up", Dimension::None, 3, layout).value_or(c.up);
  c.fovDegrees = r.optQuantity("fov_degrees", Dimension::None).value_or(c.fovDegrees);
  r.check(c.fovDegrees > 0.0 && c.fovDegrees < 180.0, "fov_degrees", "must be between 0 and 180");
  const std::array<double, 3> sight{c.target[0] - c.position[0], c.target[1] - c.position[1],
                                    c.target[2] - c.position[2]};
  const double distance = std::hypot(sight[0], sight[1], sight[2]);
  r.check(distance > 0.0, "target", "is the camera's position: the camera must look somewhere");
  const double upLength = std::hypot(c.up[0], c.up[1], c.up[2]);
  const std::array<double, 3> side{sight[1] * c.up[2] - sight[2] * c.up[1],
                                   sight[2] * c.up[0] - sight[0] * c.up[2],
                                   sight[0] * c.up[1] - sight[1] * c.up[0]};
  r.check(upLength > 0.0 && std::hypot(side[0], side[1], side[2]) > 1e-6 * distance * upLength,
          "up", "must not be zero or along the line of sight (position -> target)");
  im.camera = c;
}

void readImages(const TableReader& root, Scene& scene) {
  const toml::table* t = root.optTable("images");
  if (!t) return;
  const TableReader r(root.context(), *t, "images", "images");
  ImageOutputOptions& im = scene.images;
  im.enabled = true;
  auto checkFields = [&](const char* key, const std::vector<std::string>& names) {
    for (const std::string& n : names)
      r.check(findParticleScalarField(n) != nullptr, key,
              "no particle field '" + n + "' (known: " + particleScalarFieldList() + ")");
  };
  if (auto f = r.optStringArray("fields")) {
    checkFields("fields", *f);
    // No particle pictures is fine when the table asks for pictures of the grids.
    r.check(!f->empty() || t->contains("grids") || t->contains("surface"), "fields", "give at least one field");
    im.fields = *f;
  }
  if (auto l = r.optStringArray("log")) {
    checkFields("log", *l);
    im.log = *l;
  }
  im.every = static_cast<int>(r.optInteger("every").value_or(1));
  r.check(im.every >= 1, "every", "must be at least 1");
  im.size = static_cast<int>(r.optInteger("size").value_or(1024));
  r.check(im.size >= 64 && im.size <= 8192, "size", "must be 64 to 8192 pixels");
  im.cut = r.optString("cut").value_or("z");
  r.check(im.cut == "none" || im.cut == "x" || im.cut == "y" || im.cut == "z", "cut",
          "expected \"none\", \"x\", \"y\" or \"z\"");
  if (auto at = r.optQuantity("cut_at", Dimension::Length)) {
    r.check(spatialDimension(scene.geometry) == 3 && im.cut != "none", "cut_at",
            "moves the cut of a 3D picture; this scene has none (cut = \"" + im.cut + "\", " +
                std::to_string(spatialDimension(scene.geometry)) + "D)");
    im.cutAt = *at;
  }
  if (const toml::table* c = r.optTable("camera")) {
    r.check(spatialDimension(scene.geometry) == 3, "camera",
            "only 3D pictures have a camera; 2D and RZ pictures are orthographic sections");
    readImageCamera(TableReader(root.context(), *c, "images.camera", "images.camera"), im);
  }
  readGridImages(r, scene);
}

int lineOf(const toml::node& n) { return static_cast<int>(n.source().begin.line); }

void readThermal(const TableReader& root, Scene& scene) {
  const toml::table* t = root.optTable("thermal");
  if (!t) return;
  const TableReader r(root.context(), *t, "thermal", "thermal");
  ThermalOutputOptions& th = scene.thermal;
  th.enabled = true;
  th.line = lineOf(*t);
  th.study = r.requireString("study");
  const std::string material = r.optString("hot_material").value_or("snapshot");
  r.check(material == "snapshot" || material == "evolving", "hot_material",
          "expected \"snapshot\" (the material of one output, frozen during the pass) or "
          "\"evolving\" (the material of each moment of the pass)");
  th.evolving = material == "evolving";
  r.check(!th.study.empty(), "study", "must name a study file");
  if (const toml::node* n = t->get("times")) {
    const toml::array* arr = n->as_array();
    r.check(arr != nullptr, "times", "expected an array of times, e.g. [\"1 ms\", \"3 ms\"]");
    for (std::size_t i = 0; i < arr->size(); ++i) {
      const double time = r.quantityOf(*arr->get(i), "thermal.times[" + std::to_string(i) + "]",
                                       Dimension::Time);
      r.check(time >= 0.0, "times", "times must not be negative");
      r.check(th.times.empty() || time > th.times.back(), "times", "times must increase");
      th.times.push_back(time);
    }
  }
}

// Names within one list must be unique: bodies and deposits are reported by name.
void checkUniqueName(const TableReader& r, std::set<std::string>& seen, const std::string& name) {
  r.check(!name.empty(), "name", "must not be empty");
  r.check(seen.insert(name).second, "name", "'" + name + "' is already used by an earlier entry");
}

// Keys of a material's model tables and what each must measure; string keys are handled apart.
struct ModelKey {
  std::string_view key;
  Dimension dimension;
};
const Dimension kPerVolume{0, -3, 0, 0};
const Dimension kPerTime{0, 0, -1, 0};
const Dimension kSpecificHeat{0, 2, -2, -1};

void readModelTable(const TableReader& material, std::string_view name,
                    const std::vector<ModelKey>& keys, const std::vector<std::string_view>& models,
                    ModelSpec& out) {
  const toml::table* t = material.optTable(name);
  if (!t) return;
  const TableReader r(material.context(), *t, material.key(name),
                      "materials[]." + std::string(name));
  out.present = true;
  out.line = lineOf(*t);
  if (!models.empty()) {
    EnumNames<std::string> names;
    for (std::string_view m : models) names.push_back({m, std::string(m)});
    const std::optional<std::string> model = r.optEnum<std::string>("model", names);
    if (!model) r.fail("model", "required key is missing; one of " + enumList(names));
    out.model = *model;
  }
  out.library = r.optString("library").value_or("");
  for (const ModelKey& k : keys) {
    if (k.key == "seed") {
      if (const std::optional<long> seed = r.optInteger("seed")) {
        r.check(*seed >= 0, "seed", "must not be negative");
        out.values.emplace_back("seed", static_cast<double>(*seed));
      }
      continue;
    }
    if (const std::optional<double> v = r.optQuantity(k.key, k.dimension)) {
      r.check(*v >= 0.0, k.key, nonNegativeMessage(*v, k.dimension));
      out.values.emplace_back(std::string(k.key), *v);
    }
  }
}

void readMaterialModels(const TableReader& r, MaterialSpec& m) {
  readModelTable(r, "thermal",
                 {{"specific_heat", kSpecificHeat},
                  {"mean_atomic_mass", Dimension::None},
                  {"molar_mass", Dimension::None},
                  {"initial_temperature", Dimension::Temperature},
                  {"melt_temperature", Dimension::Temperature}},
                 {}, m.thermal);
  readModelTable(r, "strength",
                 {{"shear_modulus", Dimension::Pressure},
                  {"yield_stress", Dimension::Pressure},
                  {"A", Dimension::Pressure},
                  {"B", Dimension::Pressure},
                  {"n", Dimension::None},
                  {"C", Dimension::None},
                  {"m", Dimension::None},
                  {"reference_strain_rate", kPerTime},
                  {"room_temperature", Dimension::Temperature},
                  {"cohesion", Dimension::Pressure},
                  {"friction_intact", Dimension::None},
                  {"strength_limit", Dimension::Pressure},
                  {"friction_damaged", Dimension::None},
                  {"cohesion_damaged", Dimension::Pressure}},
                 {"elastic", "von_mises", "johnson_cook", "collins"}, m.strength);
  readModelTable(r, "fracture",
                 {{"weibull_k", kPerVolume},
                  {"weibull_m", Dimension::None},
                  {"tensile_strength", Dimension::Pressure},
                  {"erosion_strain", Dimension::None},
                  {"crack_speed_factor", Dimension::None},
                  {"max_crack_increment", Dimension::None},
                  {"seed", Dimension::None}},
                 {"none", "grady_kipp", "principal_stress"}, m.fracture);
}

void readMaterials(const TableReader& root, Scene& scene) {
  const std::vector<const toml::table*> list = root.tableArray("materials");
  if (list.empty()) root.fail("materials", "at least one [[materials]] entry is required");
  std::set<std::string> names;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const TableReader r(root.context(), *list[i], "materials[" + std::to_string(i) + "]",
                        "materials[]");
    MaterialSpec m;
    m.line = lineOf(*list[i]);
    m.name = r.requireString("name");
    checkUniqueName(r, names, m.name);
    EnumNames<std::string> eosNames;
    for (const EosKind& k : eosKinds()) eosNames.push_back({k.name, std::string(k.name)});
    m.eos = r.optEnum<std::string>("eos", eosNames).value_or("ideal_gas");
    const EosKind& kind = *findEosKind(m.eos);
    if (r.has("gamma")) {
      r.check(m.eos == "ideal_gas", "gamma", "applies to eos = \"ideal_gas\" only");
      m.gamma = *r.optQuantity("gamma", Dimension::None);
      r.check(m.gamma > 1.0, "gamma", "must exceed 1 (got " + formatQuantity(m.gamma, {}) + ")");
    }
    if (const std::optional<std::string> library = r.optString("library")) {
      std::string known;
      bool found = false;
      for (const std::string& n : kind.libraryNames) {
        known += (known.empty() ? "" : ", ") + n;
        found = found || n == *library;
      }
      r.check(found, "library",
              "no " + m.eos + " library entry '" + *library + "'" +
                  (known.empty() ? std::string(" (this eos has no library)") : "; known: " + known));
      m.library = *library;
    }
    if (const toml::table* params = r.optTable("parameters")) {
      const TableReader pr(root.context(), *params, r.key("parameters"), "materials[].parameters");
      for (auto&& [k, node] : *params) {
        const EosParameter* found = nullptr;
        for (const EosParameter& p : kind.parameters)
          if (p.key == k.str()) found = &p;
        if (!found) {
          std::string known;
          for (const EosParameter& p : kind.parameters)
            known += (known.empty() ? "" : ", ") + std::string(p.key);
          pr.fail(k.str(), "not a parameter of eos '" + m.eos + "'; its parameters: " + known);
        }
        m.parameters.emplace_back(std::string(k.str()),
                                  pr.quantityOf(node, pr.key(k.str()), found->dimension));
      }
    }
    readMaterialModels(r, m);
    scene.materials.push_back(std::move(m));
  }
}

std::string vectorLayout(Geometry g) {
  switch (g) {
    case Geometry::Line: return "[x]";
    case Geometry::Planar: return "[x, y]";
    case Geometry::Axisymmetric: return "[r, z]";
    case Geometry::Spatial: return "[x, y, z]";
  }
  return "";
}

// Bounding box of the part of the domain a shape may occupy ([-inf, inf] where unbounded).
struct Box {
  std::array<double, 3> lo{}, hi{};
};

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
  static const std::map<ShapeKind, KeyList> kShapeKeys{
      {ShapeKind::Box, {"min", "max"}},
      {ShapeKind::Sphere, {"center", "radius"}},
      {ShapeKind::Shell, {"center", "inner_radius", "outer_radius"}},
      {ShapeKind::HalfSpace, {"point", "normal"}}};
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

// A paraboloid bowl (void bodies only): floor = `point`, opening along `normal`, `radius` wide at
// `depth` above the floor.
void readBowl(const TableReader& r, const Scene& scene, BowlSpec& bowl) {
  for (std::string_view k : {"min", "max", "center", "inner_radius", "outer_radius"})
    if (r.has(k)) r.fail(k, "not used by shape 'paraboloid' (it takes point, normal, radius, depth)");
  for (std::string_view k : {"point", "normal", "radius", "depth"}) r.require(k);
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

// A [[bodies]] entry with void = true: a name and a shape, nothing that particles would need.
void readVoid(const TableReader& r, Scene& scene, int line) {
  for (std::string_view k : {"material", "lattice", "spacing", "density", "pressure",
                             "internal_energy", "velocity", "damage"})
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

void readDeposits(const TableReader& root, Scene& scene) {
  static const EnumNames<DepositProfile> kProfiles{{"top_hat", DepositProfile::TopHat},
                                                   {"gaussian", DepositProfile::Gaussian}};
  const std::vector<const toml::table*> list = root.tableArray("energy_deposits");
  const int dim = spatialDimension(scene.geometry);
  const Dimension m = Dimension::Length;
  std::set<std::string> names;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const TableReader r(root.context(), *list[i], "energy_deposits[" + std::to_string(i) + "]",
                        "energy_deposits[]");
    EnergyDepositSpec e;
    e.line = lineOf(*list[i]);
    e.name = r.requireString("name");
    checkUniqueName(r, names, e.name);
    e.energy = r.requireQuantity("energy", Dimension::Energy);
    r.check(e.energy > 0.0, "energy", positiveMessage(e.energy, Dimension::Energy));
    // A delayed deposit (the follower's burst after the impact) must fire before the run ends.
    e.time = r.optQuantity("time", Dimension::Time).value_or(0.0);
    r.check(e.time >= 0.0, "time", nonNegativeMessage(e.time, Dimension::Time));
    r.check(e.time < scene.time.tEnd, "time",
            "the deposit at " + formatQuantity(e.time, Dimension::Time) +
                " would never fire: the run ends at t_end = " +
                formatQuantity(scene.time.tEnd, Dimension::Time));
    if (const std::optional<std::string> body = r.optString("body")) {
      for (std::size_t b = 0; b < scene.bodies.size(); ++b)
        if (scene.bodies[b].name == *body) e.body = static_cast<int>(b);
      for (const VoidSpec& v : scene.voids)
        r.check(v.name != *body, "body", "'" + *body + "' is a void body: it has no particles");
      r.check(e.body >= 0, "body", "no body named '" + *body + "'");
    }
    // A body deposit without a centre covers the whole body (the seed's device particles).
    e.hasCenter = e.body < 0 || r.has("center");
    if (e.hasCenter) {
      r.require("center");
      e.center = *r.optVector("center", m, dim, vectorLayout(scene.geometry));
      if (scene.geometry == Geometry::Axisymmetric)
        r.check(e.center[0] == 0.0, "center",
                "in rz the deposit must be centred on the axis (r = 0)");
    } else {
      r.check(!r.has("radius") && !r.has("width") && !r.has("profile"), "radius",
              "a deposit over a whole body takes no radius, width or profile (give a 'center' "
              "to deposit in part of it)");
      scene.deposits.push_back(std::move(e));
      continue;
    }
    e.profile = r.optEnum("profile", kProfiles).value_or(e.profile);
    if (e.profile == DepositProfile::TopHat) {
      r.check(!r.has("width"), "width", "only a 'gaussian' profile takes a width");
      e.radius = r.requireQuantity("radius", m);
      r.check(e.radius > 0.0, "radius", positiveMessage(e.radius, m));
    } else {
      r.check(!r.has("radius"), "radius", "a 'gaussian' profile takes a width, not a radius");
      e.width = r.requireQuantity("width", m);
      r.check(e.width > 0.0, "width", positiveMessage(e.width, m));
    }
    scene.deposits.push_back(std::move(e));
  }
}

void readDetonations(const TableReader& root, Scene& scene) {
  const std::vector<const toml::table*> list = root.tableArray("detonations");
  const int dim = spatialDimension(scene.geometry);
  const Dimension m = Dimension::Length;
  std::set<std::string> names;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const TableReader r(root.context(), *list[i], "detonations[" + std::to_string(i) + "]",
                        "detonations[]");
    DetonationSpec d;
    d.line = lineOf(*list[i]);
    d.name = r.requireString("name");
    checkUniqueName(r, names, d.name);
    const std::string material = r.requireString("material");
    d.material = -1;
    for (std::size_t k = 0; k < scene.materials.size(); ++k)
      if (scene.materials[k].name == material) d.material = static_cast<int>(k);
    r.check(d.material >= 0, "material", "no material named '" + material + "'");
    r.check(scene.materials[static_cast<std::size_t>(d.material)].eos == "jwl", "material",
            "material '" + material + "' is not a JWL explosive (eos = \"jwl\"); programmed "
            "burn lights detonation products");
    r.require("point");
    d.point = *r.optVector("point", m, dim, vectorLayout(scene.geometry));
    if (const auto end = r.optVector("line_to", m, dim, vectorLayout(scene.geometry))) {
      d.alongLine = true;
      d.lineEnd = *end;
    }
    if (scene.geometry == Geometry::Axisymmetric) {
      r.check(d.point[0] == 0.0, "point", "in rz the initiation point must be on the axis (r = 0)");
      r.check(!d.alongLine || d.lineEnd[0] == 0.0, "line_to",
              "in rz an initiation line must lie on the axis (r = 0)");
    }
    d.time = r.optQuantity("time", Dimension::Time).value_or(0.0);
    r.check(d.time >= 0.0, "time", nonNegativeMessage(d.time, Dimension::Time));
    d.velocity = r.optQuantity("velocity", Dimension::Velocity).value_or(0.0);
    r.check(d.velocity >= 0.0, "velocity", nonNegativeMessage(d.velocity, Dimension::Velocity));
    for (const DetonationSpec& other : scene.detonations)
      r.check(other.material != d.material || other.velocity == d.velocity, "velocity",
              "detonations of one explosive must share one detonation velocity");
    scene.detonations.push_back(std::move(d));
  }
  // A body with neither pressure nor internal energy must be an explosive lit here: it starts at
  // its detonation energy (sim/setup/bodies.cpp).
  const std::vector<const toml::table*> bodies = root.tableArray("bodies");
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    const BodySpec& body = scene.bodies[b];
    if (body.pressure || body.internalEnergy) continue;
    bool lit = false;
    for (const DetonationSpec& d : scene.detonations) lit = lit || d.material == body.material;
    if (!lit) {
      const std::size_t entry = body.entry >= 0 ? static_cast<std::size_t>(body.entry) : b;
      const TableReader r(root.context(), *bodies[entry], "bodies[" + std::to_string(entry) + "]",
                          "bodies[]");
      r.fail("pressure", "give exactly one of 'pressure' and 'internal_energy' (only a body of "
                         "an explosive with a [[detonations]] entry may give neither)");
    }
  }
}

void readGauges(const TableReader& root, Scene& scene) {
  const std::vector<const toml::table*> list = root.tableArray("gauges");
  const int dim = spatialDimension(scene.geometry);
  std::set<std::string> names;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const TableReader r(root.context(), *list[i], "gauges[" + std::to_string(i) + "]", "gauges[]");
    GaugeSpec g;
    g.line = lineOf(*list[i]);
    g.name = r.requireString("name");
    checkUniqueName(r, names, g.name);
    for (char c : g.name)
      r.check(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-', "name",
              "a gauge name is a CSV column prefix: letters, digits, '_' and '-' only");
    r.require("position");
    g.position = *r.optVector("position", Dimension::Length, dim, vectorLayout(scene.geometry));
    if (scene.geometry == Geometry::Axisymmetric)
      r.check(g.position[0] >= 0.0, "position", "in rz a gauge's r must be >= 0");
    scene.gauges.push_back(std::move(g));
  }
}

Scene validate(const toml::table& doc, const std::string& sourceName) {
  const Context ctx(sourceName, doc);
  const TableReader root(ctx, doc, "", "");
  Scene scene;
  scene.sourcePath = sourceName;
  readScene(root, scene);
  readDomain(root, scene);
  readSph(root, scene.sph);
  readTime(root, scene.time);
  readOutput(root, scene.output);
  readMaterials(root, scene);
  readBodies(root, scene);
  readDeposits(root, scene);
  readDetonations(root, scene);
  readGauges(root, scene);
  readFields(root, scene);
  readCrater(root, scene);
  readImages(root, scene);
  readThermal(root, scene);
  return scene;
}

}  // namespace

Scene parseScene(const std::string& tomlText, const std::string& sourceName,
                 const std::vector<std::string>& overrides) {
  toml::table doc;
  try {
    doc = toml::parse(tomlText, sourceName);
  } catch (const toml::parse_error& e) {
    throw SceneError(sourceName + ":" + std::to_string(e.source().begin.line) +
                     ": TOML syntax error: " + std::string(e.description()));
  }
  for (const std::string& o : overrides) applyOverride(doc, o, sourceName);
  return validate(doc, sourceName);
}

Scene loadScene(const std::string& path, const std::vector<std::string>& overrides) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path + ": cannot open the scene file");
  std::ostringstream text;
  text << in.rdbuf();
  return parseScene(text.str(), path, overrides);
}

}  // namespace ejecta
