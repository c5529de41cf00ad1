#include "fields/shield_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "fields/fragments.hpp"

namespace ejecta::fields {

namespace {

constexpr double kPi = 3.14159265358979323846;

const BodySpec& bodyNamed(const Scene& scene, const std::string& name) {
  for (const BodySpec& b : scene.bodies)
    if (b.name == name) return b;
  throw SceneError(scene.sourcePath + ": [shield]: no body named '" + name + "'");
}

std::array<double, 3> shapeCentre(const ShapeSpec& s) {
  if (s.kind == ShapeKind::Box)
    return {(s.min[0] + s.max[0]) / 2, (s.min[1] + s.max[1]) / 2, (s.min[2] + s.max[2]) / 2};
  if (s.kind == ShapeKind::HalfSpace) return s.point;
  return s.center;
}

// The wall's lateral columns: bins one spacing wide over its lateral extent (RZ: from the axis),
// of which the inner ones (two spacings clear of the edges, the axis excepted) are measured.
struct Columns {
  int count = 0;                        // lateral axes: 1 (RZ, planar) or 2 (3D)
  std::array<int, 2> axis{};
  std::array<double, 2> lo{}, hi{};     // extent [m]
  std::array<long, 2> bins{1, 1};
  std::array<long, 2> innerLo{}, innerHi{};  // inclusive
  double width = 0.0;

  explicit Columns(const ShieldFrame& f) : width(f.spacing) {
    const int dims = spatialDimension(f.geometry);
    for (int d = 0; d < dims; ++d)
      if (d != f.normalAxis) axis[count++] = d;
    const double margin = 2.0 * width;
    for (int k = 0; k < count; ++k) {
      lo[k] = f.wallMin[axis[k]];
      hi[k] = f.wallMax[axis[k]];
      if (f.geometry == Geometry::Axisymmetric) lo[k] = 0.0;
      bins[k] = std::max(1L, static_cast<long>(std::ceil((hi[k] - lo[k]) / width)));
      // The measured columns keep clear of free edges, not of the axis or a mirror plane.
      const bool openLow = f.geometry != Geometry::Axisymmetric && !f.mirrorLow[axis[k]];
      innerLo[k] = openLow ? static_cast<long>(std::ceil(margin / width)) : 0;
      innerHi[k] = bins[k] - 1 - (f.mirrorHigh[axis[k]] ? 0 : static_cast<long>(std::ceil(margin / width)));
    }
  }
  std::size_t size() const { return static_cast<std::size_t>(bins[0] * bins[1]); }
  double lateral(const ParticleSet& p, std::size_t i, int k) const { return p.x[axis[k]][i]; }
  long binOf(double q, int k) const { return static_cast<long>(std::floor((q - lo[k]) / width)); }
  double centre(long b, int k) const { return lo[k] + (static_cast<double>(b) + 0.5) * width; }
  bool inner(long b0, long b1) const {
    return b0 >= innerLo[0] && b0 <= innerHi[0] && (count < 2 || (b1 >= innerLo[1] && b1 <= innerHi[1]));
  }
  std::size_t index(long b0, long b1) const { return static_cast<std::size_t>(b1 * bins[0] + b0); }
  // Area of a column's cross-section [m^2]; RZ: the annulus; planar: its width [m].
  double area(long b0, Geometry g) const {
    if (g == Geometry::Axisymmetric) {
      const double r0 = lo[0] + static_cast<double>(b0) * width;
      return kPi * ((r0 + width) * (r0 + width) - r0 * r0);
    }
    return count == 2 ? width * width : width;
  }
};

bool isIntactWall(const ParticleSet& p, std::size_t i, const ShieldFrame& f) {
  return p.material[i] == f.wallMaterial && !(p.hasFracture() && p.damage(i) >= f.damageThreshold);
}

}  // namespace

int ShieldFrame::mirrorCopies() const {
  int copies = 1;
  for (int d = 0; d < 3; ++d) copies *= (mirrorLow[d] ? 2 : 1) * (mirrorHigh[d] ? 2 : 1);
  return copies;
}

std::optional<ShieldFrame> shieldFrameFromScene(const Scene& scene) {
  if (!scene.shield.enabled) return std::nullopt;
  const std::string where = scene.sourcePath + ": [shield]: ";
  ShieldFrame f;
  f.geometry = scene.geometry;
  f.damageThreshold = scene.shield.damageThreshold;
  const BodySpec& wall = bodyNamed(scene, scene.shield.wall);
  f.wallName = wall.name;
  f.wallMaterial = wall.material;
  f.wallMin = wall.shape.min;
  f.wallMax = wall.shape.max;
  f.spacing = wall.spacing;
  const int dims = spatialDimension(scene.geometry);
  // A plate is thin along its normal.
  f.normalAxis = 0;
  for (int d = 1; d < dims; ++d)
    if (f.wallMax[d] - f.wallMin[d] < f.wallMax[f.normalAxis] - f.wallMin[f.normalAxis]) f.normalAxis = d;
  // Mirror planes: a domain wall on a lateral face of the wall's box (planar and 3D).
  if (scene.geometry != Geometry::Axisymmetric)
    for (int d = 0; d < dims; ++d) {
      const AxisBounds& a = scene.domain[static_cast<std::size_t>(d)];
      if (d == f.normalAxis || !a.bounded) continue;
      f.mirrorLow[d] = a.lower == BoundaryKind::Wall && std::abs(a.min - f.wallMin[d]) < 0.5 * f.spacing;
      f.mirrorHigh[d] = a.upper == BoundaryKind::Wall && std::abs(a.max - f.wallMax[d]) < 0.5 * f.spacing;
    }
  if (scene.geometry == Geometry::Axisymmetric && f.normalAxis != 1)
    throw SceneError(where + "in RZ the wall must be a plate across the axis (thinner in z than in r)");
  if (scene.geometry == Geometry::Axisymmetric && f.wallMin[0] > 0.0)
    throw SceneError(where + "in RZ the wall must reach the axis (r min = 0)");
  const BodySpec* projectile = nullptr;
  auto speed = [](const BodySpec& b) { return std::hypot(b.velocity[0], b.velocity[1], b.velocity[2]); };
  for (const BodySpec& b : scene.bodies)
    if (speed(b) > 0.0 && (!projectile || speed(b) > speed(*projectile))) projectile = &b;
  if (!projectile || projectile->velocity[f.normalAxis] == 0.0)
    throw SceneError(where + "no body moves towards the wall's plane (the projectile's velocity "
                             "along the wall's normal is zero)");
  f.direction = projectile->velocity[f.normalAxis] > 0.0 ? 1.0 : -1.0;
  const int n = f.normalAxis;
  f.wallFront = std::min(f.direction * f.wallMin[n], f.direction * f.wallMax[n]);
  f.wallRear = std::max(f.direction * f.wallMin[n], f.direction * f.wallMax[n]);
  double firstFace = f.wallFront;
  if (!scene.shield.bumper.empty()) {
    const BodySpec& bumper = bodyNamed(scene, scene.shield.bumper);
    f.bumperName = bumper.name;
    f.bumperMaterial = bumper.material;
    const double a = f.direction * bumper.shape.min[n], b = f.direction * bumper.shape.max[n];
    f.bumperRear = std::max(a, b);
    firstFace = std::min(a, b);
    if (*f.bumperRear > f.wallFront)
      throw SceneError(where + "the bumper '" + bumper.name + "' is not in front of the wall '" +
                       wall.name + "' along the projectile's path");
  }
  // The projectile's centre carried along its velocity to the first plate's front face.
  const std::array<double, 3> c = shapeCentre(projectile->shape);
  const double vn = f.direction * projectile->velocity[n];
  const double t = (firstFace - f.direction * c[n]) / vn;
  for (int d = 0; d < 3; ++d) f.shotPoint[d] = c[d] + t * projectile->velocity[d];
  return f;
}

namespace {

// Which of the real particles of `material` belong to its largest piece of particles joined by
// overlapping kernels, whatever their damage: a plate's body, not a plug, a spalled layer or
// debris that has flown off it.
std::vector<char> largestPiece(const ParticleSet& p, int material, Geometry geometry) {
  ParticleSet own = p.withSameFields();
  for (std::size_t i = 0; i < p.numReal; ++i)
    if (p.material[i] == material)
      own.append({p.x[0][i], p.x[1][i], p.x[2][i]}, {p.v[0][i], p.v[1][i], p.v[2][i]}, p.mass[i], p.rho[i],
                 p.u[i], p.h[i], p.material[i]);
  own.numReal = own.size();
  std::vector<char> in(p.numReal, 0);
  if (own.numReal == 0) return in;
  FragmentOptions connected;
  connected.damageThreshold = std::numeric_limits<double>::infinity();
  const FragmentCensus pieces = identifyFragments(own, geometry, connected);
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.numReal; ++i)
    if (p.material[i] == material) in[i] = pieces.fragmentOf[k++] == 0;
  return in;
}

}  // namespace

double rearFaceDeflection(const ParticleSet& p, const ShieldFrame& f) {
  const std::vector<char> body = largestPiece(p, f.wallMaterial, f.geometry);
  // The rear face's first layer of particles sits half a spacing inside the face.
  const double layer = f.wallRear - 0.5 * f.spacing;
  double furthest = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < p.numReal; ++i)
    if (body[i] && isIntactWall(p, i, f)) furthest = std::max(furthest, f.s(p, i));
  return std::max(0.0, furthest - layer);
}

WallState measureWall(const ParticleSet& p, const ShieldFrame& f) {
  const Columns cols(f);
  std::vector<char> covered(cols.size(), 0);
  std::vector<double> envelope(cols.size(), -std::numeric_limits<double>::infinity());
  // Each intact wall particle covers the columns whose centres lie within h of it laterally.
  for (std::size_t i = 0; i < p.numReal; ++i) {
    if (!isIntactWall(p, i, f)) continue;
    const double h = p.h[i];
    const double q0 = cols.lateral(p, i, 0), q1 = cols.count == 2 ? cols.lateral(p, i, 1) : 0.0;
    const long a0 = std::max(0L, cols.binOf(q0 - h, 0)), b0 = std::min(cols.bins[0] - 1, cols.binOf(q0 + h, 0));
    const long a1 = cols.count == 2 ? std::max(0L, cols.binOf(q1 - h, 1)) : 0;
    const long b1 = cols.count == 2 ? std::min(cols.bins[1] - 1, cols.binOf(q1 + h, 1)) : 0;
    for (long k1 = a1; k1 <= b1; ++k1)
      for (long k0 = a0; k0 <= b0; ++k0) {
        const double d0 = cols.centre(k0, 0) - q0;
        const double d1 = cols.count == 2 ? cols.centre(k1, 1) - q1 : 0.0;
        if (d0 * d0 + d1 * d1 >= h * h) continue;
        const std::size_t c = cols.index(k0, k1);
        covered[c] = 1;
        envelope[c] = std::max(envelope[c], f.s(p, i));
      }
  }
  WallState w;
  for (long k1 = 0; k1 < cols.bins[1]; ++k1)
    for (long k0 = 0; k0 < cols.bins[0]; ++k0)
      if (cols.inner(k0, k1) && !covered[cols.index(k0, k1)]) {
        w.hole = true;
        w.holeArea += cols.area(k0, f.geometry);
      }
  const double copies = f.mirrorCopies();
  w.holeArea *= copies;
  if (w.hole)
    w.holeDiameter = f.geometry == Geometry::Planar ? w.holeArea : std::sqrt(4.0 * w.holeArea / kPi);
  // Material behind the wall: beyond the intact envelope of its column by more than 2h.
  for (std::size_t i = 0; i < p.numReal; ++i) {
    const long k0 = cols.binOf(cols.lateral(p, i, 0), 0);
    const long k1 = cols.count == 2 ? cols.binOf(cols.lateral(p, i, 1), 1) : 0;
    if (k0 < 0 || k0 >= cols.bins[0] || k1 < 0 || k1 >= cols.bins[1] || !cols.inner(k0, k1)) continue;
    const std::size_t c = cols.index(k0, k1);
    const double rear = covered[c] ? envelope[c] : f.wallRear;
    if (f.s(p, i) <= rear + 2.0 * p.h[i]) continue;
    w.massBehind += p.mass[i];
    if (p.material[i] == f.wallMaterial) w.wallMassBehind += p.mass[i];
    const double volume = p.mass[i] / p.rho[i];
    w.sizeBehind += f.geometry == Geometry::Axisymmetric ? volume / (2.0 * kPi * std::max(p.x[0][i], 1e-300)) : volume;
  }
  w.massBehind *= copies;
  w.wallMassBehind *= copies;
  w.sizeBehind *= copies;
  const double piece = 2.0 * f.spacing;
  w.resolvedBehind = w.sizeBehind >= std::pow(piece, spatialDimension(f.geometry));
  w.deflection = rearFaceDeflection(p, f);
  return w;
}

DebrisCloud measureDebrisCloud(const ParticleSet& p, const ShieldFrame& f) {
  const Columns cols(f);
  const double base = f.bumperRear ? *f.bumperRear : f.direction * f.shotPoint[f.normalAxis];
  // The bumper's own body, bent back behind its rear face, is not debris.
  const std::vector<char> bumper =
      f.bumperMaterial >= 0 ? largestPiece(p, f.bumperMaterial, f.geometry) : std::vector<char>(p.numReal, 0);
  DebrisCloud cloud;
  std::array<double, 2> lateral{};
  for (std::size_t i = 0; i < p.numReal; ++i) {
    if (p.material[i] == f.wallMaterial || bumper[i]) continue;
    const double s = f.s(p, i);
    if (s <= base + p.h[i]) continue;
    const double m = p.mass[i];
    const double vn = f.direction * p.v[f.normalAxis][i];
    cloud.mass += m;
    cloud.momentum += m * vn;
    cloud.leadingEdge = std::max(cloud.leadingEdge, s - base);
    cloud.leadingSpeed = std::max(cloud.leadingSpeed, vn);
    double r2 = 0.0;
    for (int k = 0; k < cols.count; ++k) {
      const double dq = p.x[cols.axis[k]][i] - (f.geometry == Geometry::Axisymmetric ? 0.0 : f.shotPoint[cols.axis[k]]);
      r2 += dq * dq;
      if (f.geometry != Geometry::Axisymmetric) lateral[k] += m * p.v[cols.axis[k]][i];
    }
    cloud.radius = std::max(cloud.radius, std::sqrt(r2));
    if (s >= f.wallFront - p.h[i]) cloud.massOnWall += m;
  }
  // The mirrored copies: their masses and normal momenta add; sideways momentum across a
  // mirror plane cancels.
  const double copies = f.mirrorCopies();
  cloud.mass *= copies;
  cloud.momentum *= copies;
  cloud.massOnWall *= copies;
  for (int k = 0; k < cols.count; ++k)
    lateral[k] *= f.mirrorLow[cols.axis[k]] || f.mirrorHigh[cols.axis[k]] ? 0.0 : copies;
  cloud.lateralMomentum = std::hypot(lateral[0], lateral[1]);
  if (cloud.leadingEdge > 0.0) cloud.halfAngle = std::atan2(cloud.radius, cloud.leadingEdge);
  return cloud;
}

}  // namespace ejecta::fields
