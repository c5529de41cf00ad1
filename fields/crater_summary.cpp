#include "fields/crater_summary.hpp"

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
  if (c.scaled) {
    const ScaledCrater& k = *c.scaled;
    s.extras.push_back({"crater_scaling_class", c.scalingClass});
    s.extras.push_back({"crater_scaling_regime", std::string(k.strengthRegime ? "strength" : "gravity")});
    s.extras.push_back({"crater_scaled_volume_m3", k.volume});
    s.extras.push_back({"crater_scaled_diameter_m", 2.0 * k.radius});
    s.extras.push_back({"crater_scaled_depth_m", k.depth});
    if (c.found && !c.planar) s.extras.push_back({"crater_volume_over_scaled", c.volume / k.volume});
  }
}

}  // namespace ejecta::fields
