// Crater analysis by ray marching a filled-fraction field on a polar grid about the crater axis.
// Method and definitions: docs/crater.md.
#include "fields/crater.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <exception>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/csv.hpp"

namespace ejecta::fields {
namespace {

constexpr double kPi = std::numbers::pi;
// Bisections of the bin that holds a sector's apparent radius: 2^-8 of a resolution.
constexpr int kBisections = 8;

Point add(const Point& a, const Point& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Point sub(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Point scale(const Point& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
double dot(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const Point& a) { return std::sqrt(dot(a, a)); }
Point cross(const Point& a, const Point& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Point flatten(const Point& a) { return {a[0], a[1], 0.0}; }  // planar runs: drop z

std::string number(double x) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.9g", x);
  return buffer;
}

[[noreturn]] void badOption(const std::string& option, const std::string& rule, double got,
                            const std::string& what = "") {
  throw std::invalid_argument("crater: option '" + option + "' " + rule + " (got " + what +
                              number(got) + ")");
}

// Everything a ray needs, fixed before the parallel loop.
struct Setup {
  bool sphere = true;
  bool planar = false;
  Point center{};     // sphere centre
  double radius = 0;  // sphere radius
  Point axisPoint{};  // the axis on the original surface
  Point n{}, e1{}, e2{};
  double resolution = 0;
  double searchRadius = 0;  // whole bins: bins * resolution
  double threshold = 0.5;
  double gapBridge = 0;
  double step = 0;     // march step along a ray
  double uStart = 0;   // height of the first sample above the original surface (negative)
  double uEnd = 0;     // height of the last one
  int steps = 0;       // samples: steps + 1
  int bins = 0;        // radial bins
  int sectors = 0;     // azimuth sectors (planar: 2)
};

// One ray's answer: height of the present surface above the original one (-depth), the
// crossing point, and whether the march hit either end of the ray.
struct Ray {
  double height = 0;
  Point point{};
  bool startsInVoid = false;  // the surface is at the ray's start: the depth is a lower bound
  bool endsInMaterial = false;  // material up to the ray's end: the height is a lower bound
};

// Direction in the tangent plane for sector k.
Point tangent(const Setup& s, int k) {
  if (s.planar) return k == 0 ? s.e1 : scale(s.e1, -1.0);
  const double psi = 2.0 * kPi * k / s.sectors;
  return add(scale(s.e1, std::cos(psi)), scale(s.e2, std::sin(psi)));
}

// The ray at distance rho from the axis along the original surface, on sector k.
Ray marchRay(const FractionField& field, const Setup& s, double rho, int sector) {
  const Point t = tangent(s, sector);
  // Sphere: from the centre outward along d, at height u the point is C + (R + u) d.
  // Plane: along the normal through the surface point p, the point is p + u n.
  Point origin, direction;
  double offset;
  if (s.sphere) {
    const double theta = rho / s.radius;
    origin = s.center;
    direction = add(scale(s.n, std::cos(theta)), scale(t, std::sin(theta)));
    offset = s.radius;
  } else {
    origin = add(s.axisPoint, scale(t, rho));
    direction = s.n;
    offset = 0.0;
  }
  auto at = [&](double u) { return add(origin, scale(direction, offset + u)); };
  auto sample = [&](double u) {
    const double f = field(at(u));
    return std::isfinite(f) ? f : 0.0;  // a non-finite fraction counts as void
  };

  const double t0 = s.threshold;
  Ray ray;
  // The ray comes from inside the target: before its first sample it counts as filled, so a
  // first sample in void is an exit at the start.
  double uPrev = s.uStart;
  double fPrev = sample(uPrev);
  int first = 0;
  if (fPrev < t0) {
    // A thin target (a slab) or a grid clipped to a region may have no material at the start:
    // the ray begins at its first filled sample instead, provided that lies below the original
    // surface (material above it would be ejecta, not the target).
    for (int j = 1; j <= s.steps; ++j) {
      const double u = s.uStart + j * s.step;
      if (u >= 0.0) break;
      const double f = sample(u);
      if (f >= t0) {
        first = j;
        uPrev = u;
        fPrev = f;
        break;
      }
    }
  }
  bool inside = fPrev >= t0;
  bool voidFromStart = !inside;  // the void that began at the first sample is not yet bridged
  double exitU = uPrev;          // the last exit from filled into void
  for (int j = first + 1; j <= s.steps; ++j) {
    const double u = s.uStart + j * s.step;
    const double f = sample(u);
    if (inside) {
      if (f < t0) {
        exitU = uPrev + s.step * (fPrev - t0) / (fPrev - f);
        inside = false;
      }
    } else if (f >= t0) {
      const double entryU = uPrev + s.step * (t0 - fPrev) / (f - fPrev);
      if (entryU - exitU > s.gapBridge) break;  // material beyond a long void: detached
      inside = true;                            // a short void (a crack): bridged
      voidFromStart = false;
    } else if (u - exitU > s.gapBridge) {
      break;  // the void is already longer than the bridge: exitU is the surface
    }
    uPrev = u;
    fPrev = f;
  }
  if (inside) {
    ray.height = s.uEnd;
    ray.endsInMaterial = true;
  } else {
    ray.height = exitU;
    ray.startsInVoid = voidFromStart;
  }
  ray.point = at(ray.height);
  return ray;
}

Setup makeSetup(const CraterOptions& o) {
  Setup s;
  s.planar = o.planar;
  s.sphere = o.surface.kind == ReferenceSurface::Kind::Sphere;
  if (!(o.resolution > 0.0) || !std::isfinite(o.resolution))
    badOption("resolution", "must be positive", o.resolution);
  if (!(o.threshold > 0.0 && o.threshold < 1.0))
    badOption("threshold", "must lie strictly between 0 and 1", o.threshold);
  if (!(o.searchRadius >= 0.0) || !std::isfinite(o.searchRadius))
    badOption("searchRadius", "must be non-negative (0: 60 resolutions)", o.searchRadius);
  if (!(o.gapBridge >= 0.0) || !std::isfinite(o.gapBridge))
    badOption("gapBridge", "must be non-negative (0: 2 resolutions)", o.gapBridge);
  if (!(o.levelTolerance >= 0.0) || !std::isfinite(o.levelTolerance))
    badOption("levelTolerance", "must be non-negative (0: a quarter of the resolution)", o.levelTolerance);
  if (!(o.targetDensity >= 0.0) || !std::isfinite(o.targetDensity))
    badOption("targetDensity", "must be non-negative (0: no mass)", o.targetDensity);
  if (!o.planar && o.azimuths < 4)
    badOption("azimuths", "must be at least 4 in 3D", o.azimuths);

  // A planar run lives in the x-y plane: every point and direction loses its z component.
  auto proj = [&](const Point& p) { return o.planar ? flatten(p) : p; };
  const Point impact = proj(o.impactPoint);
  if (s.sphere) {
    s.radius = o.surface.radius;
    if (!(s.radius > 0.0) || !std::isfinite(s.radius))
      badOption("surface.radius", "must be positive", s.radius);
    s.center = proj(o.surface.center);
    const Point r = sub(impact, s.center);
    const double distance = norm(r);
    if (!(distance > 1e-12 * s.radius))
      badOption("impactPoint", "must differ from the sphere's centre", distance, "distance ");
    s.n = scale(r, 1.0 / distance);
    s.axisPoint = add(s.center, scale(s.n, s.radius));
  } else {
    const Point normal = proj(o.surface.normal);
    const double length = norm(normal);
    if (!(length > 0.0) || !std::isfinite(length))
      badOption("surface.normal",
                o.planar ? "must have a non-zero x-y part in a planar run" : "must be non-zero",
                length, "length ");
    s.n = scale(normal, 1.0 / length);
    const Point point = proj(o.surface.point);
    s.axisPoint = sub(impact, scale(s.n, dot(sub(impact, point), s.n)));
  }

  // Frame about the axis. Planar: e1 = n x z, in the x-y plane. 3D: e1 along the impactor's
  // track projected onto the tangent plane when given, else the coordinate axis least aligned
  // with n, projected.
  if (s.planar) {
    s.e1 = Point{s.n[1], -s.n[0], 0.0};
    s.e1 = scale(s.e1, 1.0 / norm(s.e1));
    s.e2 = Point{0.0, 0.0, 1.0};
  } else {
    Point e1 = sub(o.alongTrack, scale(s.n, dot(o.alongTrack, s.n)));
    if (!(norm(e1) > 1e-12 * norm(o.alongTrack))) {
      int axis = 0;
      for (int i = 1; i < 3; ++i)
        if (std::abs(s.n[i]) < std::abs(s.n[axis])) axis = i;
      Point ref{};
      ref[axis] = 1.0;
      e1 = sub(ref, scale(s.n, dot(ref, s.n)));
    }
    s.e1 = scale(e1, 1.0 / norm(e1));
    s.e2 = cross(s.n, s.e1);
  }

  s.resolution = o.resolution;
  s.threshold = o.threshold;
  s.gapBridge = o.gapBridge > 0.0 ? o.gapBridge : 2.0 * o.resolution;
  double search = o.searchRadius > 0.0 ? o.searchRadius : 60.0 * o.resolution;
  if (s.sphere) {
    if (o.searchRadius == 0.0) search = std::min(search, 0.5 * kPi * s.radius);
    search = std::min(search, kPi * s.radius);  // past the antipode the rays repeat
  }
  // At most 1e7 rays (0.4 GB of results) and 4e6 samples per ray, so the counts fit an int.
  const double bins = std::max(1.0, std::floor(search / o.resolution + 1e-9));
  const double sectors = o.planar ? 2.0 : static_cast<double>(o.azimuths);
  if (bins > 1e6 || bins * sectors > 1e7)
    badOption("searchRadius",
              "over 'resolution' must give at most 1e6 bins, and times 'azimuths' at most 1e7 "
              "rays",
              bins * sectors, "rays ");
  s.bins = static_cast<int>(bins);
  s.searchRadius = s.bins * o.resolution;
  s.sectors = s.planar ? 2 : o.azimuths;
  // Rays start one search radius below the original surface (sphere: at most at the centre)
  // and end one search radius above it.
  s.step = 0.5 * o.resolution;
  const double below = s.sphere ? std::min(s.searchRadius, s.radius) : s.searchRadius;
  s.steps = static_cast<int>(std::ceil((below + s.searchRadius) / s.step - 1e-9));
  s.uStart = -below;
  s.uEnd = s.uStart + s.steps * s.step;
  return s;
}

// Runs body(i) for i in [0, n) under OpenMP and rethrows the first exception afterwards (an
// exception must not leave a parallel region).
template <typename Body>
void parallelForRethrowing(std::ptrdiff_t n, int chunk, Body body) {
  std::exception_ptr error;
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, chunk)
#endif
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    try {
      body(i);
    } catch (...) {
#ifdef _OPENMP
#pragma omp critical(ejecta_crater_error)
#endif
      if (!error) error = std::current_exception();
    }
  }
  if (error) std::rethrow_exception(error);
}

void appendNote(std::string& note, const std::string& text) {
  if (!note.empty()) note += "; ";
  note += text;
}

}  // namespace

CraterMetrics analyseCrater(const FractionField& field, const CraterOptions& options) {
  if (!field) throw std::invalid_argument("crater: the field is empty");
  const Setup s = makeSetup(options);
  const int bins = s.bins;
  const int sectors = s.sectors;
  const std::ptrdiff_t rays = static_cast<std::ptrdiff_t>(bins) * sectors;

  // Every ray writes its own slot, so the result does not depend on the thread count.
  std::vector<Ray> grid(static_cast<std::size_t>(rays));
  parallelForRethrowing(rays, 16, [&](std::ptrdiff_t r) {
    const int bin = static_cast<int>(r / sectors);
    grid[static_cast<std::size_t>(r)] =
        marchRay(field, s, (bin + 0.5) * s.resolution, static_cast<int>(r % sectors));
  });

  auto depthAt = [&](int i, int k) {
    return -grid[static_cast<std::size_t>(i) * sectors + k].height;
  };
  auto rhoAt = [&](int i) { return (i + 0.5) * s.resolution; };

  CraterMetrics m;
  m.elongation = 1.0;

  // Profile and the deepest sample, in a fixed order.
  int startsInVoid = 0, endsInMaterial = 0;
  int deepBin = 0, deepSector = 0;
  m.profile.resize(static_cast<std::size_t>(bins));
  for (int i = 0; i < bins; ++i) {
    CraterProfileBin& b = m.profile[static_cast<std::size_t>(i)];
    b.distance = rhoAt(i);
    double sum = 0.0;
    b.depthMin = b.depthMax = depthAt(i, 0);
    for (int k = 0; k < sectors; ++k) {
      const double d = depthAt(i, k);
      const Ray& ray = grid[static_cast<std::size_t>(i) * sectors + k];
      startsInVoid += ray.startsInVoid;
      endsInMaterial += ray.endsInMaterial;
      sum += d;
      b.depthMin = std::min(b.depthMin, d);
      b.depthMax = std::max(b.depthMax, d);
      if (d > depthAt(deepBin, deepSector)) {
        deepBin = i;
        deepSector = k;
      }
    }
    b.depthMean = sum / sectors;
  }
  const double maxDepth = depthAt(deepBin, deepSector);
  const std::string total = std::to_string(rays);
  if (startsInVoid > 0)
    appendNote(m.note, std::to_string(startsInVoid) + " of " + total +
                           " rays found void at their start " + number(-s.uStart) +
                           " m below the original surface: the depth there is a lower bound" +
                           (s.sphere && s.uStart <= -s.radius ? "" : " (raise searchRadius)"));
  if (endsInMaterial > 0)
    appendNote(m.note, std::to_string(endsInMaterial) + " of " + total +
                           " rays found material up to their end " + number(s.uEnd) +
                           " m above the original surface");
  if (startsInVoid == rays) {
    appendNote(m.note, "no crater: no target material where the rays start (wrong surface, or "
                       "an empty field?)");
    return m;
  }
  if (!(maxDepth >= s.resolution)) {
    appendNote(m.note, "no crater: no depression deeper than one resolution (" +
                           number(s.resolution) + " m) within " + number(s.searchRadius) +
                           " m of the axis (deepest " + number(maxDepth + 0.0) + " m)");
    return m;
  }
  m.found = true;
  m.depth = maxDepth;
  m.deepestPoint = grid[static_cast<std::size_t>(deepBin) * sectors + deepSector].point;

  // Apparent radius per sector: outward from that sector's deepest bin, the first place where
  // the depth comes back to zero (within round-off). The two bins around it bracket the place;
  // extra rays bisect the bracket, and the last bracket is interpolated linearly.
  const double level = options.levelTolerance > 0.0 ? options.levelTolerance : 0.25 * s.resolution;
  std::vector<int> outside(static_cast<std::size_t>(sectors), -1);  // first bin back at zero
  int notReturned = 0;
  m.apparentRadius.assign(static_cast<std::size_t>(sectors), 0.0);
  for (int k = 0; k < sectors; ++k) {
    int deepest = 0;
    for (int i = 1; i < bins; ++i)
      if (depthAt(i, k) > depthAt(deepest, k)) deepest = i;
    if (!(depthAt(deepest, k) > level)) continue;  // no depression on this sector: radius 0
    for (int i = deepest + 1; i < bins && outside[static_cast<std::size_t>(k)] < 0; ++i)
      if (depthAt(i, k) <= level) outside[static_cast<std::size_t>(k)] = i;
    if (outside[static_cast<std::size_t>(k)] < 0) {
      m.apparentRadius[static_cast<std::size_t>(k)] = s.searchRadius;
      ++notReturned;
    }
  }
  parallelForRethrowing(sectors, 1, [&](std::ptrdiff_t kk) {
    const int k = static_cast<int>(kk);
    const int i = outside[static_cast<std::size_t>(k)];
    if (i < 0) return;
    double lo = rhoAt(i - 1), hi = rhoAt(i);
    double dLo = depthAt(i - 1, k), dHi = depthAt(i, k);
    for (int iteration = 0; iteration < kBisections; ++iteration) {
      const double mid = 0.5 * (lo + hi);
      const double d = -marchRay(field, s, mid, k).height;
      if (d > level) {
        lo = mid;
        dLo = d;
      } else {
        hi = mid;
        dHi = d;
      }
    }
    m.apparentRadius[static_cast<std::size_t>(k)] =
        lo + std::clamp(dLo / (dLo - dHi), 0.0, 1.0) * (hi - lo);
  });

  std::vector<double> crest(static_cast<std::size_t>(sectors), 0.0);
  std::vector<double> crestHeight(static_cast<std::size_t>(sectors), 0.0);
  for (int k = 0; k < sectors; ++k) {
    const double r = m.apparentRadius[static_cast<std::size_t>(k)];

    // Rim crest: the highest bin with r <= rho <= min(2r, search radius), the innermost of equal
    // heights (round-off). A local maximum is refined by the parabola through it and its two
    // neighbours. With nothing above the original level there is no rim: the crest is put at the
    // apparent radius.
    const double outer = std::min(2.0 * r, s.searchRadius);
    int top = -1;
    for (int i = 0; i < bins; ++i) {
      if (rhoAt(i) < r || rhoAt(i) > outer) continue;
      if (top < 0 || -depthAt(i, k) > -depthAt(top, k) + level) top = i;
    }
    double position = r, height = 0.0;
    if (top >= 0) {
      height = -depthAt(top, k);
      if (height > level) {
        position = rhoAt(top);
        if (top > 0 && top + 1 < bins) {
          const double ym = -depthAt(top - 1, k), y0 = height, yp = -depthAt(top + 1, k);
          const double curvature = ym - 2.0 * y0 + yp;
          if (y0 + level >= ym && y0 + level >= yp && curvature < -level) {
            const double delta = std::clamp(0.5 * (ym - yp) / curvature, -0.5, 0.5);
            position += delta * s.resolution;
            height = y0 - 0.25 * (ym - yp) * delta;
          }
        }
      }
    }
    crest[static_cast<std::size_t>(k)] = position;
    crestHeight[static_cast<std::size_t>(k)] = height;
  }
  if (notReturned > 0)
    appendNote(m.note, "the surface does not return to the original level within the search "
                       "radius on " + std::to_string(notReturned) + " of " +
                           std::to_string(sectors) + " azimuths; their apparent radius is the "
                           "search radius (" + number(s.searchRadius) + " m)");

  // Diameters: the mean over opposite pairs of r(psi) + r(psi + pi), which is twice the mean
  // radius over the sectors.
  double radiusSum = 0.0, crestSum = 0.0, heightSum = 0.0;
  for (int k = 0; k < sectors; ++k) {
    radiusSum += m.apparentRadius[static_cast<std::size_t>(k)];
    crestSum += crest[static_cast<std::size_t>(k)];
    heightSum += crestHeight[static_cast<std::size_t>(k)];
  }
  m.apparentDiameter = 2.0 * radiusSum / sectors;
  m.rimDiameter = 2.0 * crestSum / sectors;
  m.rimHeight = heightSum / sectors;

  // Volume between the present and the original surface, inside the apparent radius, where the
  // surface is below the original one: midpoint rule on the bins.
  const double dRho = s.resolution;
  const double dPsi = 2.0 * kPi / sectors;
  double volume = 0.0;
  for (int k = 0; k < sectors; ++k) {
    const double r = m.apparentRadius[static_cast<std::size_t>(k)];
    for (int i = 0; i < bins && rhoAt(i) < r; ++i) {
      const double d = depthAt(i, k);
      if (!(d > 0.0)) continue;
      const double rho = rhoAt(i);
      if (s.sphere) {
        const double R = s.radius, S = R - d, dTheta = dRho / R;
        volume += s.planar ? 0.5 * (R * R - S * S) * dTheta
                           : (R * R * R - S * S * S) / 3.0 * std::sin(rho / R) * dTheta * dPsi;
      } else {
        volume += s.planar ? d * dRho : d * rho * dRho * dPsi;
      }
    }
  }
  m.volume = volume;
  m.excavatedMass = options.targetDensity * volume;

  // Along- and cross-track diameters.
  if (s.planar) {
    m.alongTrackDiameter = m.crossTrackDiameter = m.apparentDiameter;
  } else {
    // Radius at a fractional sector x (periodic, linear between sector centres) and the
    // diameter of the pair (x, x + half a turn).
    auto radiusAt = [&](double x) {
      x = std::fmod(x, static_cast<double>(sectors));
      if (x < 0.0) x += sectors;
      const int k0 = std::min(static_cast<int>(std::floor(x)), sectors - 1);
      const double w = x - k0;
      const int k1 = (k0 + 1) % sectors;
      return (1.0 - w) * m.apparentRadius[static_cast<std::size_t>(k0)] +
             w * m.apparentRadius[static_cast<std::size_t>(k1)];
    };
    auto pairDiameter = [&](double x) { return radiusAt(x) + radiusAt(x + 0.5 * sectors); };
    double along = 0.0;
    const double alongTrackInPlane =
        norm(sub(options.alongTrack, scale(s.n, dot(options.alongTrack, s.n))));
    if (alongTrackInPlane > 1e-12 * norm(options.alongTrack)) {
      along = 0.0;  // e1 is the along-track direction
    } else {
      if (norm(options.alongTrack) > 0.0)
        appendNote(m.note, "alongTrack is along the crater axis: the longest diameter is taken "
                           "as along-track");
      double best = -1.0;
      for (int k = 0; k < sectors; ++k) {
        const double d = pairDiameter(k);
        if (d > best) {
          best = d;
          along = k;
        }
      }
    }
    m.alongTrackDiameter = pairDiameter(along);
    m.crossTrackDiameter = pairDiameter(along + 0.25 * sectors);
  }
  m.elongation = m.crossTrackDiameter > 0.0 ? m.alongTrackDiameter / m.crossTrackDiameter : 1.0;
  return m;
}

std::string craterProfileCsv(const CraterMetrics& metrics) {
  CsvWriter csv({"distance_m", "depth_mean_m", "depth_min_m", "depth_max_m"});
  for (const CraterProfileBin& b : metrics.profile)
    csv.number(b.distance).number(b.depthMean).number(b.depthMin).number(b.depthMax).endRow();
  return csv.str();
}

}  // namespace ejecta::fields
