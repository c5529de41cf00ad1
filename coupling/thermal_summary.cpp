#include "coupling/thermal_summary.hpp"

namespace ejecta::coupling {

void addToSummary(const ThermalSummary& t, RunSummary& summary) {
  auto& x = summary.extras;
  x.push_back({"thermal_passes", t.passes});
  if (const auto& p = t.governing) {
    x.push_back({"thermal_time_s", p->time});
    x.push_back({"thermal_hot_material", std::string(p->evolving ? "evolving" : "snapshot")});
    x.push_back({"thermal_dir", p->dir});
    x.push_back({"thermal_hot_particles", p->hotParticles});
    x.push_back({"thermal_emitters", p->emitters});
    x.push_back({"thermal_occluder_triangles", p->occluderTriangles});
    std::string faces;
    for (const ThermalSummary::Face& f : p->faces) {
      faces += (faces.empty() ? "" : ",") + f.name;
      const std::string k = "thermal_" + f.name;
      x.push_back({k + "_peak_flux_W_m2", f.peakFlux});
      x.push_back({k + "_steady_K", f.steadyTemperature});
      if (f.structurePeak) x.push_back({k + "_structure_peak_K", *f.structurePeak});
    }
    x.push_back({"thermal_faces", faces});
    for (const ThermalSummary::Shield& s : p->shields) {
      x.push_back({"thermal_shield_" + s.coating + "_mm", s.thicknessMm});
      x.push_back({"thermal_shield_" + s.coating + "_kg", s.mass});
    }
    x.push_back({"thermal_shield", p->recommendation});
  }
  if (!t.note.empty()) x.push_back({"thermal_note", t.note});
}

}  // namespace ejecta::coupling
