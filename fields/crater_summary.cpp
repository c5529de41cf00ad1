#include "fields/crater_summary.hpp"

#include <cstdio>

namespace ejecta::fields {

CraterSummary craterSummary(const CraterMetrics& m, bool planar) {
  CraterSummary c;
  c.found = m.found;
  c.note = m.note;
  c.planar = planar;
  c.depth = m.depth;
  c.apparentDiameter = m.apparentDiameter;
  c.rimDiameter = m.rimDiameter;
  c.rimHeight = m.rimHeight;
  c.volume = m.volume;
  c.excavatedMass = m.excavatedMass;
  c.elongation = m.elongation;
  return c;
}

std::string describeScaledCrater(const std::string& scalingClass, const ScaledCrater& k,
                                 std::optional<double> measuredVolume,
                                 std::optional<double> measuredDiameter) {
  char line[320];
  std::snprintf(line, sizeof line,
                "pi-group scaling (%s, %s regime): volume %.4g m^3, diameter %.3g m, depth %.3g m",
                scalingClass.c_str(), k.strengthRegime ? "strength" : "gravity", k.volume,
                2.0 * k.radius, k.depth);
  std::string text = line;
  if (measuredVolume) {
    std::snprintf(line, sizeof line, "; the crater's volume is %.3g of it", *measuredVolume / k.volume);
    text += line;
  }
  if (measuredDiameter) {
    std::snprintf(line, sizeof line, "%s apparent diameter %.3g", measuredVolume ? ", its" : "; the crater's",
                  *measuredDiameter / (2.0 * k.radius));
    text += line;
  }
  return text;
}

CraterSummary craterFailure(const std::string& why) {
  CraterSummary c;
  c.note = why;
  return c;
}

void addToSummary(const CraterSummary& c, RunSummary& s) {
  s.extras.push_back({"crater_found", c.found});
  if (c.growth) {
    s.extras.push_back({"crater_growth_last_fifth", c.growth->change});
    s.extras.push_back({"crater_still_growing", c.growth->growing});
  }
  if (!c.note.empty()) s.extras.push_back({"crater_note", c.note});
  if (c.scaled) {  // also when no crater was found: the prediction stands alone then
    const ScaledCrater& k = *c.scaled;
    s.extras.push_back({"crater_scaling_class", c.scalingClass});
    s.extras.push_back({"crater_scaling_regime", std::string(k.strengthRegime ? "strength" : "gravity")});
    s.extras.push_back({"crater_scaling_strength_pa", k.strength});
    s.extras.push_back({"crater_scaled_volume_m3", k.volume});
    s.extras.push_back({"crater_scaled_diameter_m", 2.0 * k.radius});
    s.extras.push_back({"crater_scaled_depth_m", k.depth});
    if (c.found) {
      s.extras.push_back({"crater_volume_over_scaled", c.volume / k.volume});
      s.extras.push_back({"crater_diameter_over_scaled", c.apparentDiameter / (2.0 * k.radius)});
    }
  }
  if (!c.found) return;
  s.extras.push_back({"crater_depth_m", c.depth});
  s.extras.push_back({"crater_apparent_diameter_m", c.apparentDiameter});
  s.extras.push_back({"crater_rim_diameter_m", c.rimDiameter});
  s.extras.push_back({"crater_rim_height_m", c.rimHeight});
  if (c.planar) {
    s.extras.push_back({"crater_area_m2", c.volume});
    s.extras.push_back({"crater_excavated_mass_kg_per_m", c.excavatedMass});
  } else {
    s.extras.push_back({"crater_volume_m3", c.volume});
    s.extras.push_back({"crater_excavated_mass_kg", c.excavatedMass});
    s.extras.push_back({"crater_elongation", c.elongation});
  }
}

}  // namespace ejecta::fields
