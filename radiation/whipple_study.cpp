// The Whipple study file (TOML, toml++), its run and its outputs. docs/whipple.md.
#include "radiation/whipple_study.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <utility>

#include "core/json.hpp"
#include "core/units.hpp"

namespace ejecta::radiation {

namespace fs = std::filesystem;

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

using KeyList = std::vector<std::string_view>;

const std::map<std::string_view, KeyList>& allowedKeys() {
  static const std::map<std::string_view, KeyList> keys = {
      {"", {"study", "shield", "threat", "curve", "options"}},
      {"study", {"name", "description"}},
      {"shield", {"bumper_thickness", "bumper_density", "wall_thickness", "wall_density", "wall_yield", "standoff",
                  "area"}},
      {"threat", {"density", "angle", "diameter", "speed"}},
      {"curve", {"speed_min", "speed_max", "samples"}},
      {"options", {"max_obliquity"}},
  };
  return keys;
}

// Checked access to one table; failures name the file, the line and the dotted key.
class Table {
 public:
  Table(const std::string& source, const toml::table& t, std::string path)
      : source_(source), t_(t), path_(std::move(path)) {
    const KeyList& allowed = allowedKeys().at(path_);
    for (auto&& [k, v] : t_) {
      if (std::find(allowed.begin(), allowed.end(), k.str()) != allowed.end()) continue;
      std::string list;
      for (std::string_view a : allowed) list += std::string(list.empty() ? "" : ", ") + std::string(a);
      failAt(&v, key(k.str()), "unknown key; allowed keys here: " + list);
    }
  }

  std::string key(std::string_view k) const { return path_.empty() ? std::string(k) : path_ + "." + std::string(k); }
  const toml::node* find(std::string_view k) const { return t_.get(k); }
  bool has(std::string_view k) const { return find(k) != nullptr; }
  const std::string& source() const { return source_; }

  [[noreturn]] void failAt(const toml::node* n, const std::string& fullKey, const std::string& reason) const {
    const int line = n ? static_cast<int>(n->source().begin.line) : 0;
    throw WhippleStudyError(source_ + ":" + std::to_string(line > 0 ? line : 1) + ": key '" + fullKey + "': " +
                            reason);
  }
  [[noreturn]] void fail(std::string_view k, const std::string& reason) const {
    const toml::node* n = find(k);
    failAt(n ? n : &t_, key(k), reason);
  }

  // A number (SI) or a string with a unit, at node n named fullKey.
  double quantityAt(const toml::node& n, const std::string& fullKey, Dimension kind) const {
    if (n.is_string()) {
      try {
        return parseQuantity(*n.value<std::string>(), kind);  // core's parser: a scene's units
      } catch (const UnitError& e) {
        failAt(&n, fullKey, e.what());
      }
    }
    if (!n.is_integer() && !n.is_floating_point())
      failAt(&n, fullKey, "expected a number (SI) or a string with a unit");
    const double x = *n.value<double>();
    if (!std::isfinite(x)) failAt(&n, fullKey, "must be finite");
    return x;
  }
  double quantity(std::string_view k, Dimension kind) const {
    const toml::node* n = find(k);
    if (!n) failAt(&t_, key(k), "required key is missing");
    return quantityAt(*n, key(k), kind);
  }
  double positive(std::string_view k, Dimension kind) const {
    const double x = quantity(k, kind);
    if (!(x > 0.0)) fail(k, "must be > 0");
    return x;
  }
  double positive(std::string_view k, Dimension kind, double fallback) const {
    return has(k) ? positive(k, kind) : fallback;
  }
  // One quantity or an array of them, each > 0.
  std::vector<double> positiveList(std::string_view k, Dimension kind) const {
    const toml::node* n = find(k);
    if (!n) failAt(&t_, key(k), "required key is missing");
    const toml::array* a = n->as_array();
    if (!a) return {positive(k, kind)};
    if (a->empty()) fail(k, "the list is empty");
    std::vector<double> out;
    for (std::size_t i = 0; i < a->size(); ++i) {
      const std::string name = key(k) + "[" + std::to_string(i) + "]";
      const double x = quantityAt(*a->get(i), name, kind);
      if (!(x > 0.0)) failAt(a->get(i), name, "must be > 0");
      out.push_back(x);
    }
    return out;
  }
  long long integer(std::string_view k, long long fallback, long long lo, long long hi) const {
    const toml::node* n = find(k);
    if (!n) return fallback;
    if (!n->is_integer()) fail(k, "expected an integer");
    const long long v = *n->value<std::int64_t>();
    if (v < lo || v > hi) fail(k, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    return v;
  }
  std::string string(std::string_view k, const std::string& fallback) const {
    const toml::node* n = find(k);
    if (!n) return fallback;
    if (!n->is_string()) fail(k, "expected a string");
    return *n->value<std::string>();
  }
  Table sub(std::string_view k) const {
    const toml::node* n = find(k);
    if (n && !n->is_table()) fail(k, "expected a table");
    static const toml::table empty;
    return Table(source_, n ? *n->as_table() : empty, std::string(k));
  }

 private:
  const std::string& source_;
  const toml::table& t_;
  std::string path_;
};

std::string num(const char* spec, double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, spec, x);
  return buf;
}
std::string mm(double metres) { return num("%.4g", metres * 1e3); }
std::string kms(double speed) { return num("%.4g", speed * 1e-3); }
// whipple.json's numbers: 12 significant digits, null where not finite.
std::string jsonNumber(double x) { return ejecta::jsonNumber(x, 12); }

std::string limitJson(double speed, const BallisticLimit& l) {
  return "{\"speed_m_s\": " + jsonNumber(speed) + ", \"normal_speed_m_s\": " + jsonNumber(l.normalSpeed) +
         ", \"critical_diameter_m\": " + jsonNumber(l.diameter) + ", \"regime\": \"" +
         std::string(regimeName(l.regime)) + "\"}";
}

}  // namespace

WhippleStudy parseWhippleStudy(const std::string& tomlText, const std::string& sourceName) {
  toml::table root;
  try {
    root = toml::parse(tomlText, sourceName);
  } catch (const toml::parse_error& e) {
    throw WhippleStudyError(sourceName + ":" + std::to_string(e.source().begin.line) + ": " +
                            std::string(e.description()));
  }
  WhippleStudy s;
  s.source = sourceName;
  const Table top(s.source, root, "");
  const Table study = top.sub("study");
  s.name = study.string("name", fs::path(sourceName).stem().string());
  s.description = study.string("description", "");

  if (!top.has("shield")) top.fail("shield", "required: the bumper, rear wall and standoff ([shield])");
  const Table shield = top.sub("shield");
  s.shield.bumperThickness = shield.positive("bumper_thickness", Dimension::Length);
  s.shield.bumperDensity = shield.positive("bumper_density", Dimension::Density);
  s.wallThicknesses = shield.positiveList("wall_thickness", Dimension::Length);
  s.shield.wallThickness = s.wallThicknesses.front();
  s.shield.wallDensity = shield.positive("wall_density", Dimension::Density, 0.0);
  s.shield.wallYieldStress = shield.positive("wall_yield", Dimension::Pressure);
  s.shield.standoff = shield.positive("standoff", Dimension::Length);
  s.area = shield.positive("area", Dimension::Area, 0.0);

  if (!top.has("threat")) top.fail("threat", "required: the projectile's density ([threat])");
  const Table threat = top.sub("threat");
  s.threat.density = threat.positive("density", Dimension::Density);
  if (threat.has("angle")) {
    s.threat.angle = threat.quantity("angle", Dimension::Angle);
    if (!(s.threat.angle >= 0.0 && s.threat.angle < 90.0 * kDegree))
      threat.fail("angle", "must be in [0, 90) deg from the bumper normal");
  }
  s.threat.diameter = threat.positive("diameter", Dimension::Length, 0.0);
  s.threat.speed = threat.positive("speed", Dimension::Velocity, 0.0);

  const Table curve = top.sub("curve");
  s.speedMin = curve.positive("speed_min", Dimension::Velocity, s.speedMin);
  s.speedMax = curve.positive("speed_max", Dimension::Velocity, s.speedMax);
  if (!(s.speedMax > s.speedMin)) curve.fail(curve.has("speed_max") ? "speed_max" : "speed_min",
                                             "speed_max must exceed speed_min");
  s.samples = static_cast<int>(curve.integer("samples", s.samples, 2, 100000));

  const Table options = top.sub("options");
  if (options.has("max_obliquity")) {
    s.options.maxObliquity = options.quantity("max_obliquity", Dimension::Angle);
    if (!(s.options.maxObliquity > 0.0 && s.options.maxObliquity <= 90.0 * kDegree))
      options.fail("max_obliquity", "must be in (0, 90] deg");
  }
  return s;
}

WhippleStudy loadWhippleStudy(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw WhippleStudyError(path.string() + ": cannot open the Whipple study file");
  std::stringstream text;
  text << in.rdbuf();
  return parseWhippleStudy(text.str(), path.string());
}

WhippleResult runWhippleStudy(const WhippleStudy& study) {
  WhippleResult r;
  r.study = study;
  const WhippleThreat& t = study.threat;
  try {
    r.boundaries = regimeBoundaries(t.angle, study.options);
    for (double tw : study.wallThicknesses) {
      WhippleWallResult w;
      w.shield = study.shield;
      w.shield.wallThickness = tw;
      w.curve = ballisticLimitCurve(w.shield, t.density, t.angle, study.speedMin, study.speedMax, study.samples,
                                    study.options);
      w.weakest = *std::min_element(w.curve.begin(), w.curve.end(), [](const auto& a, const auto& b) {
        return a.limit.diameter < b.limit.diameter;
      });
      if (t.speed > 0.0) {
        w.atThreat = criticalDiameter(w.shield, t.density, t.speed, t.angle, study.options);
        if (t.diameter > 0.0) w.stopsThreat = w.atThreat->diameter >= t.diameter;
      }
      w.arealMass = study.shield.wallDensity > 0.0 ? w.shield.arealMass() : 0.0;
      r.walls.push_back(std::move(w));
    }
    if (t.diameter > 0.0 && t.speed > 0.0) {
      WhippleDesign d;
      d.wallAtThreatSpeed = requiredWallThickness(study.shield, t.density, t.diameter, t.speed, t.angle, study.options);
      // Every curve speed up to the threat's (the curve carries the regime corners, where the
      // BLE are lowest), and the threat's own speed.
      d.wallUpToThreatSpeed = d.wallAtThreatSpeed;
      d.governingSpeed = t.speed;
      for (const BallisticLimitPoint& p : r.walls.front().curve) {
        if (p.speed > t.speed) break;
        const double tw = requiredWallThickness(study.shield, t.density, t.diameter, p.speed, t.angle, study.options);
        if (tw > d.wallUpToThreatSpeed) {
          d.wallUpToThreatSpeed = tw;
          d.governingSpeed = p.speed;
        }
      }
      d.sizing = christiansenSizing(t.density, t.diameter, t.speed, t.angle, study.shield.bumperDensity,
                                    study.shield.wallYieldStress, study.shield.standoff, study.options);
      d.bumperAdequate = bumperAdequate(study.shield, t.density, t.diameter);
      r.design = d;
    }
  } catch (const std::invalid_argument& e) {
    throw WhippleStudyError(study.source + ": " + e.what());
  }
  return r;
}

std::string formatWhippleCsv(const WhippleResult& result) {
  std::string out = "wall_thickness_m,speed_m_s,normal_speed_m_s,critical_diameter_m,regime\n";
  for (const WhippleWallResult& w : result.walls)
    for (const BallisticLimitPoint& p : w.curve)
      out += num("%.9g", w.shield.wallThickness) + "," + num("%.9g", p.speed) + "," +
             num("%.9g", p.limit.normalSpeed) + "," + num("%.9g", p.limit.diameter) + "," +
             std::string(regimeName(p.limit.regime)) + "\n";
  return out;
}

std::string formatWhippleJson(const WhippleResult& result) {
  const WhippleStudy& s = result.study;
  const WhippleThreat& t = s.threat;
  const double theta = std::min(t.angle, s.options.maxObliquity);
  std::string j = "{\n";
  j += "  \"name\": " + jsonString(s.name) + ",\n  \"source\": " + jsonString(s.source) + ",\n";
  j += "  \"description\": " + jsonString(s.description) + ",\n";
  j += "  \"equations\": \"Christiansen (1993), Int. J. Impact Eng. 14, 145-156: Whipple shield BLE\",\n";
  j += "  \"shield\": {\"bumper_thickness_m\": " + jsonNumber(s.shield.bumperThickness) +
       ", \"bumper_density_kg_m3\": " + jsonNumber(s.shield.bumperDensity) +
       ", \"wall_density_kg_m3\": " + jsonNumber(s.shield.wallDensity) +
       ", \"wall_yield_Pa\": " + jsonNumber(s.shield.wallYieldStress) +
       ", \"standoff_m\": " + jsonNumber(s.shield.standoff) + ", \"area_m2\": " + jsonNumber(s.area) + "},\n";
  j += "  \"threat\": {\"density_kg_m3\": " + jsonNumber(t.density) + ", \"angle_deg\": " +
       jsonNumber(t.angle / kDegree) + ", \"effective_angle_deg\": " + jsonNumber(theta / kDegree) +
       ", \"diameter_m\": " + (t.diameter > 0.0 ? jsonNumber(t.diameter) : "null") +
       ", \"speed_m_s\": " + (t.speed > 0.0 ? jsonNumber(t.speed) : "null") + "},\n";
  j += "  \"regime_boundaries_m_s\": {\"ballistic_max\": " + jsonNumber(result.boundaries.ballisticLimit) +
       ", \"hypervelocity_min\": " + jsonNumber(result.boundaries.hypervelocityLimit) + "},\n";
  j += "  \"walls\": [";
  for (std::size_t i = 0; i < result.walls.size(); ++i) {
    const WhippleWallResult& w = result.walls[i];
    j += std::string(i ? "," : "") + "\n    {\"wall_thickness_m\": " + jsonNumber(w.shield.wallThickness);
    j += ", \"areal_mass_kg_m2\": " + (w.arealMass > 0.0 ? jsonNumber(w.arealMass) : "null");
    if (s.area > 0.0 && s.shield.wallDensity > 0.0)
      j += ", \"bumper_mass_kg\": " + jsonNumber(s.area * s.shield.bumperDensity * s.shield.bumperThickness) +
           ", \"wall_mass_kg\": " + jsonNumber(s.area * s.shield.wallDensity * w.shield.wallThickness);
    j += ",\n     \"weakest\": " + limitJson(w.weakest.speed, w.weakest.limit);
    j += ",\n     \"at_threat\": " + (w.atThreat ? limitJson(t.speed, *w.atThreat) : std::string("null"));
    j += ", \"stops_threat\": " + (w.stopsThreat ? std::string(*w.stopsThreat ? "true" : "false") : "null") + "}";
  }
  j += "\n  ],\n  \"design\": ";
  if (result.design) {
    const WhippleDesign& d = *result.design;
    j += "{\"wall_at_threat_speed_m\": " + jsonNumber(d.wallAtThreatSpeed) +
         ", \"wall_up_to_threat_speed_m\": " + jsonNumber(d.wallUpToThreatSpeed) +
         ", \"governing_speed_m_s\": " + jsonNumber(d.governingSpeed) +
         ",\n    \"christiansen_sizing\": {\"bumper_thickness_m\": " + jsonNumber(d.sizing.bumperThickness) +
         ", \"bumper_coefficient\": " + jsonNumber(d.sizing.bumperCoefficient) +
         ", \"wall_thickness_m\": " + jsonNumber(d.sizing.wallThickness) +
         ", \"in_range\": " + (d.sizing.inRange ? "true" : "false") + "}" +
         ", \"bumper_adequate\": " + (d.bumperAdequate ? "true" : "false") + "}\n";
  } else {
    j += "null\n";
  }
  return j + "}\n";
}

std::string formatWhippleText(const WhippleResult& result) {
  const WhippleStudy& s = result.study;
  const WhippleThreat& t = s.threat;
  const double theta = std::min(t.angle, s.options.maxObliquity);
  std::string o = "Whipple shield '" + s.name + "' (" + s.source + "), Christiansen (1993) ballistic-limit equations\n";
  o += "  bumper " + mm(s.shield.bumperThickness) + " mm at " + num("%.0f", s.shield.bumperDensity) +
       " kg/m^3, standoff " + mm(s.shield.standoff) + " mm, rear-wall yield " +
       num("%.4g", s.shield.wallYieldStress * 1e-6) + " MPa (" + num("%.4g", s.shield.wallYieldStress / kPascalPerKsi) +
       " ksi)\n";
  o += "  projectile " + num("%.0f", t.density) + " kg/m^3 at " + num("%.3g", t.angle / kDegree) + " deg";
  if (theta < t.angle) o += " (evaluated at " + num("%.3g", theta / kDegree) + " deg)";
  o += ": ballistic up to " + kms(result.boundaries.ballisticLimit) + " km/s, hypervelocity from " +
       kms(result.boundaries.hypervelocityLimit) + " km/s\n";
  const bool threatSpeed = t.speed > 0.0;
  o += "  t_w [mm] | smallest d_c [mm] (at km/s)";
  if (threatSpeed) o += " | d_c at " + kms(t.speed) + " km/s [mm] (regime)";
  if (t.diameter > 0.0 && threatSpeed) o += " | stops " + mm(t.diameter) + " mm";
  if (s.shield.wallDensity > 0.0) o += " | kg/m^2";
  if (s.area > 0.0 && s.shield.wallDensity > 0.0) o += " | mass over " + num("%.4g", s.area) + " m^2 [kg] (bumper + wall)";
  o += "\n";
  for (const WhippleWallResult& w : result.walls) {
    o += "  " + num("%8.4g", w.shield.wallThickness * 1e3) + " | " + num("%8.4g", w.weakest.limit.diameter * 1e3) +
         " (" + kms(w.weakest.speed) + ")";
    if (w.atThreat)
      o += " | " + num("%8.4g", w.atThreat->diameter * 1e3) + " (" + std::string(regimeName(w.atThreat->regime)) + ")";
    if (w.stopsThreat) o += std::string(" | ") + (*w.stopsThreat ? "yes" : "NO");
    if (s.shield.wallDensity > 0.0) o += " | " + num("%.4g", w.arealMass);
    if (s.area > 0.0 && s.shield.wallDensity > 0.0)
      o += " | " + num("%.4g", w.arealMass * s.area) + " (" +
           num("%.4g", s.area * s.shield.bumperDensity * s.shield.bumperThickness) + " + " +
           num("%.4g", s.area * s.shield.wallDensity * w.shield.wallThickness) + ")";
    o += "\n";
  }
  if (result.design) {
    const WhippleDesign& d = *result.design;
    o += "  design for " + mm(t.diameter) + " mm at " + kms(t.speed) + " km/s:\n";
    o += "    rear wall with d_c = " + mm(t.diameter) + " mm at " + kms(t.speed) + " km/s: " +
         mm(d.wallAtThreatSpeed) + " mm\n";
    o += "    rear wall with d_c >= " + mm(t.diameter) + " mm at every speed from " + kms(s.speedMin) + " to " +
         kms(t.speed) + " km/s: " + mm(d.wallUpToThreatSpeed) + " mm (set at " + kms(d.governingSpeed) + " km/s)\n";
    o += "    Christiansen's sizing equations" +
         std::string(d.sizing.inRange ? "" : " (outside their range: normal speed < 7 km/s)") + ": bumper " +
         mm(d.sizing.bumperThickness) + " mm (c_b " + num("%.2f", d.sizing.bumperCoefficient) + "), rear wall " +
         mm(d.sizing.wallThickness) + " mm\n";
    o += "    bumper " + mm(s.shield.bumperThickness) + " mm is " +
         (d.bumperAdequate ? "thick enough" : "TOO THIN") + " to break up the projectile (needs >= " +
         mm(d.sizing.bumperThickness) + " mm)\n";
  }
  return o;
}

}  // namespace ejecta::radiation
