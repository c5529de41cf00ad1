// A thermal study's outputs as text (the caller writes the files): flux.csv and sizing.csv
// through core's CSV writer, thermal.json through nlohmann_json (NaN and infinities as null, key
// order kept: users' scripts read them), and the terminal summary.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "core/csv.hpp"
#include "radiation/format_number.hpp"
#include "radiation/radiative_balance.hpp"
#include "radiation/thermal_study.hpp"

namespace ejecta::radiation {

std::string formatThermalFluxCsv(const ThermalResult& r) {
  std::vector<std::string> header{"time_s"};
  for (const PatchThermal& p : r.patches) {
    header.push_back(p.patch + "_W_m2");
    header.push_back(p.patch + "_se_W_m2");
  }
  CsvWriter csv(header);
  for (std::size_t i = 0; i < r.times.size(); ++i) {
    csv.number(r.times[i]);
    for (const PatchThermal& p : r.patches) csv.number(p.flux[i].value).number(p.flux[i].standardError);
    csv.endRow();
  }
  return csv.str();
}

std::string formatThermalSizingCsv(const ThermalResult& r) {
  CsvWriter csv({"patch", "area_m2", "coating", "feasible", "thickness_m", "added_mass_kg", "structure_peak_K",
                 "coating_peak_K", "coating_melts", "limit_K", "runs", "note"});
  for (const PatchThermal& p : r.patches)
    for (const ShieldSizing& z : p.sizing)
      csv.text(p.patch)
          .number(p.area)
          .text(z.material)
          .flag(z.feasible)
          .number(z.thickness)
          .number(z.addedMass)
          .number(z.structurePeak)
          .number(z.coatingPeak)
          .flag(z.coatingMelts)
          .number(z.limit)
          .integer(z.runs)
          .quoted(z.note)
          .endRow();
  return csv.str();
}

std::string formatThermalJson(const ThermalResult& r, const std::string& extra) {
  using Json = nlohmann::ordered_json;  // keys in the order users' scripts know
  Json doc;
  doc["name"] = r.name;
  doc["source"] = r.source;
  // The caller's own fields ("key": value, ... as JSON text), after name and source.
  if (!extra.empty()) {
    const Json fields = Json::parse("{" + extra + "}");
    for (const auto& [key, value] : fields.items()) doc[key] = value;
  }
  doc["emitters"] = r.emitterCount;
  doc["occluder_triangles"] = r.occluderTriangles;
  doc["groups"] = r.groupNames;
  doc["times_s"] = r.times;
  doc["rays"] = r.rays;
  doc["seconds"] = {{"rays", r.raySeconds}, {"wall", r.wallSeconds}, {"sizing", r.sizingSeconds}};
  Json patches = Json::array();
  for (const PatchThermal& p : r.patches) {
    Json j;
    j["patch"] = p.patch;
    j["area_m2"] = p.area;
    j["peak_flux_W_m2"] = p.peakFlux;
    j["peak_flux_se_W_m2"] = p.peakFluxError;
    j["peak_time_s"] = p.peakTime;
    j["absorptivity"] = p.absorptivity;
    j["emissivity"] = p.emissivity;
    j["steady_temperature_K"] = p.steadyTemperature;
    j["seed_baseline"] = {{"peak_flux", p.peakSeedFlux},
                          {"steady_temperature_K", p.seedSteadyTemperature},
                          {"absorptivity", kSeedAluminiumAbsorptivity},
                          {"emissivity", kSeedAluminiumEmissivity}};
    if (!p.toOccluder.empty()) j["occluder_view_factor_at_peak"] = p.peakOccluderFactor;
    if (p.wall) {
      Json layers = Json::array();
      const auto& wallLayers = p.wall->wall().layers();
      for (std::size_t l = 0; l < wallLayers.size(); ++l)
        layers.push_back({{"material", wallLayers[l].material.name},
                          {"thickness_m", wallLayers[l].thickness},
                          {"peak_K", p.layerPeak[l]},
                          {"melting_point_K", wallLayers[l].material.meltingPoint},
                          {"melt_time_s", p.layerMeltTime[l]}});  // NaN (never) is written null
      j["wall"] = {{"layers", std::move(layers)},
                   {"structure_limit_K", p.structureLimit},
                   {"structure_within_limit", p.structureWithinLimit}};
    }
    if (!p.sizing.empty()) {
      Json sizing = Json::array();
      for (const ShieldSizing& z : p.sizing)
        sizing.push_back({{"coating", z.material},
                          {"feasible", z.feasible},
                          {"thickness_m", z.thickness},
                          {"added_mass_kg", z.addedMass},
                          {"structure_peak_K", z.structurePeak},
                          {"coating_melts", z.coatingMelts}});
      j["sizing"] = std::move(sizing);
    }
    patches.push_back(std::move(j));
  }
  doc["patches"] = std::move(patches);
  Json total = Json::object();
  for (const auto& [coating, mass] : r.totalAddedMass) total[coating] = mass;
  doc["total_added_mass_kg"] = std::move(total);
  return doc.dump(2) + "\n";
}

std::string formatThermalText(const ThermalResult& r) {
  std::string o = "thermal study '" + r.name + "' (" + r.source + "): " + std::to_string(r.emitterCount) +
                  " emitters, " +
                  (r.occluderTriangles ? "an occluder of " + std::to_string(r.occluderTriangles) + " triangles, " : "") +
                  std::to_string(r.times.size()) + " flux samples over " +
                  formatNumber("%.12g", r.times.back()) + " s, " + std::to_string(r.rays) + " rays in " + formatNumber("%.12g", r.raySeconds) + " s\n";
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
