#include "coupling/ballistic_limit_search.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "core/csv.hpp"
#include "fields/shield_outputs.hpp"
#include "sim/run/run.hpp"
#include "sim/solid/strength_library.hpp"

namespace fs = std::filesystem;

namespace ejecta::coupling {

namespace {

const BodySpec& bodyNamed(const Scene& scene, const std::string& name) {
  for (const BodySpec& b : scene.bodies)
    if (b.name == name) return b;
  throw SceneError(scene.sourcePath + ": [shield]: no body named '" + name + "'");
}

std::size_t projectileIndex(const Scene& scene) {
  std::size_t best = scene.bodies.size();
  double fastest = 0.0;
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    const auto& v = scene.bodies[b].velocity;
    const double speed = std::hypot(v[0], v[1], v[2]);
    if (speed > fastest) fastest = speed, best = b;
  }
  if (best == scene.bodies.size()) throw SceneError(scene.sourcePath + ": no body moves: no projectile");
  if (scene.bodies[best].shape.kind != ShapeKind::Sphere)
    throw SceneError(scene.sourcePath + ": the projectile '" + scene.bodies[best].name +
                     "' must be a sphere for its diameter to be varied");
  return best;
}

// The wall material's yield stress: Johnson-Cook's A (its own or its library entry's), or the
// von Mises yield stress.
std::optional<double> wallYieldOf(const Scene& scene, const BodySpec& wall) {
  const ModelSpec& s = scene.materials[static_cast<std::size_t>(wall.material)].strength;
  if (s.model == "johnson_cook") {
    if (const double* a = s.find("A")) return *a;
    if (const StrengthLibraryEntry* e = findStrengthEntry(s.library)) return e->johnsonCook.A;
  }
  if (s.model == "von_mises")
    if (const double* y = s.find("yield_stress")) return *y;
  return std::nullopt;
}

std::string number(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

std::string vectorValue(const std::array<double, 3>& v, int dims) {
  std::string s = "[";
  for (int d = 0; d < dims; ++d) s += (d ? ", " : "") + number(v[d]);
  return s + "]";
}

// The overrides that put a sphere of diameter d at `speed` along the original path, its front
// half a spacing from the first plate.
std::vector<std::string> shotOverrides(const Scene& scene, std::size_t k, const fields::ShieldFrame& f,
                                       double diameter, double speed) {
  const BodySpec& p = scene.bodies[k];
  const auto& v = p.velocity;
  const double v0 = std::hypot(v[0], v[1], v[2]);
  const std::array<double, 3> dir = {v[0] / v0, v[1] / v0, v[2] / v0};
  const double cosine = std::abs(dir[f.normalAxis]);
  const double r = 0.5 * diameter;
  const double back = (r + 0.5 * p.spacing) / cosine;
  const std::array<double, 3> centre = {f.shotPoint[0] - dir[0] * back, f.shotPoint[1] - dir[1] * back,
                                        f.shotPoint[2] - dir[2] * back};
  const std::array<double, 3> velocity = {dir[0] * speed, dir[1] * speed, dir[2] * speed};
  const int dims = spatialDimension(scene.geometry);
  const std::string body = "bodies[" + std::to_string(k) + "].";
  return {body + "radius=" + number(r), body + "center=" + vectorValue(centre, dims),
          body + "velocity=" + vectorValue(velocity, dims)};
}

std::string shotName(double speed, double diameter) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "v%.4gkms_d%.4gmm", speed * 1e-3, diameter * 1e3);
  return buf;
}

// A shot already run into `dir` (its summary.json holds a verdict): read back.
std::optional<LimitShot> readShot(const fs::path& dir, double speed, double diameter) {
  std::ifstream in(dir / "summary.json");
  if (!in) return std::nullopt;
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    if (j.value("status", "") != "completed") return std::nullopt;
    const nlohmann::json& e = j.at("extras");
    LimitShot s{speed, diameter, e.at("shield_perforated").get<bool>(), e.at("shield_reason").get<std::string>(), 0.0};
    return s;
  } catch (const std::exception&) {
    return std::nullopt;  // half written or another kind of run: run it again
  }
}

}  // namespace

radiation::WhippleShield shieldOfScene(const Scene& scene, std::optional<double> wallYield) {
  const std::optional<fields::ShieldFrame> f = fields::shieldFrameFromScene(scene);
  if (!f || !f->bumperRear)
    throw SceneError(scene.sourcePath + ": a ballistic limit needs a [shield] table naming the wall and the bumper");
  const BodySpec& wall = bodyNamed(scene, f->wallName);
  const BodySpec& bumper = bodyNamed(scene, f->bumperName);
  const int n = f->normalAxis;
  radiation::WhippleShield s;
  s.bumperThickness = bumper.shape.max[n] - bumper.shape.min[n];
  s.bumperDensity = bumper.density;
  s.wallThickness = f->wallRear - f->wallFront;
  s.wallDensity = wall.density;
  s.standoff = f->wallFront - *f->bumperRear;
  const std::optional<double> yield = wallYield ? wallYield : wallYieldOf(scene, wall);
  if (!yield)
    throw SceneError(scene.sourcePath + ": the wall's material '" +
                     scene.materials[static_cast<std::size_t>(wall.material)].name +
                     "' has no Johnson-Cook A or von Mises yield stress for the ballistic-limit "
                     "equations: give the yield stress (--wall-yield)");
  s.wallYieldStress = *yield;
  return s;
}

LimitSearchResult searchBallisticLimits(const std::string& sceneText, const std::string& label,
                                        const LimitSearchOptions& o) {
  if (!(o.smallest > 0.0) || !(o.largest > o.smallest))
    throw std::invalid_argument("whipple-limit: the diameters must satisfy 0 < smallest < largest");
  if (o.speeds.empty()) throw std::invalid_argument("whipple-limit: no speeds");
  if (o.iterations < 0) throw std::invalid_argument("whipple-limit: the iterations must be 0 or more");
  const Scene base = parseScene(sceneText, label, o.overrides);
  const std::size_t k = projectileIndex(base);
  const std::optional<fields::ShieldFrame> frame = fields::shieldFrameFromScene(base);
  LimitSearchResult result;
  result.shield = shieldOfScene(base, o.wallYield);
  result.projectileDensity = base.bodies[k].density;
  const auto& v = base.bodies[k].velocity;
  result.impactAngle = std::acos(std::abs(v[frame->normalAxis]) / std::hypot(v[0], v[1], v[2]));

  auto shoot = [&](double speed, double diameter) {
    const fs::path dir = o.outDir / shotName(speed, diameter);
    if (std::optional<LimitShot> done = readShot(dir, speed, diameter)) {
      if (o.onShot) o.onShot(speed, diameter, done->perforated, -1.0);
      result.shots.push_back(*done);
      return done->perforated;
    }
    std::vector<std::string> overrides = o.overrides;
    for (std::string& s : shotOverrides(base, k, *frame, diameter, speed)) overrides.push_back(std::move(s));
    RunOptions run;
    run.outDir = dir.string();
    run.threads = o.threads;
    run.sceneSource = sceneText;
    run.overrides = overrides;
    run.configure = [](const Scene& s, RunOptions& ro) { fields::addShieldOutputs(ro, s); };
    fs::create_directories(dir);
    const RunOutcome r = runScene(parseScene(sceneText, label, overrides), run);
    if (!r.ok)
      throw std::runtime_error(label + ": the shot at " + shotName(speed, diameter) + " failed: " + r.error +
                               " (" + dir.string() + ")");
    LimitShot shot{speed, diameter, r.summary.flag("shield_perforated"), r.summary.text("shield_reason"),
                   r.summary.wallSeconds};
    if (o.onShot) o.onShot(speed, diameter, shot.perforated, shot.wallSeconds);
    result.shots.push_back(shot);
    return shot.perforated;
  };

  for (double speed : o.speeds) {
    SpeedLimit limit;
    limit.speed = speed;
    limit.equations = radiation::criticalDiameter(result.shield, result.projectileDensity, speed, result.impactAngle);
    double held = o.smallest, perforating = o.largest;
    const bool smallPerforates = shoot(speed, held);
    const bool largePerforates = smallPerforates || shoot(speed, perforating);
    if (smallPerforates) {
      limit.smallestPerforating = held;  // the limit lies below the bracket
    } else if (!largePerforates) {
      limit.largestHeld = perforating;   // above it
    } else {
      for (int i = 0; i < o.iterations; ++i) {
        // Bisect in log d: the bracket may span a decade.
        const double mid = std::sqrt(held * perforating);
        (shoot(speed, mid) ? perforating : held) = mid;
      }
      limit.largestHeld = held;
      limit.smallestPerforating = perforating;
      limit.critical = std::sqrt(held * perforating);
    }
    result.limits.push_back(limit);
  }
  return result;
}

std::string limitsCsv(const LimitSearchResult& r) {
  CsvWriter csv({"speed_m_s", "largest_held_m", "smallest_perforating_m", "critical_m",
                 "ble_critical_m", "ble_regime", "critical_over_ble"});
  for (const SpeedLimit& l : r.limits) {
    csv.number(l.speed);
    l.largestHeld ? csv.number(*l.largestHeld) : csv.text("");
    l.smallestPerforating ? csv.number(*l.smallestPerforating) : csv.text("");
    l.critical ? csv.number(*l.critical) : csv.text("");
    csv.number(l.equations.diameter).text(radiation::regimeName(l.equations.regime));
    l.critical ? csv.number(*l.critical / l.equations.diameter) : csv.text("");
    csv.endRow();
  }
  return csv.str();
}

std::string shotsCsv(const LimitSearchResult& r) {
  CsvWriter csv({"speed_m_s", "diameter_m", "perforated", "reason", "wall_seconds"});
  for (const LimitShot& s : r.shots)
    csv.number(s.speed).number(s.diameter).flag(s.perforated).text(s.reason).number(s.wallSeconds).endRow();
  return csv.str();
}

}  // namespace ejecta::coupling
