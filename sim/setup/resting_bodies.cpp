#include "sim/setup/resting_bodies.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <unordered_map>
#include <vector>

#include "core/units.hpp"
#include "sim/setup/bodies.hpp"

namespace ejecta {

namespace {

using Point = std::array<double, 3>;

// How far the search runs each way, in the larger of the two bodies' spacings: a body placed by
// hand where it should rest is within a spacing or two of it.
constexpr double kSearchSpacings = 4.0;
// Steps of the scan, in gaps: a pair cannot close by more than a sixteenth of the gap between
// two tries, so the first contact is found to that, then bisected.
constexpr double kScanStepsPerGap = 16.0;
constexpr int kBisections = 60;
// Bounds on the work of placing a body: its own lattice points, and the other body's around it.
// A resting body is a device or an impactor, hundreds to thousands of particles; the bounds keep
// a scene reader given any text (it is fuzzed, 10 s per input under sanitizers) well under a
// second.
constexpr std::size_t kMaxRestingPoints = 50'000;
constexpr std::size_t kMaxNearbyPoints = 1'000'000;
constexpr long kMaxScanSteps = 10'000;
constexpr double kMaxPairTries = 2e6;  // its particles near the other body, times the tries
// A lattice point rebuilt with its moved shape matches the point moved by hand to rounding; a
// billionth of a spacing is far above that and far below any cut.
constexpr double kSamePoint = 1e-9;
constexpr double kRounding = 8.0 * std::numeric_limits<double>::epsilon();  // of a coordinate far out

// The other body's points hashed into cells one gap wide: "is any of them nearer than the gap"
// looks at the 3^d cells around a point.
class PointCells {
 public:
  PointCells(std::vector<Point> points, double cell, int dim) : points_(std::move(points)), cell_(cell), dim_(dim) {
    for (std::size_t j = 0; j < points_.size(); ++j) cells_[key(index(points_[j]))].push_back(j);
  }

  // Whether a point other than those `excluded` lies within `radius` (at most one cell) of x.
  template <typename Excluded>
  bool anyWithin(const Point& x, double radius, Excluded&& excluded) const {
    const std::array<long, 3> c = index(x);
    const long reach[3] = {1, dim_ >= 2 ? 1L : 0L, dim_ >= 3 ? 1L : 0L};
    for (long k = -reach[2]; k <= reach[2]; ++k)
      for (long j = -reach[1]; j <= reach[1]; ++j)
        for (long i = -reach[0]; i <= reach[0]; ++i) {
          const auto found = cells_.find(key({c[0] + i, c[1] + j, c[2] + k}));
          if (found == cells_.end()) continue;
          for (std::size_t n : found->second) {
            double r2 = 0.0;
            for (int d = 0; d < dim_; ++d) r2 += (points_[n][d] - x[d]) * (points_[n][d] - x[d]);
            if (r2 < radius * radius && !excluded(points_[n])) return true;
          }
        }
    return false;
  }

 private:
  std::array<long, 3> index(const Point& x) const {
    std::array<long, 3> c{0, 0, 0};
    // Clamped: a coordinate far from the origin must not overflow the cast (cells that far
    // share an index, which costs distance tests, not answers).
    for (int d = 0; d < dim_; ++d) c[d] = static_cast<long>(std::clamp(std::floor(x[d] / cell_), -1e15, 1e15));
    return c;
  }
  static std::uint64_t key(const std::array<long, 3>& c) {
    // 21 bits per axis: cells 2^21 apart share a key, which costs distance tests, not answers.
    const auto bits = [](long v) { return static_cast<std::uint64_t>(v) & 0x1FFFFFu; };
    return bits(c[0]) | (bits(c[1]) << 21) | (bits(c[2]) << 42);
  }

  std::vector<Point> points_;
  double cell_;
  int dim_;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells_;
};

ShapeSpec moved(ShapeSpec shape, const Point& direction, double distance, int dim) {
  for (int d = 0; d < dim; ++d) {
    const double dx = distance * direction[d];
    shape.center[d] += dx;
    shape.min[d] += dx;
    shape.max[d] += dx;
  }
  return shape;
}

// Every lattice point body `index` makes, as the build makes them (no window).
std::vector<Point> everyLatticePoint(const Scene& scene, std::size_t index) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  return bodyLatticePoints(scene, index, {-kInf, -kInf, -kInf}, {kInf, kInf, kInf},
                           scene.bodies.size(), kMaxRestingPoints);
}

std::string length(double metres) { return formatQuantity(metres, Dimension::Length); }

void placeOne(Scene& scene, std::size_t index) {
  BodySpec& body = scene.bodies[index];
  const int dim = spatialDimension(scene.geometry);
  const std::string key = bodyContext(scene, index, "rest_on");
  std::size_t target = scene.bodies.size();
  for (std::size_t k = 0; k < scene.bodies.size(); ++k)
    if (scene.bodies[k].name == body.restOn) target = k;
  if (target == scene.bodies.size()) {
    for (const VoidSpec& v : scene.voids)
      if (v.name == body.restOn)
        throw SceneError(key + ": '" + body.restOn + "' is a void body: it has no particles to rest on");
    throw SceneError(key + ": no body named '" + body.restOn + "'");
  }
  if (target == index) throw SceneError(key + ": a body cannot rest on itself");
  if (target < index)
    throw SceneError(key + ": list it before '" + body.restOn +
                     "' (earlier bodies win where shapes overlap, so the body that rests must claim its place)");
  // Each is placed against the other's particles as they stand, so one that moves afterwards
  // would leave the first resting on nothing (or inside it).
  if (!scene.bodies[target].restOn.empty())
    throw SceneError(key + ": '" + body.restOn + "' rests on a body itself; a chain of resting bodies is not supported");
  for (std::size_t k = 0; k < index; ++k)
    if (scene.bodies[k].restOn == body.restOn)
      throw SceneError(key + ": '" + scene.bodies[k].name + "' rests on '" + body.restOn +
                       "' already; one body may rest on another");
  const BodySpec& under = scene.bodies[target];
  const double gap = body.restGap * body.spacing;
  const double range = kSearchSpacings * std::max(body.spacing, under.spacing);
  const double step = gap / kScanStepsPerGap;
  const long steps = static_cast<long>(std::ceil(2.0 * range / step));
  if (steps > kMaxScanSteps)
    throw SceneError(key + ": its spacing (" + length(body.spacing) + ") is too fine beside '" + body.restOn +
                     "''s (" + length(under.spacing) + ") to search for its rest");

  std::vector<Point> own, nearby;
  try {
    own = everyLatticePoint(scene, index);
    if (own.empty()) throw SceneError("the body makes no particles where it is placed");
    Point lo = own.front(), hi = own.front();
    for (const Point& x : own)
      for (int d = 0; d < dim; ++d) lo[d] = std::min(lo[d], x[d]), hi[d] = std::max(hi[d], x[d]);
    const double margin = range + gap + under.spacing;
    for (int d = 0; d < dim; ++d) lo[d] -= margin, hi[d] += margin;
    // The other body's particles near the path, as they are built but for this body's claim
    // (which moves with it: those inside its moved shape are left out at each try).
    nearby = bodyLatticePoints(scene, target, lo, hi, index, kMaxNearbyPoints);
  } catch (const SceneError& e) {
    throw SceneError(key + ": placing it: " + e.what());
  }
  const std::vector<Point> placed = own;
  // Only its particles that pass within reach of the other body's can meet them: the rest are
  // left out of every try (a coarse look, cells as wide as the reach).
  const double reach = range + gap;
  const PointCells coarse(nearby, reach, dim);
  std::erase_if(own, [&](const Point& x) { return !coarse.anyWithin(x, reach, [](const Point&) { return false; }); });
  if (static_cast<double>(own.size()) * static_cast<double>(steps + kBisections) > kMaxPairTries)
    throw SceneError(key + ": too many of its particles (" + std::to_string(own.size()) +
                     ") near '" + body.restOn + "' to search for its rest; place it by its coordinates");
  const PointCells cells(std::move(nearby), gap, dim);

  const Point& dir = body.restDirection;
  const auto shifted = [&](const Point& x, double t) {
    Point y = x;
    for (int d = 0; d < dim; ++d) y[d] += t * dir[d];
    return y;
  };
  const auto meets = [&](double t) {
    const ShapeSpec shape = moved(body.shape, dir, t, dim);
    const auto claimed = [&](const Point& x) { return insideShape(shape, x, dim); };
    for (const Point& x : own)
      if (cells.anyWithin(shifted(x, t), gap, claimed)) return true;
    return false;
  };
  // Where the search starts, no particle of it may be within the gap of the other's, nor inside
  // the other body (a body set into another is not resting on it).
  bool inside = false;
  for (const Point& x : own) inside = inside || bodyOwnsPoint(scene, target, shifted(x, -range), index);
  if (inside || meets(-range))
    throw SceneError(key + ": it is within the gap (" + length(gap) + ") of '" + body.restOn +
                     "', or inside it, even " + length(range) +
                     " back against rest_direction: place it clear of that body, where it would rest");
  double free = -range, touching = free;
  bool met = false;
  for (long k = 1; k <= steps; ++k) {
    const double t = -range + static_cast<double>(k) * step;
    if (meets(t)) {
      touching = t;
      met = true;
      break;
    }
    free = t;
  }
  if (!met)
    throw SceneError(key + ": meets nothing of '" + body.restOn + "' within " + length(range) +
                     " along rest_direction of where it is placed");
  for (int k = 0; k < kBisections; ++k) {
    const double mid = 0.5 * (free + touching);
    (meets(mid) ? touching : free) = mid;
  }
  body.shape = moved(body.shape, dir, free, dim);
  body.restMove = free;
  // Its lattice moved with it; what the build makes there must be those same points, moved (a
  // domain face, an earlier body or a void it moved against would cut it differently).
  const std::vector<Point> resting = everyLatticePoint(scene, index);
  bool same = resting.size() == placed.size();
  for (std::size_t k = 0; same && k < resting.size(); ++k)
    for (int d = 0; d < dim; ++d)
      same = same && std::abs(resting[k][d] - shifted(placed[k], free)[d]) <=
                         kSamePoint * body.spacing + kRounding * std::abs(resting[k][d]);
  if (!same)
    throw SceneError(key + ": at its rest (moved " + length(free) + ") a domain face, an earlier body or a void "
                     "cuts it differently than where it was placed; place it clear of them");
}

}  // namespace

void placeRestingBodies(Scene& scene) {
  for (std::size_t i = 0; i < scene.bodies.size(); ++i)
    if (!scene.bodies[i].restOn.empty()) placeOne(scene, i);
}

}  // namespace ejecta
