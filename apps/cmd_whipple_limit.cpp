// `ejecta whipple-limit SCENE --speeds ... --diameters MIN,MAX`: ballistic limits of a Whipple
// shield from simulation, against Christiansen's equations (coupling/ballistic_limit_search.hpp,
// docs/whipple.md). Writes limits.csv, shots.csv, ble_curve.csv and limit.png.
#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "apps/commands.hpp"
#include "core/atomic_file.hpp"
#include "core/csv.hpp"
#include "core/units.hpp"
#include "coupling/ballistic_limit_search.hpp"
#include "render/charts.hpp"
#include "sim/setup/scene_catalog.hpp"

namespace fs = std::filesystem;

namespace ejecta::app {

namespace {

std::vector<double> quantities(const std::vector<std::string>& texts, Dimension d, const char* what) {
  std::vector<double> values;
  for (const std::string& t : texts) {
    const double v = parseQuantity(t, d);
    if (!(v > 0.0)) throw std::runtime_error(std::string(what) + ": '" + t + "' must be positive");
    values.push_back(v);
  }
  return values;
}

// The chart: the equations' curve over the speeds searched (with a margin), and the bracket of
// each speed the simulations found.
std::string drawLimitChart(const fs::path& out, const coupling::LimitSearchResult& r, const std::string& title) {
  double lo = r.limits.front().speed, hi = lo;
  for (const coupling::SpeedLimit& l : r.limits) lo = std::min(lo, l.speed), hi = std::max(hi, l.speed);
  const auto curve = radiation::ballisticLimitCurve(r.shield, r.projectileDensity, r.impactAngle,
                                                    std::max(0.5e3, 0.5 * lo), 1.5 * hi + 1e3, 120);
  CsvWriter ble({"speed_km_s", "critical_diameter_mm"});
  for (const radiation::BallisticLimitPoint& p : curve) ble.number(p.speed * 1e-3).number(p.limit.diameter * 1e3).endRow();
  writeFileAtomically(out / "ble_curve.csv", ble.str());
  CsvWriter held({"speed_km_s", "diameter_mm"}), perforating({"speed_km_s", "diameter_mm"});
  for (const coupling::SpeedLimit& l : r.limits) {
    if (l.largestHeld) held.number(l.speed * 1e-3).number(*l.largestHeld * 1e3).endRow();
    if (l.smallestPerforating) perforating.number(l.speed * 1e-3).number(*l.smallestPerforating * 1e3).endRow();
  }
  writeFileAtomically(out / "limit_held.csv", held.str());
  writeFileAtomically(out / "limit_perforating.csv", perforating.str());
  render::ChartRunner charts;
  if (!charts.chartsAvailable()) return charts.unavailableReason();
  std::vector<render::ChartSeries> series = {
      {.y = "critical_diameter_mm", .label = "Christiansen (1993) BLE", .csv = out / "ble_curve.csv", .reference = true}};
  if (held.str().find('\n') != held.str().rfind('\n'))
    series.push_back({.y = "diameter_mm", .label = "SPH: largest not perforating", .csv = out / "limit_held.csv", .scatter = true});
  if (perforating.str().find('\n') != perforating.str().rfind('\n'))
    series.push_back({.y = "diameter_mm", .label = "SPH: smallest perforating", .csv = out / "limit_perforating.csv", .scatter = true});
  try {
    charts.writeChart({.csv = out / "ble_curve.csv", .x = "speed_km_s", .series = series,
                       .xlabel = "impact speed [km/s]", .ylabel = "projectile diameter [mm]",
                       .title = title + ": ballistic limit", .out = out / "limit.png"});
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace

int whippleLimitCommand(const WhippleLimitArgs& args) {
  const SceneText scene = readSceneArgument(args.scene);
  coupling::LimitSearchOptions o;
  o.speeds = quantities(args.speeds, Dimension::Velocity, "--speeds");
  const std::vector<double> bracket = quantities(args.diameters, Dimension::Length, "--diameters");
  if (bracket.size() != 2 || !(bracket[0] < bracket[1]))
    throw std::runtime_error("--diameters: give two, the smaller first (e.g. \"2 mm,12 mm\")");
  o.smallest = bracket[0];
  o.largest = bracket[1];
  o.iterations = args.iterations;
  o.overrides = args.overrides;
  o.threads = args.threads;
  if (!args.wallYield.empty()) o.wallYield = parseQuantity(args.wallYield, Dimension::Pressure);
  const Scene parsed = parseScene(scene.text, scene.label, args.overrides);
  o.outDir = args.outDir.empty() ? fs::path("runs") / (parsed.name + "_limit") : fs::path(args.outDir);
  fs::create_directories(o.outDir);
  o.onShot = [](double speed, double d, bool perforated, double seconds) {
    if (seconds < 0.0)
      std::fprintf(stderr, "ejecta: %.4g km/s, %.4g mm: %s (run before; read back)\n", speed * 1e-3, d * 1e3,
                   perforated ? "perforated" : "held");
    else
      std::fprintf(stderr, "ejecta: %.4g km/s, %.4g mm: %s (%.1f s)\n", speed * 1e-3, d * 1e3,
                   perforated ? "perforated" : "held", seconds);
  };
  const coupling::LimitSearchResult r = coupling::searchBallisticLimits(scene.text, scene.label, o);
  writeFileAtomically(o.outDir / "limits.csv", coupling::limitsCsv(r));
  writeFileAtomically(o.outDir / "shots.csv", coupling::shotsCsv(r));
  const std::string noChart = args.charts ? drawLimitChart(o.outDir, r, parsed.name) : "";
  if (!noChart.empty()) std::fprintf(stderr, "ejecta whipple-limit: no limit.png: %s\n", noChart.c_str());

  std::printf("ejecta whipple-limit: %s, %zu shots (bumper %.3g mm, wall %.3g mm, standoff %.4g mm, "
              "wall yield %.3g MPa, %.3g deg)\n", parsed.name.c_str(), r.shots.size(),
              r.shield.bumperThickness * 1e3, r.shield.wallThickness * 1e3, r.shield.standoff * 1e3,
              r.shield.wallYieldStress * 1e-6, r.impactAngle * 180.0 / 3.14159265358979323846);
  std::printf("  %-10s %-22s %-14s %-22s\n", "speed", "critical diameter (SPH)", "BLE", "SPH / BLE");
  for (const coupling::SpeedLimit& l : r.limits) {
    char sph[64], ratio[32] = "-";
    if (l.critical)
      std::snprintf(sph, sizeof sph, "%.3g mm (%.3g-%.3g)", *l.critical * 1e3, *l.largestHeld * 1e3,
                    *l.smallestPerforating * 1e3);
    else if (l.smallestPerforating)
      std::snprintf(sph, sizeof sph, "below %.3g mm", *l.smallestPerforating * 1e3);
    else
      std::snprintf(sph, sizeof sph, "above %.3g mm", *l.largestHeld * 1e3);
    if (l.critical) std::snprintf(ratio, sizeof ratio, "%.2f", *l.critical / l.equations.diameter);
    char speed[32], ble[32];
    std::snprintf(speed, sizeof speed, "%.3g km/s", l.speed * 1e-3);
    std::snprintf(ble, sizeof ble, "%.3g mm", l.equations.diameter * 1e3);
    std::printf("  %-10s %-22s %-14s %-22s\n", speed, sph, ble, ratio);
  }
  std::printf("  outputs: %s/{limits.csv, shots.csv, ble_curve.csv%s, one run per shot}\n",
              o.outDir.string().c_str(), noChart.empty() && args.charts ? ", limit.png" : "");
  return 0;
}

}  // namespace ejecta::app
