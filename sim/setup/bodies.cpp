#include "sim/setup/bodies.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/units.hpp"
#include "sim/eos/jwl.hpp"
#include "sim/sources/programmed_burn.hpp"
#include "sim/state/tensor.hpp"

namespace ejecta {

namespace {

using Point = std::array<double, 3>;

// Guard against a typo in spacing turning into an out-of-memory crash.
constexpr double kMaxCandidatesPerBody = 2e9;

struct Bounds {
  Point lo{}, hi{};  // finite on the first `dimension` axes
};

std::string where(const Scene& scene, int line) {
  return scene.sourcePath + ":" + std::to_string(line);
}

// The region the body's lattice must cover: its shape's extent clipped to the domain.
Bounds bodyBounds(const Scene& scene, const ShapeSpec& shape, int dim) {
  Bounds b;
  for (int d = 0; d < dim; ++d) {
    switch (shape.kind) {
      case ShapeKind::Box:
        b.lo[d] = shape.min[d];
        b.hi[d] = shape.max[d];
        break;
      case ShapeKind::Sphere:
      case ShapeKind::Shell:
        b.lo[d] = shape.center[d] - shape.radius;
        b.hi[d] = shape.center[d] + shape.radius;
        break;
      case ShapeKind::HalfSpace:  // validation guarantees a bounded domain here
        b.lo[d] = scene.domain[d].min;
        b.hi[d] = scene.domain[d].max;
        break;
    }
    const AxisBounds& a = scene.domain[d];
    if (a.bounded) {
      b.lo[d] = std::max(b.lo[d], a.min);
      b.hi[d] = std::min(b.hi[d], a.max);
    }
  }
  if (scene.geometry == Geometry::Axisymmetric) b.lo[0] = std::max(b.lo[0], 0.0);
  return b;
}

// Where the lattice is anchored: points sit at origin + (i + 1/2) * pitch. A box's lattice starts
// at its min corner, a sphere's is symmetric about its centre; in RZ r always starts at the axis
// side (r = s/2) unless a box begins further out.
Point latticeOrigin(const Scene& scene, const ShapeSpec& shape, int dim) {
  Point o{};
  for (int d = 0; d < dim; ++d) {
    switch (shape.kind) {
      case ShapeKind::Box: o[d] = shape.min[d]; break;
      case ShapeKind::Sphere:
      case ShapeKind::Shell: o[d] = shape.center[d]; break;
      case ShapeKind::HalfSpace: o[d] = scene.domain[d].min; break;
    }
  }
  if (scene.geometry == Geometry::Axisymmetric)
    o[0] = (shape.kind == ShapeKind::Box) ? std::max(shape.min[0], 0.0) : 0.0;
  return o;
}

// Strictly inside: a particle exactly on a wall (or the axis) would coincide with its own mirror
// image, and on a periodic face with its periodic image.
bool insideDomain(const Scene& scene, const Point& x, int dim) {
  if (scene.geometry == Geometry::Axisymmetric && !(x[0] > 0.0)) return false;
  for (int d = 0; d < dim; ++d) {
    const AxisBounds& a = scene.domain[d];
    if (a.bounded && !(x[d] > a.min && x[d] < a.max)) return false;
  }
  return true;
}

// Index range of points origin + (i + 1/2) * pitch inside [lo, hi] (padded by one; the caller
// tests every point exactly).
struct IndexRange {
  long first, last;
};
IndexRange indexRange(double origin, double pitch, double lo, double hi) {
  return {static_cast<long>(std::floor((lo - origin) / pitch - 0.5)) - 1,
          static_cast<long>(std::ceil((hi - origin) / pitch - 0.5)) + 1};
}

long parity(long i) { return ((i % 2) + 2) % 2; }

// Calls visit(point) for every lattice point in `bounds` (and a margin of one pitch).
//   cubic:        points on a grid of pitch s
//   hexagonal 2D: rows along axis 0 of pitch s, row pitch s*sqrt(3)/2, odd rows shifted by s/2
//   hexagonal 3D: face-centred cubic = the points of a grid of pitch s/sqrt(2) whose index sum
//                 is even (nearest-neighbour distance s)
template <typename Visit>
void forEachLatticePoint(LatticeKind lattice, int dim, double s, const Point& origin,
                         const Bounds& bounds, const std::string& context, Visit&& visit) {
  const bool hex = (lattice == LatticeKind::Hexagonal && dim >= 2);
  std::array<double, 3> pitch{s, s, s};
  if (hex && dim == 2) pitch[1] = s * std::sqrt(3.0) / 2.0;
  if (hex && dim == 3) pitch = {s / std::sqrt(2.0), s / std::sqrt(2.0), s / std::sqrt(2.0)};

  // Counted in floating point first, so that an absurd spacing cannot overflow the indices.
  double candidates = 1.0;
  for (int d = 0; d < dim; ++d) {
    const double far =
        std::max(std::abs(bounds.lo[d] - origin[d]), std::abs(bounds.hi[d] - origin[d]));
    candidates *= std::max((bounds.hi[d] - bounds.lo[d]) / pitch[d], 0.0) + 3.0;
    if (!(far / pitch[d] <= kMaxCandidatesPerBody)) candidates = INFINITY;
  }
  if (!(candidates <= kMaxCandidatesPerBody)) {
    std::ostringstream msg;
    msg << context << ": the spacing would give about " << candidates
        << " lattice points; is the spacing in the right units?";
    throw SceneError(msg.str());
  }
  std::array<IndexRange, 3> range{IndexRange{0, 0}, IndexRange{0, 0}, IndexRange{0, 0}};
  for (int d = 0; d < dim; ++d)
    range[d] = indexRange(origin[d], pitch[d], bounds.lo[d], bounds.hi[d]);

  for (long k = range[2].first; k <= range[2].last; ++k) {
    for (long j = range[1].first; j <= range[1].last; ++j) {
      for (long i = range[0].first; i <= range[0].last; ++i) {
        if (hex && dim == 3 && parity(i + j + k) != 0) continue;
        const double shift = (hex && dim == 2 && parity(j) == 1) ? 0.5 : 0.0;
        Point x{};
        x[0] = origin[0] + (static_cast<double>(i) + 0.5 + shift) * pitch[0];
        if (dim >= 2) x[1] = origin[1] + (static_cast<double>(j) + 0.5) * pitch[1];
        if (dim >= 3) x[2] = origin[2] + (static_cast<double>(k) + 0.5) * pitch[2];
        visit(x);
      }
    }
  }
}

double initialSpecificEnergy(const BodySpec& body, const MaterialTable& materials,
                             const std::string& context) {
  if (body.internalEnergy) return *body.internalEnergy;
  if (body.material < 0 || static_cast<std::size_t>(body.material) >= materials.size())
    throw SceneError(context + ": material index out of range");
  const Material& material = materials[static_cast<std::size_t>(body.material)];
  const EquationOfState& eos = *material.eos;
  // A detonated explosive without a given state carries its chemical energy (the scene checked
  // that a detonation lights it).
  if (!body.pressure) {
    if (const auto* jwl = dynamic_cast<const Jwl*>(&eos))
      return jwl->params().specificDetonationEnergy();
    throw SceneError(context + ": give 'pressure' or 'internal_energy'");
  }
  try {
    // A porous body's density and pressure are the bulk's: its matrix is alpha_0 times denser
    // and carries alpha_0 times the pressure (P = P_s(alpha rho, u) / alpha).
    if (material.porosity) {
      const double alpha0 = material.porosity->initialDistention();
      return eos.specificEnergy(alpha0 * body.density, alpha0 * body.pressure.value_or(0.0));
    }
    return eos.specificEnergy(body.density, body.pressure.value_or(0.0));
  } catch (const std::domain_error& e) {
    throw SceneError(context + ": no internal energy gives pressure " +
                     formatQuantity(body.pressure.value_or(0.0), Dimension::Pressure) +
                     " at density " + formatQuantity(body.density, Dimension::Density) + " (" +
                     e.what() + ")");
  }
}

// Which of the scene's particles (numbered in build order, all bodies together) a build keeps:
// those in [begin, end); `next` is the number of the next one found. The particles outside are
// counted, not stored.
struct BuildRange {
  std::size_t next = 0;
  std::size_t begin = 0;
  std::size_t end = std::numeric_limits<std::size_t>::max();
};

}  // namespace

std::string bodyContext(const Scene& scene, std::size_t index, const std::string& key) {
  const BodySpec& body = scene.bodies.at(index);
  const std::size_t entry = body.entry >= 0 ? static_cast<std::size_t>(body.entry) : index;
  return where(scene, body.line) + ": key 'bodies[" + std::to_string(entry) + "]" +
         (key.empty() ? "" : "." + key) + "': body '" + body.name + "'";
}

namespace {

// Appends the particles of body `index` that fall in `range` (every one by default), their ids
// their numbers in build order. Returns how many the body has in all.
std::size_t fillBody(const Scene& scene, const MaterialTable& materials, std::size_t index,
                     ParticleSet& p, BuildRange& range) {
  const BodySpec& body = scene.bodies[index];
  const int dim = spatialDimension(scene.geometry);
  const bool rz = (scene.geometry == Geometry::Axisymmetric);
  const std::string context = bodyContext(scene, index);
  const double cell = latticeCellVolume(body.lattice, dim, body.spacing);
  const double h = scene.sph.eta * std::pow(cell, 1.0 / dim);
  const double u = initialSpecificEnergy(body, materials, context);
  const std::size_t before = range.next;

  auto visit = [&](const Point& x) {
    if (!bodyOwnsPoint(scene, index, x, scene.bodies.size())) return;
    // RZ: each particle is a ring of radius r; planar 2D: per metre depth; 1D: per m^2.
    const double mass = body.density * cell * (rz ? 2.0 * std::numbers::pi * x[0] : 1.0);
    const std::size_t number = range.next++;
    if (number < range.begin || number >= range.end) return;
    p.append(x, body.velocity, mass, body.density, u, h, body.material);
    p.id[p.size() - 1] = static_cast<std::int64_t>(number);
  };
  forEachLatticePoint(body.lattice, dim, body.spacing, latticeOrigin(scene, body.shape, dim),
                      bodyBounds(scene, body.shape, dim), context, visit);
  if (range.next == before)
    throw SceneError(context +
                     ": produces no particles (the shape is outside the domain, "
                     "covered by earlier bodies or voids, or smaller than the spacing " +
                     formatQuantity(body.spacing, Dimension::Length) + ")");
  return range.next - before;
}

double distanceSquared(const Point& a, const Point& b, int dim) {
  double r2 = 0.0;
  for (int d = 0; d < dim; ++d) r2 += (a[d] - b[d]) * (a[d] - b[d]);
  return r2;
}

std::string describeRegion(const EnergyDepositSpec& dep, int dim) {
  if (!dep.hasCenter) return "its body";
  std::string centre = "(";
  for (int d = 0; d < dim; ++d)
    centre += (d ? ", " : "") + formatQuantity(dep.center[static_cast<std::size_t>(d)], Dimension::Length);
  centre += ")";
  return (dep.profile == DepositProfile::TopHat
              ? "radius " + formatQuantity(dep.radius, Dimension::Length)
              : "width " + formatQuantity(dep.width, Dimension::Length)) +
         " around " + centre;
}

}  // namespace

// Adds the deposit so that sum_i m_i du_i = E exactly: du_i = E w_i / sum_j m_j w_j, with
// w = 1 inside the top hat (0 outside) or w = exp(-r^2/width^2).
// A body deposit (dep.body >= 0) weighs only that body's particles, the ids
// [firstIdOfBody[b], firstIdOfBody[b + 1]) (ids are assigned in body order at build, and travel
// with the particles when they are reordered); without a centre, all of them equally
// (du = E / M_body, the seed's DED).
Point applyDeposit(const Scene& scene, std::size_t index, const std::vector<std::int64_t>& firstIdOfBody,
                   ParticleSet& p, double time, const Communicator* ranks) {
  const EnergyDepositSpec& dep = scene.deposits[index];
  const int dim = spatialDimension(scene.geometry);
  const std::size_t n = p.numReal;
  std::int64_t idBegin = 0, idEnd = std::numeric_limits<std::int64_t>::max();
  if (dep.body >= 0) {
    idBegin = firstIdOfBody.at(static_cast<std::size_t>(dep.body));
    idEnd = firstIdOfBody.at(static_cast<std::size_t>(dep.body) + 1);
  }
  std::vector<double> w(n, 0.0);
  double weightedMass = 0.0;
  Point centroid{};
  for (std::size_t i = 0; i < n; ++i) {
    if (p.id[i] < idBegin || p.id[i] >= idEnd) continue;
    const double r2 = distanceSquared({p.x[0][i], p.x[1][i], p.x[2][i]}, dep.center, dim);
    if (!dep.hasCenter)
      w[i] = 1.0;
    else if (dep.profile == DepositProfile::TopHat)
      w[i] = (r2 <= dep.radius * dep.radius) ? 1.0 : 0.0;
    else
      w[i] = std::exp(-r2 / (dep.width * dep.width));
    weightedMass += p.mass[i] * w[i];
    for (int d = 0; d < 3; ++d) centroid[d] += p.mass[i] * w[i] * p.x[d][i];
  }
  if (ranks) {
    std::array<double, 4> sums{weightedMass, centroid[0], centroid[1], centroid[2]};
    ranks->sumInRankOrder(sums);
    weightedMass = sums[0];
    centroid = {sums[1], sums[2], sums[3]};
  }
  if (!(weightedMass > 0.0)) {
    std::string message = where(scene, dep.line) + ": key 'energy_deposits[" +
                          std::to_string(index) + "]': deposit '" + dep.name + "'";
    if (dep.time > 0.0)
      message += " of scene '" + scene.name + "' at time " +
                 formatQuantity(time, Dimension::Time) + " (its 'time' " +
                 formatQuantity(dep.time, Dimension::Time) + ")";
    message += " covers no particles (" + describeRegion(dep, dim) +
               (dep.body >= 0 ? " in body '" + scene.bodies[static_cast<std::size_t>(dep.body)].name + "'"
                              : std::string()) +
               (dep.time > 0.0 ? ": the region is empty at that moment)" : ")");
    throw SceneError(message);
  }
  const double scale = dep.energy / weightedMass;
  for (std::size_t i = 0; i < n; ++i) p.u[i] += scale * w[i];
  for (double& c : centroid) c /= weightedMass;
  // In RZ each particle is a ring about the axis: the centroid of the energy is on the axis.
  if (scene.geometry == Geometry::Axisymmetric) centroid[0] = 0.0;
  return centroid;
}

namespace {

// The ids each body's particles get at build: body b holds [first[b], first[b + 1]).
std::vector<std::int64_t> firstIds(const std::vector<std::size_t>& firstOfBody) {
  return {firstOfBody.begin(), firstOfBody.end()};
}

}  // namespace

double latticeCellVolume(LatticeKind lattice, int dimension, double spacing) {
  const double s = spacing;
  if (lattice == LatticeKind::Hexagonal && dimension == 2) return s * s * std::sqrt(3.0) / 2.0;
  if (lattice == LatticeKind::Hexagonal && dimension == 3) return s * s * s / std::sqrt(2.0);
  return std::pow(s, dimension);
}

bool insideShape(const ShapeSpec& shape, const std::array<double, 3>& x, int dimension) {
  switch (shape.kind) {
    case ShapeKind::Box:
      for (int d = 0; d < dimension; ++d)
        if (x[d] < shape.min[d] || x[d] > shape.max[d]) return false;
      return true;
    case ShapeKind::Sphere:
      return distanceSquared(x, shape.center, dimension) <= shape.radius * shape.radius;
    case ShapeKind::Shell: {
      const double r2 = distanceSquared(x, shape.center, dimension);
      return r2 >= shape.innerRadius * shape.innerRadius && r2 <= shape.radius * shape.radius;
    }
    case ShapeKind::HalfSpace: {
      double side = 0.0;
      for (int d = 0; d < dimension; ++d) side += (x[d] - shape.point[d]) * shape.normal[d];
      return side <= 0.0;
    }
  }
  return false;
}

bool insideBowl(const BowlSpec& bowl, const std::array<double, 3>& x, int dimension) {
  double height = 0.0, r2 = 0.0;
  for (int d = 0; d < dimension; ++d) {
    height += (x[d] - bowl.floor[d]) * bowl.axis[d];
    r2 += (x[d] - bowl.floor[d]) * (x[d] - bowl.floor[d]);
  }
  if (height < 0.0) return false;
  // Distance from the axis squared; in RZ (floor on the axis, axis along z) this is r^2.
  const double off2 = r2 - height * height;
  return off2 <= bowl.radius * bowl.radius * height / bowl.depth;
}

bool insideVoid(const VoidSpec& v, const std::array<double, 3>& x, int dimension) {
  return v.isBowl ? insideBowl(v.bowl, x, dimension) : insideShape(v.shape, x, dimension);
}

bool bodyOwnsPoint(const Scene& scene, std::size_t index, const Point& x, std::size_t ignoring) {
  const int dim = spatialDimension(scene.geometry);
  if (!insideShape(scene.bodies[index].shape, x, dim) || !insideDomain(scene, x, dim)) return false;
  for (std::size_t k = 0; k < index; ++k)
    if (k != ignoring && insideShape(scene.bodies[k].shape, x, dim)) return false;  // an earlier body owns it
  for (const VoidSpec& v : scene.voids)
    if (v.firstCarved <= index && insideVoid(v, x, dim)) return false;  // so does an earlier void
  return true;
}

std::vector<Point> bodyLatticePoints(const Scene& scene, std::size_t index, const Point& lo,
                                     const Point& hi, std::size_t ignoring, std::size_t maxPoints) {
  const BodySpec& body = scene.bodies.at(index);
  const int dim = spatialDimension(scene.geometry);
  const std::string context = bodyContext(scene, index);
  Bounds bounds = bodyBounds(scene, body.shape, dim);
  for (int d = 0; d < dim; ++d) {
    bounds.lo[d] = std::max(bounds.lo[d], lo[d]);
    bounds.hi[d] = std::min(bounds.hi[d], hi[d]);
    if (!(bounds.lo[d] <= bounds.hi[d])) return {};
  }
  // Counted before any is visited: the caller's bound holds for the points tried, not only kept
  // (a cubic cell per point; the other lattices pack at most sqrt 2 more).
  double candidates = 1.0;
  for (int d = 0; d < dim; ++d) candidates *= (bounds.hi[d] - bounds.lo[d]) / body.spacing + 3.0;
  if (!(candidates <= 2.0 * static_cast<double>(maxPoints))) {
    std::ostringstream msg;
    msg << context << ": about " << candidates << " lattice points to look at, above the "
        << maxPoints << " this use allows";
    throw SceneError(msg.str());
  }
  std::vector<Point> points;
  forEachLatticePoint(body.lattice, dim, body.spacing, latticeOrigin(scene, body.shape, dim), bounds,
                      context, [&](const Point& x) {
                        bool within = true;
                        for (int d = 0; d < dim; ++d) within = within && x[d] >= lo[d] && x[d] <= hi[d];
                        if (within && bodyOwnsPoint(scene, index, x, ignoring)) points.push_back(x);
                      });
  return points;
}

ParticleSet buildParticles(const Scene& scene, const MaterialTable& materials,
                           const Communicator* ranks) {
  ParticleSet p;
  BuildRange range;
  const bool share = ranks && ranks->size() > 1 && !needsWholeBody(materials);
  if (share) {
    // This rank's slice of the build order; the counting pass stores nothing.
    const std::size_t total = static_cast<std::size_t>(bodyFirstIds(scene, materials).back());
    const std::size_t r = static_cast<std::size_t>(ranks->rank()), n = static_cast<std::size_t>(ranks->size());
    range.begin = total / n * r + total % n * r / n;
    range.end = total / n * (r + 1) + total % n * (r + 1) / n;
  }
  std::vector<std::size_t> firstOfBody;
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    firstOfBody.push_back(range.next);
    fillBody(scene, materials, b, p, range);
  }
  firstOfBody.push_back(range.next);
  p.numReal = p.size();
  // Delayed deposits (time > 0) are the simulation's to fire (Simulation::step).
  for (std::size_t k = 0; k < scene.deposits.size(); ++k)
    if (!(scene.deposits[k].time > 0.0))
      applyDeposit(scene, k, firstIds(firstOfBody), p, 0.0, share ? ranks : nullptr);
  assignLightingTimes(scene.detonations, scene.geometry, materials, p);
  // Solid state exists only when a material needs it ("model no more than the scene asks").
  if (materials.anyStrength())
    p.enableStrength(stressComponentCount(spatialDimension(scene.geometry)));
  bool damaged = false;
  for (const BodySpec& b : scene.bodies) damaged = damaged || b.damage > 0.0;
  if (materials.anyFracture() || damaged) {
    p.enableFracture();
    for (std::size_t i = 0; i < p.numReal; ++i) {
      const auto id = static_cast<std::size_t>(p.id[i]);
      const std::size_t b = static_cast<std::size_t>(
          std::upper_bound(firstOfBody.begin(), firstOfBody.end(), id) - firstOfBody.begin()) - 1;
      p.crack[i] = std::cbrt(scene.bodies[b].damage);
    }
  }
  return p;
}

}  // namespace ejecta

namespace ejecta {

std::vector<std::int64_t> bodyFirstIds(const Scene& scene, const MaterialTable& materials) {
  ParticleSet none;
  BuildRange count;
  count.end = 0;  // count every body's particles, keep none
  std::vector<std::int64_t> first;
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    first.push_back(static_cast<std::int64_t>(count.next));
    fillBody(scene, materials, b, none, count);
  }
  first.push_back(static_cast<std::int64_t>(count.next));
  return first;
}

bool needsWholeBody(const MaterialTable& materials) {
  for (std::size_t m = 0; m < materials.size(); ++m)
    if (materials[m].fracture.kind == FractureKind::GradyKipp) return true;
  return false;
}

}  // namespace ejecta
