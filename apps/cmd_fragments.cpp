// `ejecta fragments INPUT [--out DIR] [--follower STUDY --shield SHIELD]`: the fragments of a
// snapshot (fields/fragments.hpp): fragments.csv, size_frequency.csv, speed_distribution.csv and
// their charts; with a follower study, the fragments the spacecraft meets on its approach, and
// with a Whipple shield, whether each perforates it (coupling/debris_threat.hpp,
// docs/fragments.md).
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "apps/commands.hpp"
#include "core/atomic_file.hpp"
#include "core/csv.hpp"
#include "coupling/debris_threat.hpp"
#include "coupling/snapshot_emitters.hpp"
#include "fields/fragment_outputs.hpp"
#include "radiation/whipple_study.hpp"
#include "render/charts.hpp"
#include "sim/io/snapshot.hpp"
#include "sim/io/snapshot_checks.hpp"
#include "sim/run/run.hpp"
#include "sim/setup/scene_catalog.hpp"

namespace fs = std::filesystem;

namespace ejecta::app {

namespace {

// The cumulative mass and count of fragments faster than each speed (fastest first).
std::string speedDistributionCsv(const fields::FragmentCensus& c) {
  std::vector<const fields::Fragment*> order;
  for (const fields::Fragment& f : c.fragments) order.push_back(&f);
  std::stable_sort(order.begin(), order.end(),
                   [](const fields::Fragment* a, const fields::Fragment* b) { return a->speed > b->speed; });
  CsvWriter csv({"speed_m_s", "count_at_least", "mass_at_least_kg", "mass_fraction_at_least"});
  double mass = 0.0;
  for (std::size_t k = 0; k < order.size(); ++k) {
    mass += order[k]->mass;
    if (k + 1 == order.size() || order[k + 1]->speed != order[k]->speed)
      csv.number(order[k]->speed).count(k + 1).number(mass).number(c.totalMass > 0 ? mass / c.totalMass : 0.0).endRow();
  }
  return csv.str();
}

// size_frequency.png and speed_distribution.png; returns why not, or "".
std::string drawCharts(const fs::path& out, const std::string& title, double resolutionLimit) {
  render::ChartRunner charts;
  if (!charts.chartsAvailable()) return charts.unavailableReason();
  char limit[32];
  std::snprintf(limit, sizeof limit, "%.3g m", resolutionLimit);
  try {
    charts.writeChart({.csv = out / "size_frequency.csv", .x = "diameter_m",
                       .series = {{.y = "count_at_least", .label = "all fragments (single particles included)"},
                                  {.y = "measured_count_at_least", .label = "fragments of measured size"}},
                       .xlog = true, .ylog = true, .xlabel = "equivalent diameter d [m]",
                       .ylabel = "N(>= d)",
                       .title = title + ": size-frequency",
                       .vlines = {{.y = resolutionLimit, .label = std::string("sizes below ") + limit + " are not measured"}},
                       .out = out / "size_frequency.png"});
    charts.writeChart({.csv = out / "speed_distribution.csv", .x = "speed_m_s",
                       .series = {{.y = "mass_fraction_at_least", .label = "mass at least this fast"}},
                       .ylog = true, .xlabel = "speed [m/s]", .ylabel = "mass fraction",
                       .title = title + ": speed distribution", .out = out / "speed_distribution.png"});
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace

int fragmentsCommand(const FragmentsArgs& args) {
  const std::string snapshot = coupling::resolveSnapshotPath(args.input);
  SnapshotInfo info;
  const ParticleSet particles = readSnapshot(snapshot, info);
  const Scene scene = storedScene(info, snapshot);
  checkSnapshotMaterials(particles, scene.materials.size(), snapshot);
  fields::FragmentOptions options = fields::fragmentOptions(scene.fragments);
  if (args.linkFactor) options.linkFactor = *args.linkFactor;
  if (args.damageThreshold) options.damageThreshold = *args.damageThreshold;
  if (args.resolvedSpacings) options.resolvedSpacings = *args.resolvedSpacings;
  const fields::FragmentCensus census = fields::identifyFragments(particles, scene.geometry, options);
  const fields::FragmentSummary summary = fields::summarizeFragments(census, options);

  std::vector<std::string> names;
  for (const MaterialSpec& m : scene.materials) names.push_back(m.name);
  const fs::path out = args.outDir.empty() ? fs::path(snapshot).parent_path().parent_path() / "fragments_analysis"
                                           : fs::path(args.outDir);
  fs::create_directories(out);
  writeFileAtomically(out / "fragments.csv", fields::fragmentsCsv(census, names));
  writeFileAtomically(out / "size_frequency.csv", fields::sizeFrequencyCsv(census));
  writeFileAtomically(out / "speed_distribution.csv", speedDistributionCsv(census));

  nlohmann::ordered_json json;
  json["snapshot"] = snapshot;
  json["time_s"] = info.time;
  json["fragments"] = summary.fragments;
  json["resolved"] = summary.resolved;
  json["single_failed_particles"] = summary.failedParticles;
  json["largest_mass_kg"] = summary.largestMass;
  json["largest_mass_fraction"] = summary.largestMassFraction;
  json["largest_diameter_m"] = summary.largestDiameter;
  json["resolution_limit_m"] = summary.resolutionLimit;
  json["fastest_resolved_speed_m_s"] = summary.fastestResolvedSpeed;

  std::optional<coupling::DebrisThreat> threat;
  if (!args.follower.empty()) {
    const SceneText study = readSceneArgument(args.follower, "thermal study");
    const radiation::ThermalStudy follower =
        radiation::parseThermalStudy(study.text, study.label, study.directory);
    std::optional<radiation::WhippleShield> shield;
    if (!args.shield.empty()) {
      const SceneText text = readSceneArgument(args.shield, "Whipple study");
      shield = radiation::parseWhippleStudy(text.text, text.label).shield;
    }
    threat = coupling::assessDebrisThreat(census, follower, shield);
    writeFileAtomically(out / "encounters.csv", coupling::encountersCsv(*threat));
    std::size_t resolvedMet = 0;
    double massMet = 0.0, fastest = 0.0;
    for (const coupling::Encounter& e : threat->encounters) {
      resolvedMet += e.resolved;
      massMet += e.mass;
      fastest = std::max(fastest, e.speed);
    }
    nlohmann::ordered_json t;
    t["follower"] = study.label;
    t["pass_duration_s"] = threat->passDuration;
    t["spacecraft_radius_m"] = threat->spacecraftRadius;
    t["encounters"] = threat->encounters.size();
    t["encounters_resolved"] = resolvedMet;
    t["mass_met_kg"] = massMet;
    t["fastest_relative_speed_m_s"] = fastest;
    if (shield) {
      t["shield"] = args.shield;
      t["perforating"] = threat->perforating;
      t["perforating_resolved"] = threat->perforatingResolved;
      t["required_wall_m"] = threat->requiredWall;
      t["required_wall_resolved_m"] = threat->requiredWallResolved;
    }
    json["follower"] = t;
  }
  writeFileAtomically(out / "fragments.json", json.dump(2) + "\n");
  const std::string noChart = args.charts ? drawCharts(out, scene.name, summary.resolutionLimit) : "";
  if (!noChart.empty()) std::fprintf(stderr, "ejecta fragments: no charts: %s\n", noChart.c_str());

  if (args.json) {
    std::printf("%s\n", json.dump(2).c_str());
    return 0;
  }
  std::printf("ejecta fragments: %s (t = %.4g s): %zu fragments, %zu of measured size, %zu single "
              "failed particles\n", snapshot.c_str(), info.time, summary.fragments, summary.resolved,
              summary.failedParticles);
  std::printf("  the largest: %.4g kg (%.3g%% of the mass), %.3g m across; sizes below %.3g m are not "
              "measured (%.3g spacings)\n", summary.largestMass, 100 * summary.largestMassFraction,
              summary.largestDiameter, summary.resolutionLimit, options.resolvedSpacings);
  if (threat) {
    std::printf("  follower: %zu fragment(s) met in the %.3g ms pass (spacecraft radius %.3g m)\n",
                threat->encounters.size(), threat->passDuration * 1e3, threat->spacecraftRadius);
    if (threat->shieldGiven)
      std::printf("  shield %s: %zu perforate it (%zu of measured size); a rear wall of %.3g mm stops "
                  "all of them (%.3g mm the measured ones)\n", args.shield.c_str(), threat->perforating,
                  threat->perforatingResolved, threat->requiredWall * 1e3, threat->requiredWallResolved * 1e3);
  }
  std::printf("  outputs: %s/{fragments.csv, size_frequency.csv, speed_distribution.csv, fragments.json%s}\n",
              out.string().c_str(), threat ? ", encounters.csv" : "");
  return 0;
}

}  // namespace ejecta::app
