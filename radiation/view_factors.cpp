#include "radiation/view_factors.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <exception>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace ejecta::radiation {

using namespace vec3;
using sampling::PointSet;

namespace {

constexpr std::uint32_t kAbsent = RayScene::kMiss;
constexpr int kBlock = RayBlock::kCapacity;
// Rays of one replicate traced by one work item: large enough to amortise scheduling, small
// enough that 16 replicates still give every thread work at the first round.
constexpr std::uint64_t kChunk = 4096;

// A ray leaving a surface starts this far in front of it, so that single-precision rounding of
// the origin and of the triangle cannot put it behind its own triangle: 32 float ulps of the
// coordinates' magnitude. The displacement changes view factors between touching patches by
// about offset / size, under 1e-5 for a 1 m patch 10 m from the origin.
double originOffset(double coordinateMagnitude) {
  return 32.0 * static_cast<double>(FLT_EPSILON) * coordinateMagnitude;
}

double maxAbs(const Vec3& v) { return std::max({std::abs(v[0]), std::abs(v[1]), std::abs(v[2])}); }

struct Frame {
  Vec3 n, t1, t2;
};

Frame frameAbout(const Vec3& normal) {
  Frame f;
  f.n = normalized(normal);
  const Vec3 helper = std::abs(f.n[0]) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  f.t1 = normalized(cross(helper, f.n));
  f.t2 = cross(f.n, f.t1);
  return f;
}

Vec3 toWorld(const Frame& f, const std::array<double, 3>& local) {
  return add(add(scale(f.t1, local[0]), scale(f.t2, local[1])), scale(f.n, local[2]));
}

// Rays from a patch: area-uniform origins (triangle by inverse CDF of area, then a point in it),
// cosine-weighted directions about the triangle's normal.
struct PatchRays {
  struct Triangle {
    Vec3 v0, e1, e2;
    Frame frame;
    double offset = 0.0;
  };
  std::vector<Triangle> triangles;
  std::vector<double> cdf;  // cumulative area fraction after each triangle; last is 1

  void make(const double (&u)[sampling::kDimensions], Vec3& origin, Vec3& dir) const {
    const auto it = std::upper_bound(cdf.begin(), cdf.end() - 1, u[0]);
    const auto k = static_cast<std::size_t>(it - cdf.begin());
    const double lo = k == 0 ? 0.0 : cdf[k - 1];
    const double s = std::clamp((u[0] - lo) / (cdf[k] - lo), 0.0, 1.0);
    const Triangle& t = triangles[k];
    const auto w = sampling::squareToTriangle(s, u[1]);
    origin = add(add(add(t.v0, scale(t.e1, w[1])), scale(t.e2, w[2])), scale(t.frame.n, t.offset));
    dir = toWorld(t.frame, sampling::squareToCosineHemisphere(u[2], u[3]));
  }
};

// Rays from a differential element: cosine-weighted about its normal.
struct ElementRays {
  Vec3 origin;
  Frame frame;
  void make(const double (&u)[sampling::kDimensions], Vec3& o, Vec3& dir) const {
    o = origin;
    dir = toWorld(frame, sampling::squareToCosineHemisphere(u[2], u[3]));
  }
};

// Rays from a point in all directions, uniformly.
struct SphereRays {
  Vec3 origin;
  void make(const double (&u)[sampling::kDimensions], Vec3& o, Vec3& dir) const {
    o = origin;
    const auto d = sampling::squareToSphere(u[2], u[3]);
    dir = {d[0], d[1], d[2]};
  }
};

std::uint64_t nextPowerOfTwo(std::uint64_t x) {
  std::uint64_t p = 1;
  while (p < x) p <<= 1;
  return p;
}

std::uint64_t bitsOf(double x) {
  std::uint64_t b = 0;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

std::uint64_t keyOf(const Vec3& a, const Vec3& b, std::uint64_t tag) {
  std::uint64_t k = tag;
  for (int i = 0; i < 3; ++i) k = sampling::combine(k, bitsOf(a[i]));
  for (int i = 0; i < 3; ++i) k = sampling::combine(k, bitsOf(b[i]));
  return k;
}

void checkOptions(const SamplingOptions& o) {
  if (o.replicates < 2) throw std::invalid_argument("sampling: replicates must be >= 2");
  if (!(o.absoluteTolerance >= 0.0) || !std::isfinite(o.absoluteTolerance))
    throw std::invalid_argument("sampling: the absolute tolerance must be >= 0");
  if (!(o.relativeTolerance >= 0.0) || !std::isfinite(o.relativeTolerance))
    throw std::invalid_argument("sampling: the relative tolerance must be >= 0");
  if (o.rays == 0 && o.absoluteTolerance == 0.0 && o.relativeTolerance == 0.0)
    throw std::invalid_argument("sampling: give a ray count or a tolerance");
  if (o.rays == 0 && o.maxRays < o.minRays)
    throw std::invalid_argument("sampling: max rays must be >= min rays");
  if (o.rays > (std::uint64_t{1} << 40) || o.maxRays > (std::uint64_t{1} << 40))
    throw std::invalid_argument("sampling: more than 2^40 rays per receiver");
}

// Mean and standard error of the replicate values.
Estimate estimateOf(const std::vector<double>& values) {
  const double r = static_cast<double>(values.size());
  double mean = 0.0;
  for (double v : values) mean += v;
  mean /= r;
  double ss = 0.0;
  for (double v : values) ss += (v - mean) * (v - mean);
  return {mean, std::sqrt(ss / (r * (r - 1.0)))};
}

}  // namespace

struct ViewFactorSolver::Impl {
  explicit Impl(const RaySceneOptions& options) : rays(options) {}
  RadiationScene scene;
  RayScene rays;
  std::uint32_t surfacesId = kAbsent, occluderId = kAbsent, emittersId = kAbsent;
  std::vector<Vec3> surfaceNormal;  // per surface triangle
  std::vector<double> exitance;     // eps sigma T^4 per emitter
  double occluderExitance = 0.0;
  double sceneScale = 1.0;          // coordinate magnitude of the scene, for origin offsets

  std::size_t patches() const { return scene.surfaces.patchCount(); }
  std::size_t groups() const { return scene.emitters.groupNames.size(); }
  // Tally categories: patches, groups, occluder, space, back face.
  std::size_t categories() const { return patches() + groups() + 3; }

  template <class Rays>
  ReceiverResult run(const Rays& gen, std::uint64_t stream, const SamplingOptions& o,
                     double fluxFactor) const;
};

ViewFactorSolver::ViewFactorSolver(RadiationScene scene, const RaySceneOptions& rayOptions)
    : impl_(std::make_unique<Impl>(rayOptions)) {
  Impl& m = *impl_;
  m.scene = std::move(scene);
  const RadiationScene& s = m.scene;
  double scale = 0.0;
  if (!s.surfaces.triangles.empty()) {
    validateMesh(s.surfaces, "surfaces");
    m.surfacesId = m.rays.addTriangles(s.surfaces);
    m.surfaceNormal.resize(s.surfaces.triangleCount());
    for (std::size_t t = 0; t < s.surfaces.triangleCount(); ++t)
      m.surfaceNormal[t] = s.surfaces.triangleNormal(t);
    scale = std::max(scale, maxAbs(s.surfaces.boundingCenter()) + s.surfaces.boundingRadius());
  }
  if (!s.occluder.mesh.triangles.empty()) {
    validateMesh(s.occluder.mesh, "occluder");
    if (!(s.occluder.temperature >= 0.0) || !std::isfinite(s.occluder.temperature))
      throw std::invalid_argument("occluder temperature must be >= 0");
    if (!(s.occluder.emissivity > 0.0 && s.occluder.emissivity <= 1.0))
      throw std::invalid_argument("occluder emissivity must be in (0, 1]");
    m.occluderId = m.rays.addTriangles(s.occluder.mesh);
    const double t2 = s.occluder.temperature * s.occluder.temperature;
    m.occluderExitance = s.occluder.emissivity * kStefanBoltzmann * t2 * t2;
    scale = std::max(scale, maxAbs(s.occluder.mesh.boundingCenter()) + s.occluder.mesh.boundingRadius());
  }
  if (!s.emitters.empty()) {
    const Emitters& e = s.emitters;
    if (e.y.size() != e.size() || e.z.size() != e.size() || e.radius.size() != e.size() ||
        e.temperature.size() != e.size() || e.emissivity.size() != e.size() || e.group.size() != e.size())
      throw std::invalid_argument("emitters: arrays of different lengths");
    // Arrays may have been filled directly rather than through Emitters::add: check them here.
    for (std::size_t i = 0; i < e.size(); ++i) {
      const bool ok = std::isfinite(e.x[i]) && std::isfinite(e.y[i]) && std::isfinite(e.z[i]) &&
                      e.radius[i] > 0.0 && std::isfinite(e.radius[i]) && e.temperature[i] >= 0.0 &&
                      std::isfinite(e.temperature[i]) && e.emissivity[i] > 0.0 && e.emissivity[i] <= 1.0 &&
                      e.group[i] < e.groupNames.size();
      if (!ok)
        throw std::invalid_argument("emitter " + std::to_string(i) +
                                    ": a non-finite centre, radius <= 0, temperature < 0, emissivity "
                                    "outside (0, 1] or group out of range");
    }
    m.emittersId = m.rays.addSpheres(e.x, e.y, e.z, e.radius);
    m.exitance.resize(e.size());
    for (std::size_t i = 0; i < e.size(); ++i) m.exitance[i] = e.exitance(i);
  }
  m.sceneScale = scale > 0.0 ? scale : 1.0;
  m.rays.commit();
}

ViewFactorSolver::~ViewFactorSolver() = default;
ViewFactorSolver::ViewFactorSolver(ViewFactorSolver&&) noexcept = default;
ViewFactorSolver& ViewFactorSolver::operator=(ViewFactorSolver&&) noexcept = default;

const RadiationScene& ViewFactorSolver::scene() const { return impl_->scene; }

template <class Rays>
ReceiverResult ViewFactorSolver::Impl::run(const Rays& gen, std::uint64_t stream,
                                           const SamplingOptions& o, double fluxFactor) const {
  checkOptions(o);
  const auto R = static_cast<std::size_t>(o.replicates);
  const std::size_t P = patches(), G = groups(), C = categories();
  const std::size_t F = G + 1;  // flux slots: groups, occluder
  const std::size_t catOccluder = P + G, catSpace = P + G + 1, catBack = P + G + 2;

  const bool fixed = o.rays > 0;
  const auto perReplicate = [R](std::uint64_t total) {
    return std::max<std::uint64_t>(kBlock, nextPowerOfTwo((total + R - 1) / R));
  };
  std::uint64_t n = perReplicate(fixed ? o.rays : o.minRays);
  // The adaptive limit: the largest power of two per replicate within maxRays in all.
  std::uint64_t nMax = kBlock;
  while (2 * nMax * R <= o.maxRays) nMax *= 2;
  nMax = std::max(n, nMax);
  if (n > (std::uint64_t{1} << 32)) throw std::invalid_argument("sampling: more than 2^32 rays per replicate");

  std::vector<PointSet> sets;
  const std::uint64_t receiverKey = sampling::combine(o.seed, stream);
  for (std::size_t r = 0; r < R; ++r) sets.emplace_back(o.sampler, sampling::combine(receiverKey, r));

  std::vector<std::uint64_t> counts(R * C, 0);
  std::vector<double> flux(R * F, 0.0);
  const TriangleMesh& surf = scene.surfaces;
  const Emitters& em = scene.emitters;

  // Traces points [a, b) of every replicate and adds them to counts and flux.
  auto process = [&](std::uint64_t a, std::uint64_t b) {
    const std::uint64_t chunk = std::min(kChunk, b - a);
    const std::uint64_t chunks = (b - a) / chunk;
    const std::size_t items = R * static_cast<std::size_t>(chunks);
    std::vector<double> itemFlux(items * F, 0.0);
    std::exception_ptr failure;
#pragma omp parallel
    {
      std::vector<std::uint64_t> local(R * C, 0);
      auto block = std::make_unique<RayBlock>();
      const auto points = std::make_unique<double[][sampling::kDimensions]>(kBlock);
      double (*u)[sampling::kDimensions] = points.get();
#pragma omp for schedule(dynamic)
      for (std::size_t item = 0; item < items; ++item) {
        try {
          const std::size_t r = item / chunks;
          const std::uint64_t start = a + (item % chunks) * chunk;
          double* fl = &itemFlux[item * F];
          std::uint64_t* cnt = &local[r * C];
          for (std::uint64_t bs = start; bs < start + chunk; bs += kBlock) {
            const int count = static_cast<int>(std::min<std::uint64_t>(kBlock, start + chunk - bs));
            block->count = count;
            sets[r].block(static_cast<std::uint32_t>(bs), count, u);
            for (int i = 0; i < count; ++i) {
              Vec3 origin, dir;
              gen.make(u[i], origin, dir);
              block->ox[i] = static_cast<float>(origin[0]);
              block->oy[i] = static_cast<float>(origin[1]);
              block->oz[i] = static_cast<float>(origin[2]);
              block->dx[i] = static_cast<float>(dir[0]);
              block->dy[i] = static_cast<float>(dir[1]);
              block->dz[i] = static_cast<float>(dir[2]);
            }
            rays.trace(*block, o.trace);
            for (int i = 0; i < count; ++i) {
              const std::uint32_t geom = block->geometry[i], prim = block->primitive[i];
              if (geom == kAbsent) {
                ++cnt[catSpace];
              } else if (geom == surfacesId) {
                const Vec3& nt = surfaceNormal[prim];
                const double facing = nt[0] * block->dx[i] + nt[1] * block->dy[i] + nt[2] * block->dz[i];
                ++cnt[facing > 0.0 ? catBack : surf.patchOf[prim]];
              } else if (geom == emittersId) {
                const std::uint32_t g = em.group[prim];
                ++cnt[P + g];
                fl[g] += exitance[prim];
              } else {  // the occluder
                ++cnt[catOccluder];
                fl[G] += occluderExitance;
              }
            }
          }
        } catch (...) {
#pragma omp critical(ejecta_viewfactor_failure)
          if (!failure) failure = std::current_exception();
        }
      }
#pragma omp critical(ejecta_viewfactor_merge)
      for (std::size_t k = 0; k < counts.size(); ++k) counts[k] += local[k];  // integers: exact
    }
    if (failure) std::rethrow_exception(failure);
    // Item order, not thread order: the sums are the same for any thread count.
    for (std::size_t item = 0; item < items; ++item) {
      const std::size_t r = item / chunks;
      for (std::size_t f = 0; f < F; ++f) flux[r * F + f] += itemFlux[item * F + f];
    }
  };

  ReceiverResult res;
  res.replicates = static_cast<int>(R);
  std::uint64_t done = 0;
  std::vector<double> per(R);
  for (;;) {
    process(done, n);
    done = n;
    const double inv = 1.0 / static_cast<double>(done);
    auto fraction = [&](std::size_t cat) {
      for (std::size_t r = 0; r < R; ++r) per[r] = static_cast<double>(counts[r * C + cat]) * inv;
      return estimateOf(per);
    };
    res.rays = done * R;
    res.toPatch.assign(P, {});
    res.toGroup.assign(G, {});
    res.fluxFromGroup.assign(G, {});
    for (std::size_t p = 0; p < P; ++p) res.toPatch[p] = fraction(p);
    for (std::size_t g = 0; g < G; ++g) {
      res.toGroup[g] = fraction(P + g);
      for (std::size_t r = 0; r < R; ++r) per[r] = fluxFactor * flux[r * F + g] * inv;
      res.fluxFromGroup[g] = estimateOf(per);
    }
    res.toOccluder = fraction(catOccluder);
    res.toSpace = fraction(catSpace);
    res.toBackFace = fraction(catBack);
    for (std::size_t r = 0; r < R; ++r) {
      std::uint64_t hits = 0;
      for (std::size_t g = 0; g < G; ++g) hits += counts[r * C + P + g];
      per[r] = static_cast<double>(hits) * inv;
    }
    res.toEmitters = estimateOf(per);
    for (std::size_t r = 0; r < R; ++r) per[r] = fluxFactor * flux[r * F + G] * inv;
    res.fluxFromOccluder = estimateOf(per);
    for (std::size_t r = 0; r < R; ++r) {
      double sum = 0.0;
      for (std::size_t f = 0; f < F; ++f) sum += flux[r * F + f];
      per[r] = fluxFactor * sum * inv;
    }
    res.flux = estimateOf(per);
    if (fixed) break;

    double worst = std::max({res.toEmitters.standardError, res.toOccluder.standardError,
                             res.toSpace.standardError, res.toBackFace.standardError});
    for (const Estimate& e : res.toPatch) worst = std::max(worst, e.standardError);
    for (const Estimate& e : res.toGroup) worst = std::max(worst, e.standardError);
    bool ok = o.absoluteTolerance == 0.0 || worst <= o.absoluteTolerance;
    if (o.relativeTolerance > 0.0 && res.flux.value > 0.0)
      ok = ok && res.flux.standardError <= o.relativeTolerance * res.flux.value;
    if (ok) break;
    if (2 * n > nMax) {
      res.converged = false;
      break;
    }
    n *= 2;
  }
  return res;
}

ReceiverResult ViewFactorSolver::fromPatch(std::size_t patch, const SamplingOptions& o) const {
  const TriangleMesh& s = impl_->scene.surfaces;
  if (patch >= s.patchCount())
    throw std::invalid_argument("no surface patch " + std::to_string(patch) + " (there are " +
                                std::to_string(s.patchCount()) + ")");
  PatchRays gen;
  double area = 0.0;
  std::vector<double> areas;
  for (std::size_t t = 0; t < s.triangleCount(); ++t) {
    if (s.patchOf[t] != patch) continue;
    const double a = s.triangleArea(t);
    if (!(a > 0.0)) continue;  // degenerate: never sampled
    const auto& tri = s.triangles[t];
    PatchRays::Triangle pt;
    pt.v0 = s.vertices[tri[0]];
    pt.e1 = sub(s.vertices[tri[1]], pt.v0);
    pt.e2 = sub(s.vertices[tri[2]], pt.v0);
    pt.frame = frameAbout(s.triangleNormal(t));
    pt.offset = std::max({maxAbs(pt.v0), maxAbs(s.vertices[tri[1]]), maxAbs(s.vertices[tri[2]])});
    gen.triangles.push_back(pt);
    areas.push_back(a);
    area += a;
  }
  if (!(area > 0.0))
    throw std::invalid_argument("surface patch '" + s.patchNames[patch] + "' has no area");
  double cum = 0.0;
  for (std::size_t k = 0; k < areas.size(); ++k) {
    cum += areas[k];
    gen.cdf.push_back(cum / area);
    // Scale for the offset: the coordinates, and the patch size for patches near the origin.
    gen.triangles[k].offset = originOffset(gen.triangles[k].offset + std::sqrt(area));
  }
  gen.cdf.back() = 1.0;
  return impl_->run(gen, sampling::combine(0x9a7c4ull, patch), o, 1.0);
}

ReceiverResult ViewFactorSolver::fromPatch(const std::string& name, const SamplingOptions& o) const {
  const int p = impl_->scene.surfaces.findPatch(name);
  if (p < 0) throw std::invalid_argument("no surface patch named '" + name + "'");
  return fromPatch(static_cast<std::size_t>(p), o);
}

ReceiverResult ViewFactorSolver::fromPoint(const Vec3& point, const Vec3& normal,
                                           const SamplingOptions& o) const {
  if (!finite(point) || !finite(normal) || norm(normal) == 0.0)
    throw std::invalid_argument("a receiving element needs a finite point and a non-zero normal");
  ElementRays gen;
  gen.frame = frameAbout(normal);
  gen.origin = add(point, scale(gen.frame.n, originOffset(maxAbs(point) + 1e-3 * impl_->sceneScale)));
  return impl_->run(gen, keyOf(point, normal, 0xe1e7ull), o, 1.0);
}

ReceiverResult ViewFactorSolver::allDirectionsFrom(const Vec3& point, const SamplingOptions& o) const {
  if (!finite(point)) throw std::invalid_argument("the point must be finite");
  SphereRays gen;
  gen.origin = point;
  // Uniform directions: the integral of the radiance over 4 pi sr is 4 x the mean of eps sigma T^4.
  return impl_->run(gen, keyOf(point, Vec3{}, 0x5fe7ull), o, 4.0);
}

Estimate ViewFactorSolver::emitterSolidAngle(const Vec3& point, const SamplingOptions& o) const {
  const Estimate f = allDirectionsFrom(point, o).toEmitters;
  constexpr double fourPi = 4.0 * std::numbers::pi;
  return {fourPi * f.value, fourPi * f.standardError};
}

}  // namespace ejecta::radiation
