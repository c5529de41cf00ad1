#include "render/view_transform.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace ejecta::render {

namespace {

constexpr double kFitMargin = 1.06;  // auto-fit: 3% of empty space on each side

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
Vec3 scaled(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }

Mat4 identity() { return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}; }

// The eye frame of a camera at `eye` looking at `target`: right, up, backwards (OpenGL's).
Mat4 lookAt(const Vec3& eye, const Vec3& target, const Vec3& upHint) {
  const Vec3 forward = sub(target, eye);
  const double distance = norm(forward);
  const Vec3 f = scaled(forward, 1.0 / distance);
  Vec3 s = cross(f, upHint);
  const double sLength = norm(s);
  if (!(sLength > 1e-9 * norm(upHint)))
    throw std::invalid_argument("camera: 'up' is along the line of sight");
  s = scaled(s, 1.0 / sLength);
  const Vec3 u = cross(s, f);
  Mat4 m = identity();
  for (int i = 0; i < 3; ++i) {
    m[i * 4 + 0] = s[i];
    m[i * 4 + 1] = u[i];
    m[i * 4 + 2] = -f[i];
  }
  m[12] = -dot(s, eye);
  m[13] = -dot(u, eye);
  m[14] = dot(f, eye);
  return m;
}

Mat4 orthographic(double left, double right, double bottom, double top, double near, double far) {
  Mat4 m = identity();
  m[0] = 2.0 / (right - left);
  m[5] = 2.0 / (top - bottom);
  m[10] = -2.0 / (far - near);
  m[12] = -(right + left) / (right - left);
  m[13] = -(top + bottom) / (top - bottom);
  m[14] = -(far + near) / (far - near);
  return m;
}

Mat4 perspective(double fovY, double aspect, double near, double far) {
  const double f = 1.0 / std::tan(fovY / 2.0);
  Mat4 m{};
  m[0] = f / aspect;
  m[5] = f;
  m[10] = (far + near) / (near - far);
  m[11] = -1.0;
  m[14] = 2.0 * far * near / (near - far);
  return m;
}

std::array<double, 4> apply(const Mat4& m, const std::array<double, 4>& v) {
  std::array<double, 4> out{};
  for (int r = 0; r < 4; ++r)
    out[r] = m[r] * v[0] + m[4 + r] * v[1] + m[8 + r] * v[2] + m[12 + r] * v[3];
  return out;
}

// The box of a particle layer's discs (OpenMP reductions: min and max are exact, so the result
// does not depend on the thread count). Non-finite positions are skipped.
Bounds particleBounds(const ParticleLayer& layer) {
  double lo0 = 1e300, lo1 = 1e300, lo2 = 1e300, hi0 = -1e300, hi1 = -1e300, hi2 = -1e300;
  const auto n = static_cast<std::ptrdiff_t>(layer.x.size());
  const bool hasZ = !layer.z.empty();
#pragma omp parallel for schedule(static) reduction(min                            \
                                                    : lo0, lo1, lo2) reduction(max \
                                                                               : hi0, hi1, hi2)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const double x = layer.x[k], y = layer.y[k], z = hasZ ? layer.z[k] : 0.0;
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) continue;
    const double r = layer.discRadius(k);
    lo0 = std::min(lo0, x - r);
    lo1 = std::min(lo1, y - r);
    lo2 = std::min(lo2, z - r);
    hi0 = std::max(hi0, x + r);
    hi1 = std::max(hi1, y + r);
    hi2 = std::max(hi2, z + r);
  }
  Bounds b;
  if (lo0 <= hi0) {
    b.lo = {lo0, lo1, lo2};
    b.hi = {hi0, hi1, hi2};
  }
  return b;
}

// The farthest reach of a particle layer's discs from c (and of their mirror images).
double particleReach(const ParticleLayer& layer, const Vec3& c, bool mirror) {
  double reach2 = 0.0;
  const auto n = static_cast<std::ptrdiff_t>(layer.x.size());
  const bool hasZ = !layer.z.empty();
#pragma omp parallel for schedule(static) reduction(max : reach2)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const double r = layer.discRadius(k);
    const double dy = layer.y[k] - c[1], dz = (hasZ ? layer.z[k] : 0.0) - c[2];
    for (double x : {layer.x[k], mirror ? -layer.x[k] : layer.x[k]}) {
      const double dx = x - c[0];
      const double reach = std::sqrt(dx * dx + dy * dy + dz * dz) + r;
      if (std::isfinite(reach)) reach2 = std::max(reach2, reach * reach);
    }
  }
  return reach2;
}

}  // namespace

std::array<Vec3, 4> sliceCorners(const SliceLayer& s) {
  std::array<Vec3, 4> corners{};
  int n = 0;
  for (double j : {-0.5, s.ny - 0.5})
    for (double i : {-0.5, s.nx - 0.5}) {
      Vec3& p = corners[static_cast<std::size_t>(n++)];
      for (int k = 0; k < 3; ++k)
        p[k] = s.origin[k] + i * s.spacing[0] * s.uAxis[k] + j * s.spacing[1] * s.vAxis[k];
    }
  return corners;
}

void Bounds::add(const Vec3& p, double radius) {
  for (int k = 0; k < 3; ++k) {
    if (!std::isfinite(p[k])) return;  // a lost particle must not blow up the framing
  }
  for (int k = 0; k < 3; ++k) {
    lo[k] = std::min(lo[k], p[k] - radius);
    hi[k] = std::max(hi[k], p[k] + radius);
  }
}

void Bounds::add(const Bounds& other) {
  if (other.empty()) return;
  add(other.lo);
  add(other.hi);
}

Vec3 Bounds::center() const {
  return {(lo[0] + hi[0]) / 2.0, (lo[1] + hi[1]) / 2.0, (lo[2] + hi[2]) / 2.0};
}

PictureExtent measurePicture(const Picture& scene, bool mirror) {
  PictureExtent extent;
  Bounds& b = extent.bounds;
  for (const ParticleLayer& layer : scene.particles) b.add(particleBounds(layer));
  for (const MeshLayer& layer : scene.meshes)
    for (const Vec3& v : layer.vertices) b.add(v);
  for (const SliceLayer& s : scene.slices)
    for (const Vec3& corner : sliceCorners(s)) b.add(corner);
  if (b.empty()) return extent;
  if (mirror) {
    const double r = std::max(std::abs(b.lo[0]), std::abs(b.hi[0]));
    b.lo[0] = -r;
    b.hi[0] = r;
  }
  // The bounding sphere about the box's centre: the farthest point, not the half diagonal, so
  // that a round body fills the picture.
  const Vec3 c = b.center();
  double r2 = 0.0;
  auto far = [&](const Vec3& p, double radius) {
    const Vec3 d = sub(p, c);
    const double reach = norm(d) + radius;
    if (std::isfinite(reach)) r2 = std::max(r2, reach * reach);
  };
  for (const ParticleLayer& layer : scene.particles)
    r2 = std::max(r2, particleReach(layer, c, mirror));
  for (const MeshLayer& layer : scene.meshes)
    for (const Vec3& v : layer.vertices) far(v, 0.0);
  for (const SliceLayer& s : scene.slices)
    for (const Vec3& corner : sliceCorners(s)) {
      far(corner, 0.0);
      if (mirror) far({-corner[0], corner[1], corner[2]}, 0.0);
    }
  extent.radius = std::sqrt(r2);
  return extent;
}

std::array<double, 3> Framing::project(const Vec3& world) const {
  const Vec3 p = sub(world, origin);
  const auto clip = apply(projection, apply(view, {p[0], p[1], p[2], 1.0}));
  const double x = (clip[0] / clip[3] + 1.0) / 2.0 * plotWidth;
  const double y = (1.0 - clip[1] / clip[3]) / 2.0 * plotHeight;
  return {x, y, clip[3]};
}

Framing frameView(const View& view, const PictureExtent& extent, int plotWidth, int plotHeight) {
  if (plotWidth <= 0 || plotHeight <= 0)
    throw std::invalid_argument("view: the picture has no pixels (" + std::to_string(plotWidth) +
                                " x " + std::to_string(plotHeight) + ")");
  Framing f;
  f.plotWidth = plotWidth;
  f.plotHeight = plotHeight;
  const double aspect = static_cast<double>(plotWidth) / plotHeight;
  const Bounds& b = extent.bounds;
  const bool empty = b.empty();
  // Something to fall back on when nothing is drawn: a 1 m box at the origin.
  const Vec3 boxCenter = empty ? Vec3{0.0, 0.0, 0.0} : b.center();
  const double radius = empty || !(extent.radius > 0.0) ? 0.5 : extent.radius;

  if (view.kind != ViewKind::Perspective) {
    f.mirror = view.kind == ViewKind::Axisymmetric;
    double cx = boxCenter[0], cy = boxCenter[1];
    double width = view.width;
    if (view.width < 0.0 || !std::isfinite(view.width))
      throw std::invalid_argument("view: width must be > 0 (or 0 to fit), got " +
                                  std::to_string(view.width));
    if (width == 0.0) {
      const double bw = empty ? 1.0 : b.hi[0] - b.lo[0], bh = empty ? 1.0 : b.hi[1] - b.lo[1];
      width = std::max(bw, bh * aspect) * kFitMargin;
      if (!(width > 0.0)) width = 2.0 * radius;
    }
    if (view.center) {
      cx = (*view.center)[0];
      cy = (*view.center)[1];
    }
    const double height = width / aspect;
    // Depth: everything drawn, whatever its z, seen from +z.
    const double zc = boxCenter[2];
    const double depth = std::max(radius, empty ? 1.0 : (b.hi[2] - b.lo[2])) * 1.1 + 1e-9;
    f.origin = {cx, cy, zc};
    f.view = identity();
    f.projection = orthographic(-width / 2, width / 2, -height / 2, height / 2, -depth, depth);
    f.pixelsPerMetre = plotWidth / width;
    f.sizeScale = f.pixelsPerMetre;
    return f;
  }

  f.perspective = true;
  Camera camera;
  if (view.camera) {
    camera = *view.camera;
  } else {
    camera.fovYDegrees = view.autoFovYDegrees;
    const double dLength = norm(view.autoDirection);
    if (!(dLength > 0.0)) throw std::invalid_argument("view: autoDirection must not be zero");
    const Vec3 dir = scaled(view.autoDirection, 1.0 / dLength);
    // The sphere fits the narrower of the two fields of view.
    const double halfY = camera.fovYDegrees * std::numbers::pi / 360.0;
    const double halfX = std::atan(aspect * std::tan(halfY));
    const double distance = radius / std::sin(std::min(halfX, halfY)) * (kFitMargin - 0.04);
    camera.target = boxCenter;
    camera.position = {boxCenter[0] + dir[0] * distance, boxCenter[1] + dir[1] * distance,
                       boxCenter[2] + dir[2] * distance};
    camera.up = std::abs(dir[1]) > 0.999 ? Vec3{0.0, 0.0, -1.0} : Vec3{0.0, 1.0, 0.0};
  }
  if (!(camera.fovYDegrees > 0.0 && camera.fovYDegrees < 180.0))
    throw std::invalid_argument("camera: fovYDegrees must be in (0, 180), got " +
                                std::to_string(camera.fovYDegrees));
  const double targetDistance = norm(sub(camera.target, camera.position));
  if (!(targetDistance > 0.0)) throw std::invalid_argument("camera: position and target coincide");
  f.origin = boxCenter;
  f.view = lookAt(sub(camera.position, f.origin), sub(camera.target, f.origin), camera.up);
  // Near and far planes hug the scene's bounding sphere (a tight range keeps depth precise).
  const double centerDistance = norm(sub(boxCenter, camera.position));
  const double far = centerDistance + 1.01 * radius;
  const double near = std::max(centerDistance - 1.01 * radius, 1e-4 * far);
  const double fovY = camera.fovYDegrees * std::numbers::pi / 180.0;
  f.projection = perspective(fovY, aspect, near, far);
  f.sizeScale = f.projection[5] * plotHeight / 2.0;
  f.pixelsPerMetre = f.sizeScale / targetDistance;
  return f;
}

}  // namespace ejecta::render
