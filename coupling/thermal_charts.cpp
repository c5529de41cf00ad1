#include "coupling/thermal_charts.hpp"

#include <limits>

#include "core/atomic_file.hpp"
#include "core/csv.hpp"

namespace fs = std::filesystem;

namespace ejecta::coupling {

namespace {

// The coatings in the order the study lists them (every sized face has the same list).
std::vector<std::string> coatingsOf(const radiation::ThermalResult& result) {
  std::vector<std::string> names;
  for (const radiation::PatchThermal& p : result.patches)
    if (!p.sizing.empty()) {
      for (const radiation::ShieldSizing& z : p.sizing) names.push_back(z.material);
      break;
    }
  return names;
}

void writeFluxChart(render::ChartRunner& charts, const radiation::ThermalResult& result,
                    const fs::path& dir, const std::string& name, std::vector<std::string>& written) {
  render::ChartSpec flux{.csv = dir / "flux.csv", .x = "time_s", .xlabel = "time in the pass [s]",
                         .ylabel = "incident flux [W/m^2]",
                         .title = name + ": flux on each face", .out = dir / "flux.png"};
  for (const radiation::PatchThermal& p : result.patches)
    flux.series.push_back({.y = p.patch + "_W_m2", .label = p.patch, .markers = true});
  if (flux.series.empty()) return;
  charts.writeChart(flux);
  written.push_back("flux.png");
}

void writeWallChart(render::ChartRunner& charts, const radiation::ThermalResult& result,
                    const fs::path& dir, const std::string& name, std::vector<std::string>& written) {
  const radiation::PatchThermal* hottest = nullptr;
  for (const radiation::PatchThermal& p : result.patches)
    if (p.wall && (!hottest || p.peakFlux > hottest->peakFlux)) hottest = &p;
  if (!hottest) return;
  const radiation::LayeredWall& wall = hottest->wall->wall();
  render::ChartSpec temps{.csv = dir / ("wall_" + hottest->patch + ".csv"), .x = "time_s",
                          .series = {{.y = "hot_face_K", .label = "hot face"}},
                          .xlabel = "time in the pass [s]", .ylabel = "temperature [K]",
                          .title = name + ": wall of " + hottest->patch,
                          .out = dir / ("wall_" + hottest->patch + ".png")};
  for (std::size_t k = 0; k + 1 < wall.layerCount(); ++k)
    temps.series.push_back({.y = "interface_" + std::to_string(k + 1) + "_K",
                            .label = wall.layers()[k].material.name + " / " +
                                     wall.layers()[k + 1].material.name});
  temps.series.push_back({.y = "cold_face_K", .label = "cold face"});
  charts.writeChart(temps);
  written.push_back(temps.out.filename().string());
}

void writeSizingChart(render::ChartRunner& charts, const radiation::ThermalResult& result,
                      const fs::path& dir, const std::string& name, std::vector<std::string>& written) {
  const std::vector<std::string> coatings = coatingsOf(result);
  if (coatings.empty()) return;
  writeFileAtomically(dir / "sizing_chart.csv", sizingChartCsv(result));
  bool anyNeeded = false, anyInfeasible = false;
  for (const radiation::PatchThermal& p : result.patches)
    for (const radiation::ShieldSizing& z : p.sizing) {
      anyNeeded = anyNeeded || (z.feasible && z.thickness > 0.0);
      anyInfeasible = anyInfeasible || !z.feasible;
    }
  std::string title = name + ": coating needed on each face";
  if (anyInfeasible) title += " (a missing bar: that coating cannot protect the face)";
  render::ChartSpec spec{.kind = render::ChartKind::Bar, .csv = dir / "sizing_chart.csv",
                         .x = "patch", .xlabel = "face", .ylabel = "coating thickness [mm]",
                         .title = title, .out = dir / "sizing.png"};
  // All bars zero would be empty axes: say what they mean.
  if (!anyNeeded && !anyInfeasible) spec.note = "no coating needed: every face stays below its limit";
  for (const std::string& c : coatings) spec.series.push_back({.y = c + "_mm", .label = c});
  charts.writeChart(spec);
  written.push_back("sizing.png");
}

}  // namespace

std::string sizingChartCsv(const radiation::ThermalResult& result) {
  const std::vector<std::string> coatings = coatingsOf(result);
  std::vector<std::string> header{"patch"};
  for (const std::string& c : coatings) header.push_back(c + "_mm");
  for (const std::string& c : coatings) header.push_back(c + "_kg");
  CsvWriter csv(header);
  // NaN ("nan") reads as a missing bar: no thickness up to the thickest considered protects the face.
  constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
  for (const radiation::PatchThermal& p : result.patches) {
    if (p.sizing.size() != coatings.size()) continue;
    csv.text(p.patch);
    for (const radiation::ShieldSizing& z : p.sizing) csv.number(z.feasible ? z.thickness * 1e3 : kNone);
    for (const radiation::ShieldSizing& z : p.sizing) csv.number(z.feasible ? z.addedMass : kNone);
    csv.endRow();
  }
  return csv.str();
}

std::vector<std::string> writeThermalCharts(render::ChartRunner& charts,
                                            const radiation::ThermalResult& result,
                                            const fs::path& dir, const std::string& name) {
  std::vector<std::string> written;
  writeFluxChart(charts, result, dir, name, written);
  writeWallChart(charts, result, dir, name, written);
  writeSizingChart(charts, result, dir, name, written);
  return written;
}

}  // namespace ejecta::coupling
