#include "fields/shield_outputs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "core/csv.hpp"
#include "fields/history_csv.hpp"

namespace fs = std::filesystem;

namespace ejecta::fields {

namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;

std::string reasonOf(const WallState& w) {
  if (w.hole && w.resolvedBehind) return "hole and material behind the wall";
  if (w.hole) return "hole";
  if (w.resolvedBehind && w.wallMassBehind == w.massBehind) return "detached spall";
  if (w.resolvedBehind) return "material behind the wall";
  return "intact";
}

// What a restarted run takes over from the rows of its history before the restart: the peak
// deflection of the steps before it and the first output at which the wall was perforated.
struct EarlierRows {
  double peak = 0.0;
  std::optional<double> firstPerforated;
};

double cellNumber(const std::string& cell, const std::string& row) {
  double v = 0.0;
  if (!parseCsvNumber(cell, v))
    throw std::runtime_error("shield_history.csv: '" + cell + "' is not a number, in the row '" +
                             row + "'");
  return v;
}

EarlierRows earlierRows(const std::vector<std::string>& rows) {
  EarlierRows e;
  for (const std::string& row : rows) {
    std::stringstream in(row);
    std::string time, perforated, cell;
    std::getline(in, time, ',');
    std::getline(in, perforated, ',');
    for (int c = 2; c < 8; ++c) std::getline(in, cell, ',');  // ends on peak_deflection_m
    e.peak = std::max(e.peak, cellNumber(cell, row));
    if (perforated == "1" && !e.firstPerforated) e.firstPerforated = cellNumber(time, row);
  }
  return e;
}

}  // namespace

std::string shieldHistoryHeader() {
  return "time_s,perforated,hole_diameter_m,hole_area_m2,mass_behind_kg,wall_mass_behind_kg,"
         "deflection_m,peak_deflection_m,cloud_mass_kg,cloud_momentum_kg_m_s,"
         "cloud_lateral_momentum_kg_m_s,cloud_leading_edge_m,cloud_leading_speed_m_s,"
         "cloud_radius_m,cloud_half_angle_deg,cloud_mass_on_wall_kg";
}

std::string shieldHistoryRow(double time, const WallState& w, double peak, const DebrisCloud& c) {
  const auto n = shortestNumber;
  return n(time) + ',' + (w.perforated() ? "1" : "0") + ',' + n(w.holeDiameter) + ',' +
         n(w.holeArea) + ',' + n(w.massBehind) + ',' + n(w.wallMassBehind) + ',' + n(w.deflection) +
         ',' + n(peak) + ',' + n(c.mass) + ',' + n(c.momentum) + ',' + n(c.lateralMomentum) + ',' +
         n(c.leadingEdge) + ',' + n(c.leadingSpeed) + ',' + n(c.radius) + ',' +
         n(c.halfAngle / kDegree) + ',' + n(c.massOnWall);
}

std::string describeVerdict(const ShieldSummary& s) {
  char buf[256];
  if (!s.perforated) {
    std::snprintf(buf, sizeof buf, "not perforated: the wall '%s' holds (rear face deflected %.3g mm at most)",
                  s.wallName.c_str(), s.peakDeflection * 1e3);
    std::string text = buf;
    if (s.wall.massBehind > 0.0) {
      std::snprintf(buf, sizeof buf, "; %.3g g shed behind it, below the resolution", s.wall.massBehind * 1e3);
      text += buf;
    }
    return text;
  }
  std::string text = "perforated (" + s.reason + ")";
  if (s.wall.hole) {
    std::snprintf(buf, sizeof buf, ": a hole %.3g mm across", s.wall.holeDiameter * 1e3);
    text += buf;
  }
  if (s.wall.resolvedBehind) {
    std::snprintf(buf, sizeof buf, "%s%.3g g behind the wall (%.3g g of it the wall's own)",
                  s.wall.hole ? ", " : ": ", s.wall.massBehind * 1e3, s.wall.wallMassBehind * 1e3);
    text += buf;
  }
  if (s.firstPerforated) {
    std::snprintf(buf, sizeof buf, "; first seen at %.3g us", *s.firstPerforated * 1e6);
    text += buf;
  }
  return text;
}

void addToSummary(const ShieldSummary& s, RunSummary& summary) {
  auto& e = summary.extras;
  e.push_back({"shield_wall", s.wallName});
  e.push_back({"shield_perforated", s.perforated});
  e.push_back({"shield_verdict", std::string(s.perforated ? "P" : "NP")});
  e.push_back({"shield_reason", s.reason});
  e.push_back({"shield_hole", s.wall.hole});
  e.push_back({"shield_hole_diameter_m", s.wall.holeDiameter});
  e.push_back({"shield_mass_behind_wall_kg", s.wall.massBehind});
  e.push_back({"shield_wall_mass_behind_kg", s.wall.wallMassBehind});
  e.push_back({"shield_behind_resolved", s.wall.resolvedBehind});
  e.push_back({"shield_deflection_m", s.wall.deflection});
  e.push_back({"shield_peak_deflection_m", s.peakDeflection});
  if (s.firstPerforated) e.push_back({"shield_first_perforated_s", *s.firstPerforated});
  e.push_back({"shield_cloud_mass_kg", s.cloud.mass});
  e.push_back({"shield_cloud_momentum_kg_m_s", s.cloud.momentum});
  e.push_back({"shield_cloud_lateral_momentum_kg_m_s", s.cloud.lateralMomentum});
  e.push_back({"shield_cloud_leading_edge_m", s.cloud.leadingEdge});
  e.push_back({"shield_cloud_leading_speed_m_s", s.cloud.leadingSpeed});
  e.push_back({"shield_cloud_radius_m", s.cloud.radius});
  e.push_back({"shield_cloud_half_angle_deg", s.cloud.halfAngle / kDegree});
  e.push_back({"shield_cloud_mass_on_wall_kg", s.cloud.massOnWall});
}

void addShieldOutputs(RunOptions& options, const Scene& scene,
                      std::function<void(const ShieldSummary&)> onShield) {
  const std::optional<ShieldFrame> found = shieldFrameFromScene(scene);
  if (!found) return;
  const ShieldFrame frame = *found;
  struct Tracking {
    std::optional<HistoryCsv> history;
    double peak = 0.0;           // over the outputs so far (rank 0)
    bool started = false;
    std::optional<double> firstPerforated;
  };
  auto tracking = std::make_shared<Tracking>();
  const fs::path historyFile = options.outDir.empty() ? fs::path() : fs::path(options.outDir) / "shield_history.csv";
  const std::string kind = "shield history";
  if (!historyFile.empty()) tracking->history.emplace(historyFile, shieldHistoryHeader(), kind);

  // The wall and the cloud at every output, measured on every rank's particles at rank 0.
  auto measure = [frame](const Simulation& sim, WallState& wall, DebrisCloud& cloud) {
    const ParticleSet& all = sim.gatheredParticles();
    if (!sim.ranks().isRoot()) return;
    wall = measureWall(all, frame);
    cloud = measureDebrisCloud(all, frame);
  };
  auto previousOutput = options.onOutput;
  options.onOutput = [=](const Simulation& sim, const SnapshotInfo& info, bool final) {
    if (previousOutput) previousOutput(sim, info, final);
    WallState wall;
    DebrisCloud cloud;
    measure(sim, wall, cloud);
    if (!sim.ranks().isRoot()) return;
    if (!tracking->started) {
      tracking->started = true;
      // A restart: the peak and the first perforation of the steps before it are in the rows
      // the history keeps from then (a fresh run at t = 0 keeps none).
      if (tracking->history && info.time > 0.0) {
        const EarlierRows e = earlierRows(readHistoryRows(historyFile, shieldHistoryHeader(), kind, info.time));
        tracking->peak = std::max(tracking->peak, e.peak);
        tracking->firstPerforated = e.firstPerforated;
      }
    }
    if (wall.perforated() && !tracking->firstPerforated) tracking->firstPerforated = info.time;
    tracking->peak = std::max(tracking->peak, wall.deflection);
    if (tracking->history)
      tracking->history->record(info.time, shieldHistoryRow(info.time, wall, tracking->peak, cloud));
  };

  auto previousFinish = options.onFinish;
  options.onFinish = [=](const Simulation& sim, RunSummary& summary) {
    if (previousFinish) previousFinish(sim, summary);
    ShieldSummary s;
    measure(sim, s.wall, s.cloud);
    if (!sim.ranks().isRoot()) return;
    s.wallName = frame.wallName;
    s.perforated = s.wall.perforated();
    s.reason = reasonOf(s.wall);
    s.peakDeflection = std::max(tracking->peak, s.wall.deflection);
    s.firstPerforated = tracking->firstPerforated;
    if (s.perforated && !s.firstPerforated) s.firstPerforated = sim.time();
    addToSummary(s, summary);
    if (onShield) onShield(s);
  };
}

}  // namespace ejecta::fields
