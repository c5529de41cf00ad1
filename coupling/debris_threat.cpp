#include "coupling/debris_threat.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/csv.hpp"
#include "radiation/geometry_file.hpp"

namespace ejecta::coupling {

namespace {

using radiation::Vec3;

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// The body's reach from its origin: the farthest vertex of its mesh.
double boundingRadius(const radiation::ThermalStudy& study) {
  const radiation::TriangleMesh body = radiation::buildShape(study.spacecraft.body, study.source);
  double r2 = 0.0;
  for (const Vec3& v : body.vertices) r2 = std::max(r2, dot(v, v));
  return std::sqrt(r2);
}

}  // namespace

DebrisThreat assessDebrisThreat(const fields::FragmentCensus& census,
                                const radiation::ThermalStudy& follower,
                                const std::optional<radiation::WhippleShield>& shield,
                                const radiation::WhippleOptions& options) {
  const Geometry g = census.geometry;
  if (g != Geometry::Spatial && g != Geometry::Axisymmetric)
    throw std::invalid_argument("debris threat: the spacecraft flies in 3D or along an RZ run's axis; "
                                "a " + std::string(geometryName(g)) + " run has neither");
  const radiation::ApproachSpec& a = follower.approach;
  const bool rz = g == Geometry::Axisymmetric;
  if (rz && (a.start[0] != 0.0 || a.start[2] != 0.0 || a.velocity[0] != 0.0 || a.velocity[2] != 0.0))
    throw std::invalid_argument(follower.source + ": an RZ run's debris is met only by a pass along "
                                "its axis (the study's y axis): start and velocity must have x = z = 0");
  const double speed = std::sqrt(dot(a.velocity, a.velocity));
  if (!(speed > 0.0)) throw std::invalid_argument(follower.source + ": the approach has no speed");
  const Vec3 forward = {a.velocity[0] / speed, a.velocity[1] / speed, a.velocity[2] / speed};

  DebrisThreat threat;
  threat.passDuration = a.duration;
  threat.spacecraftRadius = boundingRadius(follower);
  threat.shieldGiven = shield.has_value();
  for (std::size_t k = 0; k < census.fragments.size(); ++k) {
    const fields::Fragment& f = census.fragments[k];
    // Relative position and velocity of the fragment seen from the spacecraft's centre; in RZ
    // in the meridional plane (r, y), the spacecraft on the axis at r = 0.
    const Vec3 x = rz ? Vec3{f.center[0], f.center[1], 0.0} : Vec3{f.center[0], f.center[1], f.center[2]};
    const Vec3 v = rz ? Vec3{f.velocity[0], f.velocity[1], 0.0} : Vec3{f.velocity[0], f.velocity[1], f.velocity[2]};
    const Vec3 d0 = {x[0] - a.start[0], x[1] - a.start[1], x[2] - a.start[2]};
    const Vec3 w = {v[0] - a.velocity[0], v[1] - a.velocity[1], v[2] - a.velocity[2]};
    const double w2 = dot(w, w);
    const double t = w2 > 0.0 ? std::clamp(-dot(d0, w) / w2, 0.0, a.duration) : 0.0;
    const Vec3 d = {d0[0] + w[0] * t, d0[1] + w[1] * t, d0[2] + w[2] * t};
    const double miss = std::sqrt(dot(d, d));
    if (miss >= threat.spacecraftRadius + 0.5 * f.diameter) continue;
    Encounter e;
    e.fragment = k;
    e.time = t;
    e.missDistance = miss;
    e.speed = std::sqrt(w2);
    // The angle between the fragment's path relative to the spacecraft and the leading face's
    // normal (the flight direction): 0 for a head-on strike.
    e.angle = e.speed > 0.0 ? std::acos(std::clamp(-dot(w, forward) / e.speed, -1.0, 1.0)) : 0.0;
    e.diameter = f.diameter;
    e.mass = f.mass;
    e.density = f.volume > 0.0 ? f.mass / f.volume : 0.0;
    e.resolved = f.resolved;
    // The BLE hold for strikes on the shield's face: from ahead (angles below 90 degrees).
    if (shield && e.speed > 0.0 && e.angle < 0.5 * 3.14159265358979323846 && e.density > 0.0) {
      e.limit = radiation::criticalDiameter(*shield, e.density, e.speed, e.angle, options);
      e.perforates = e.diameter > e.limit->diameter;
      e.requiredWall = radiation::requiredWallThickness(*shield, e.density, e.diameter, e.speed, e.angle, options);
      threat.perforating += e.perforates;
      threat.perforatingResolved += e.perforates && e.resolved;
      threat.requiredWall = std::max(threat.requiredWall, e.requiredWall);
      if (e.resolved) threat.requiredWallResolved = std::max(threat.requiredWallResolved, e.requiredWall);
    }
    threat.encounters.push_back(e);
  }
  std::stable_sort(threat.encounters.begin(), threat.encounters.end(),
                   [](const Encounter& p, const Encounter& q) { return p.time < q.time; });
  return threat;
}

std::string encountersCsv(const DebrisThreat& threat) {
  CsvWriter csv({"fragment", "time_s", "miss_distance_m", "speed_m_s", "angle_deg", "diameter_m",
                 "mass_kg", "density_kg_m3", "resolved", "critical_diameter_m", "perforates",
                 "required_wall_m"});
  for (const Encounter& e : threat.encounters) {
    csv.count(e.fragment).number(e.time).number(e.missDistance).number(e.speed)
        .number(e.angle * 180.0 / 3.14159265358979323846).number(e.diameter).number(e.mass)
        .number(e.density).flag(e.resolved);
    if (e.limit) csv.number(e.limit->diameter).flag(e.perforates).number(e.requiredWall);
    else csv.text("").text("").text("");
    csv.endRow();
  }
  return csv.str();
}

}  // namespace ejecta::coupling
