// The Whipple study file (TOML, toml++), its run and its outputs. docs/whipple.md.
#include "radiation/whipple_study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <utility>

#include <nlohmann/json.hpp>

#include "core/csv.hpp"
#include "radiation/format_number.hpp"
#include "radiation/study_input.hpp"

namespace ejecta::radiation {

namespace fs = std::filesystem;

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

const config::SchemaTables& shieldSchema() {
  static const config::SchemaTables keys = {
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

constexpr auto kRaise = &config::raiseInputError<WhippleStudyError>;

using config::TableReader;
using namespace input;

// One quantity or a non-empty array of them, each > 0.
std::vector<double> positiveList(const TableReader& t, std::string_view k, Dimension dim) {
  if (!t.require(k).is_array()) return {requirePositive(t, k, dim)};
  const std::vector<double> out = quantityList(t, k, dim);
  if (out.empty()) t.fail(k, "the list is empty");
  const toml::array& a = *t.find(k)->as_array();
  for (std::size_t i = 0; i < out.size(); ++i)
    if (!(out[i] > 0.0)) t.context().fail(a.get(i), t.key(k) + "[" + std::to_string(i) + "]", "must be > 0");
  return out;
}

std::string num(const char* spec, double x) { return formatNumber(spec, x); }
std::string mm(double metres) { return num("%.4g", metres * 1e3); }
std::string kms(double speed) { return num("%.4g", speed * 1e-3); }
}  // namespace

WhippleStudy parseWhippleStudy(const std::string& tomlText, const std::string& sourceName) {
  const InputDocument doc(tomlText, sourceName, shieldSchema(), kRaise);
  const TableReader top = doc.top();
  WhippleStudy s;
  s.source = sourceName;
  readStudyTitle(top, s.name, s.description);

  if (!top.has("shield")) top.fail("shield", "required: the bumper, rear wall and standoff ([shield])");
  const TableReader shield = subTable(top, "shield");
  s.shield.bumperThickness = requirePositive(shield, "bumper_thickness", Dimension::Length);
  s.shield.bumperDensity = requirePositive(shield, "bumper_density", Dimension::Density);
  s.wallThicknesses = positiveList(shield, "wall_thickness", Dimension::Length);
  s.shield.wallThickness = s.wallThicknesses.front();
  s.shield.wallDensity = optPositive(shield, "wall_density", Dimension::Density, 0.0);
  s.shield.wallYieldStress = requirePositive(shield, "wall_yield", Dimension::Pressure);
  s.shield.standoff = requirePositive(shield, "standoff", Dimension::Length);
  s.area = optPositive(shield, "area", Dimension::Area, 0.0);

  if (!top.has("threat")) top.fail("threat", "required: the projectile's density ([threat])");
  const TableReader threat = subTable(top, "threat");
  s.threat.density = requirePositive(threat, "density", Dimension::Density);
  s.threat.angle = threat.optQuantity("angle", Dimension::Angle).value_or(0.0);
  if (!(s.threat.angle >= 0.0 && s.threat.angle < 90.0 * kDegree))
    threat.fail("angle", "must be in [0, 90) deg from the bumper normal");
  s.threat.diameter = optPositive(threat, "diameter", Dimension::Length, 0.0);
  s.threat.speed = optPositive(threat, "speed", Dimension::Velocity, 0.0);

  const TableReader curve = subTable(top, "curve");
  s.speedMin = optPositive(curve, "speed_min", Dimension::Velocity, s.speedMin);
  s.speedMax = optPositive(curve, "speed_max", Dimension::Velocity, s.speedMax);
  if (!(s.speedMax > s.speedMin)) curve.fail(curve.has("speed_max") ? "speed_max" : "speed_min",
                                             "speed_max must exceed speed_min");
  s.samples = static_cast<int>(integerIn(curve, "samples", s.samples, 2, 100000));

  const TableReader options = subTable(top, "options");
  s.options.maxObliquity = options.optQuantity("max_obliquity", Dimension::Angle).value_or(s.options.maxObliquity);
  if (!(s.options.maxObliquity > 0.0 && s.options.maxObliquity <= 90.0 * kDegree))
    options.fail("max_obliquity", "must be in (0, 90] deg");
  return s;
}

WhippleStudy loadWhippleStudy(const fs::path& path) {
  return parseWhippleStudy(readInputFile(path, "Whipple study file", kRaise), path.string());
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
  CsvWriter csv({"wall_thickness_m", "speed_m_s", "normal_speed_m_s", "critical_diameter_m", "regime"});
  for (const WhippleWallResult& w : result.walls)
    for (const BallisticLimitPoint& p : w.curve)
      csv.number(w.shield.wallThickness)
          .number(p.speed)
          .number(p.limit.normalSpeed)
          .number(p.limit.diameter)
          .text(regimeName(p.limit.regime))
          .endRow();
  return csv.str();
}

std::string formatWhippleJson(const WhippleResult& result) {
  using Json = nlohmann::ordered_json;  // keys in the order users' scripts know
  const WhippleStudy& s = result.study;
  const WhippleThreat& t = s.threat;
  const double theta = std::min(t.angle, s.options.maxObliquity);
  auto limitJson = [](double speed, const BallisticLimit& l) {
    return Json{{"speed_m_s", speed},
                {"normal_speed_m_s", l.normalSpeed},
                {"critical_diameter_m", l.diameter},
                {"regime", regimeName(l.regime)}};
  };
  // A design quantity the file did not give is null, not 0.
  auto given = [](double x) { return x > 0.0 ? Json(x) : Json(nullptr); };
  Json doc;
  doc["name"] = s.name;
  doc["source"] = s.source;
  doc["description"] = s.description;
  doc["equations"] = "Christiansen (1993), Int. J. Impact Eng. 14, 145-156: Whipple shield BLE";
  doc["shield"] = {{"bumper_thickness_m", s.shield.bumperThickness},
                   {"bumper_density_kg_m3", s.shield.bumperDensity},
                   {"wall_density_kg_m3", s.shield.wallDensity},
                   {"wall_yield_Pa", s.shield.wallYieldStress},
                   {"standoff_m", s.shield.standoff},
                   {"area_m2", s.area}};
  doc["threat"] = {{"density_kg_m3", t.density},
                   {"angle_deg", t.angle / kDegree},
                   {"effective_angle_deg", theta / kDegree},
                   {"diameter_m", given(t.diameter)},
                   {"speed_m_s", given(t.speed)}};
  doc["regime_boundaries_m_s"] = {{"ballistic_max", result.boundaries.ballisticLimit},
                                  {"hypervelocity_min", result.boundaries.hypervelocityLimit}};
  Json walls = Json::array();
  for (const WhippleWallResult& w : result.walls) {
    Json j;
    j["wall_thickness_m"] = w.shield.wallThickness;
    j["areal_mass_kg_m2"] = given(w.arealMass);
    if (s.area > 0.0 && s.shield.wallDensity > 0.0) {
      j["bumper_mass_kg"] = s.area * s.shield.bumperDensity * s.shield.bumperThickness;
      j["wall_mass_kg"] = s.area * s.shield.wallDensity * w.shield.wallThickness;
    }
    j["weakest"] = limitJson(w.weakest.speed, w.weakest.limit);
    j["at_threat"] = w.atThreat ? limitJson(t.speed, *w.atThreat) : Json(nullptr);
    j["stops_threat"] = w.stopsThreat ? Json(*w.stopsThreat) : Json(nullptr);
    walls.push_back(std::move(j));
  }
  doc["walls"] = std::move(walls);
  doc["design"] = nullptr;
  if (result.design) {
    const WhippleDesign& d = *result.design;
    doc["design"] = {{"wall_at_threat_speed_m", d.wallAtThreatSpeed},
                     {"wall_up_to_threat_speed_m", d.wallUpToThreatSpeed},
                     {"governing_speed_m_s", d.governingSpeed},
                     {"christiansen_sizing", {{"bumper_thickness_m", d.sizing.bumperThickness},
                                              {"bumper_coefficient", d.sizing.bumperCoefficient},
                                              {"wall_thickness_m", d.sizing.wallThickness},
                                              {"in_range", d.sizing.inRange}}},
                     {"bumper_adequate", d.bumperAdequate}};
  }
  return doc.dump(2) + "\n";
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
