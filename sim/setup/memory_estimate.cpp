#include "sim/setup/memory_estimate.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/machine_memory.hpp"

namespace ejecta {

namespace {

// The share of its bounding box (clipped to the domain) a shape fills.
double fillFraction(const ShapeSpec& shape, int dim) {
  switch (shape.kind) {
    case ShapeKind::Box:
    case ShapeKind::HalfSpace: return 1.0;
    case ShapeKind::Sphere:
    case ShapeKind::Shell: {
      const double ball = dim == 3 ? std::numbers::pi / 6.0 : dim == 2 ? std::numbers::pi / 4.0 : 1.0;
      const double hollow = shape.kind == ShapeKind::Shell && shape.radius > 0.0
                                ? std::pow(shape.innerRadius / shape.radius, dim)
                                : 0.0;
      return ball * (1.0 - hollow);
    }
  }
  return 1.0;
}

// Lattice points per unit measure: cubic 1/s^d; hexagonal 2D 2/(sqrt(3) s^2); face-centred
// cubic with nearest-neighbour distance s, sqrt(2)/s^3.
double pointsPerMeasure(LatticeKind lattice, int dim, double s) {
  const double cubic = 1.0 / std::pow(s, dim);
  if (lattice != LatticeKind::Hexagonal || dim == 1) return cubic;
  return dim == 2 ? cubic * 2.0 / std::sqrt(3.0) : cubic * std::numbers::sqrt2;
}

}  // namespace

RunMemoryEstimate estimateRunMemory(const Scene& scene) {
  const int dim = spatialDimension(scene.geometry);
  RunMemoryEstimate e;
  for (const BodySpec& body : scene.bodies) {
    double measure = 1.0;
    for (int d = 0; d < dim; ++d) {
      double lo = 0.0, hi = 0.0;
      switch (body.shape.kind) {
        case ShapeKind::Box: lo = body.shape.min[d], hi = body.shape.max[d]; break;
        case ShapeKind::Sphere:
        case ShapeKind::Shell:
          lo = body.shape.center[d] - body.shape.radius, hi = body.shape.center[d] + body.shape.radius;
          break;
        case ShapeKind::HalfSpace: lo = -INFINITY, hi = INFINITY; break;
      }
      const AxisBounds& a = scene.domain[static_cast<std::size_t>(d)];
      if (a.bounded) lo = std::fmax(lo, a.min), hi = std::fmin(hi, a.max);
      if (scene.geometry == Geometry::Axisymmetric && d == 0) lo = std::fmax(lo, 0.0);
      measure *= std::fmax(hi - lo, 0.0);
    }
    if (body.spacing > 0.0)
      e.particles += measure * fillFraction(body.shape, dim) * pointsPerMeasure(body.lattice, dim, body.spacing);
  }
  e.bytes = e.particles * bytesPerParticle(scene);
  return e;
}

double bytesPerParticle(const Scene& scene) {
  const bool riemann = scene.sph.dissipation == Dissipation::Riemann;
  return kBytesPerParticle + (riemann ? kRiemannBytesPerParticle[spatialDimension(scene.geometry)] : 0.0);
}

void requireRunMemory(const Scene& scene, int ranks) {
  const RunMemoryEstimate e = estimateRunMemory(scene);
  char detail[160];
  std::snprintf(detail, sizeof detail, "about %.3g particles x %.0f bytes%s", e.particles,
                bytesPerParticle(scene), ranks > 1 ? ", per rank" : "");
  requireMemory(scene.sourcePath + ": key 'bodies': the run of scene '" + scene.name + "'",
                e.bytes / std::fmax(ranks, 1), detail,
                "coarsen the bodies' spacing (memory goes as spacing^-d) or run on more ranks");
}

}  // namespace ejecta
