#include "radiation/spacecraft.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace ejecta::radiation {

using namespace vec3;

namespace {

constexpr double kPi = std::numbers::pi;

void requirePositive(double x, const char* what) {
  if (!(x > 0.0) || !std::isfinite(x))
    throw std::invalid_argument(std::string(what) + " must be positive and finite");
}

void requireFinite(const Vec3& v, const char* what) {
  if (!finite(v)) throw std::invalid_argument(std::string(what) + " must be finite");
}

// Two triangles p00 p10 p11, p00 p11 p01 of a quad given by its four vertex indices, in the
// order corner, corner + e1, corner + e1 + e2, corner + e2: the normal is e1 x e2.
void addQuad(TriangleMesh& m, std::uint32_t p00, std::uint32_t p10, std::uint32_t p11,
             std::uint32_t p01, std::uint32_t patch) {
  m.addTriangle(p00, p10, p11, patch);
  m.addTriangle(p00, p11, p01, patch);
}

// An orthonormal pair (u, v) with u x v = n for a unit n.
std::pair<Vec3, Vec3> tangentBasis(const Vec3& n) {
  const Vec3 helper = std::abs(n[0]) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  const Vec3 u = normalized(cross(helper, n));
  return {u, cross(n, u)};
}

// The radius of a regular n-gon with the area of a circle of radius r.
double equalAreaPolygonRadius(double r, int n) {
  const double a = 2.0 * kPi / n;
  return r * std::sqrt(a / std::sin(a));
}

// The eight corners of the box [lo, hi], index i + 2 j + 4 k for (x, y, z) at (lo|hi).
std::uint32_t addBoxCorners(TriangleMesh& m, const Vec3& lo, const Vec3& hi) {
  const auto base = static_cast<std::uint32_t>(m.vertices.size());
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) m.addVertex({i ? hi[0] : lo[0], j ? hi[1] : lo[1], k ? hi[2] : lo[2]});
  return base;
}

// The six outward faces of a box whose corners start at `c` (see addBoxCorners), named
// in the order +x, -x, +y, -y, +z, -z.
void addBoxFaces(TriangleMesh& m, std::uint32_t c, const std::array<std::string, 6>& names) {
  auto v = [c](int i, int j, int k) { return c + static_cast<std::uint32_t>(i + 2 * j + 4 * k); };
  addQuad(m, v(1, 0, 0), v(1, 1, 0), v(1, 1, 1), v(1, 0, 1), m.patchIndex(names[0]));  // y x z = +x
  addQuad(m, v(0, 0, 0), v(0, 0, 1), v(0, 1, 1), v(0, 1, 0), m.patchIndex(names[1]));  // z x y = -x
  addQuad(m, v(0, 1, 0), v(0, 1, 1), v(1, 1, 1), v(1, 1, 0), m.patchIndex(names[2]));  // z x x = +y
  addQuad(m, v(0, 0, 0), v(1, 0, 0), v(1, 0, 1), v(0, 0, 1), m.patchIndex(names[3]));  // x x z = -y
  addQuad(m, v(0, 0, 1), v(1, 0, 1), v(1, 1, 1), v(0, 1, 1), m.patchIndex(names[4]));  // x x y = +z
  addQuad(m, v(0, 0, 0), v(0, 1, 0), v(1, 1, 0), v(1, 0, 0), m.patchIndex(names[5]));  // y x x = -z
}

}  // namespace

Rotation Rotation::fromForwardUp(const Vec3& forward, const Vec3& up) {
  requireFinite(forward, "forward");
  requireFinite(up, "up");
  const Vec3 x = normalized(forward);
  if (norm(x) == 0.0) throw std::invalid_argument("forward must not be the zero vector");
  const Vec3 yRaw = sub(up, scale(x, dot(up, x)));
  if (norm(yRaw) <= 1e-9 * norm(up) || norm(up) == 0.0)
    throw std::invalid_argument("up must not be zero or parallel to forward");
  const Vec3 y = normalized(yRaw);
  const Vec3 z = cross(x, y);
  Rotation r;
  for (int i = 0; i < 3; ++i) r.row[i] = {x[i], y[i], z[i]};
  return r;
}

Rotation Rotation::fromAxisAngle(const Vec3& axis, double angle) {
  requireFinite(axis, "rotation axis");
  if (!std::isfinite(angle)) throw std::invalid_argument("rotation angle must be finite");
  const Vec3 k = normalized(axis);
  if (norm(k) == 0.0) throw std::invalid_argument("rotation axis must not be the zero vector");
  const double c = std::cos(angle), s = std::sin(angle), t = 1.0 - c;
  Rotation r;
  r.row[0] = {c + t * k[0] * k[0], t * k[0] * k[1] - s * k[2], t * k[0] * k[2] + s * k[1]};
  r.row[1] = {t * k[1] * k[0] + s * k[2], c + t * k[1] * k[1], t * k[1] * k[2] - s * k[0]};
  r.row[2] = {t * k[2] * k[0] - s * k[1], t * k[2] * k[1] + s * k[0], c + t * k[2] * k[2]};
  return r;
}

Pose Pose::at(double dt) const {
  Pose p = *this;
  p.position = add(position, scale(velocity, dt));
  return p;
}

TriangleMesh placeMesh(const TriangleMesh& body, const Pose& pose) {
  TriangleMesh world = body;
  for (Vec3& v : world.vertices) v = pose.toWorld(v);
  return world;
}

TriangleMesh makeBox(double depth, double height, double width) {
  requirePositive(depth, "box depth");
  requirePositive(height, "box height");
  requirePositive(width, "box width");
  TriangleMesh m;
  const Vec3 half{0.5 * depth, 0.5 * height, 0.5 * width};
  const std::uint32_t c = addBoxCorners(m, scale(half, -1.0), half);
  addBoxFaces(m, c, {"side0", "aft", "side1", "side2", "side3", "side4"});
  return m;
}

TriangleMesh makeEnclosure(const Vec3& lo, const Vec3& hi) {
  requireFinite(lo, "enclosure corner");
  requireFinite(hi, "enclosure corner");
  for (int k = 0; k < 3; ++k) requirePositive(hi[k] - lo[k], "enclosure size");
  TriangleMesh m;
  const std::uint32_t c = addBoxCorners(m, lo, hi);
  // Outward faces named after the wall they are, then turned to face the inside.
  addBoxFaces(m, c, {"x+", "x-", "y+", "y-", "z+", "z-"});
  m.flip();
  return m;
}

TriangleMesh makeCylinder(double radius, double length, int segments, int sectors) {
  requirePositive(radius, "cylinder radius");
  requirePositive(length, "cylinder length");
  if (segments < 3) throw std::invalid_argument("a cylinder needs at least 3 segments");
  if (sectors < 1 || segments % sectors != 0)
    throw std::invalid_argument("cylinder sectors must divide the segment count");
  TriangleMesh m;
  const double r = equalAreaPolygonRadius(radius, segments);
  const double x0 = -0.5 * length, x1 = 0.5 * length;
  // Vertex j at angle phi_j from +y towards +z; sector 0 is centred on phi = 0.
  const double offset = -kPi / sectors;
  std::vector<std::uint32_t> ring0(segments), ring1(segments);
  for (int j = 0; j < segments; ++j) {
    const double phi = offset + 2.0 * kPi * j / segments;
    const double y = r * std::cos(phi), z = r * std::sin(phi);
    ring0[j] = m.addVertex({x0, y, z});
    ring1[j] = m.addVertex({x1, y, z});
  }
  const std::uint32_t c0 = m.addVertex({x0, 0, 0}), c1 = m.addVertex({x1, 0, 0});
  const std::uint32_t front = m.patchIndex("front"), aft = m.patchIndex("aft");
  std::vector<std::uint32_t> side(sectors);
  for (int s = 0; s < sectors; ++s)
    side[s] = m.patchIndex(sectors == 1 ? std::string("side") : "side" + std::to_string(s));
  const int perSector = segments / sectors;
  for (int j = 0; j < segments; ++j) {
    const int k = (j + 1) % segments;
    // Mantle: (phi_j, x0) (phi_k, x0) (phi_k, x1) (phi_j, x1): tangent x axis = outward.
    addQuad(m, ring0[j], ring0[k], ring1[k], ring1[j], side[j / perSector]);
    m.addTriangle(c1, ring1[j], ring1[k], front);  // sin(phi_k - phi_j) > 0: +x
    m.addTriangle(c0, ring0[k], ring0[j], aft);
  }
  return m;
}

TriangleMesh makeRectangle(const std::string& patch, const Vec3& corner, const Vec3& edge1,
                           const Vec3& edge2) {
  requireFinite(corner, "rectangle corner");
  requireFinite(edge1, "rectangle edge");
  requireFinite(edge2, "rectangle edge");
  if (norm(cross(edge1, edge2)) == 0.0)
    throw std::invalid_argument("rectangle edges must not be zero or parallel");
  TriangleMesh m;
  const std::uint32_t p00 = m.addVertex(corner), p10 = m.addVertex(add(corner, edge1)),
                      p11 = m.addVertex(add(add(corner, edge1), edge2)),
                      p01 = m.addVertex(add(corner, edge2));
  addQuad(m, p00, p10, p11, p01, m.patchIndex(patch));
  return m;
}

TriangleMesh makeDisc(const std::string& patch, const Vec3& center, const Vec3& normal,
                      double radius, int segments) {
  requireFinite(center, "disc centre");
  requireFinite(normal, "disc normal");
  requirePositive(radius, "disc radius");
  if (segments < 3) throw std::invalid_argument("a disc needs at least 3 segments");
  const Vec3 n = normalized(normal);
  if (norm(n) == 0.0) throw std::invalid_argument("disc normal must not be the zero vector");
  const auto [u, v] = tangentBasis(n);
  const double r = equalAreaPolygonRadius(radius, segments);
  TriangleMesh m;
  const std::uint32_t c = m.addVertex(center);
  for (int j = 0; j < segments; ++j) {
    const double phi = 2.0 * kPi * j / segments;
    m.addVertex(add(center, add(scale(u, r * std::cos(phi)), scale(v, r * std::sin(phi)))));
  }
  const std::uint32_t p = m.patchIndex(patch);
  for (int j = 0; j < segments; ++j)
    m.addTriangle(c, c + 1 + static_cast<std::uint32_t>(j),
                  c + 1 + static_cast<std::uint32_t>((j + 1) % segments), p);
  return m;
}

TriangleMesh makeSphere(const std::string& patch, const Vec3& center, double radius,
                        int subdivisions) {
  requireFinite(center, "sphere centre");
  requirePositive(radius, "sphere radius");
  if (subdivisions < 0 || subdivisions > 8)
    throw std::invalid_argument("sphere subdivisions must be in [0, 8]");
  // The icosahedron: the 12 cyclic permutations of (0, +-1, +-phi).
  const double g = 0.5 * (1.0 + std::sqrt(5.0));
  std::vector<Vec3> v = {{-1, g, 0}, {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                         {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
  for (Vec3& p : v) p = normalized(p);
  std::vector<std::array<std::uint32_t, 3>> f = {
      {0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
      {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int level = 0; level < subdivisions; ++level) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoint;
    auto mid = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      const auto it = midpoint.find(key);
      if (it != midpoint.end()) return it->second;
      v.push_back(normalized(add(v[a], v[b])));
      const auto idx = static_cast<std::uint32_t>(v.size() - 1);
      midpoint.emplace(key, idx);
      return idx;
    };
    std::vector<std::array<std::uint32_t, 3>> next;
    next.reserve(f.size() * 4);
    for (const auto& t : f) {
      const std::uint32_t ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
      next.push_back({t[0], ab, ca});
      next.push_back({t[1], bc, ab});
      next.push_back({t[2], ca, bc});
      next.push_back({ab, bc, ca});
    }
    f = std::move(next);
  }
  TriangleMesh m;
  for (const Vec3& p : v) m.addVertex(add(center, scale(p, radius)));
  const std::uint32_t patchIdx = m.patchIndex(patch);
  for (auto t : f) {
    // Outward winding: the normal must point away from the centre.
    const Vec3 n = cross(sub(v[t[1]], v[t[0]]), sub(v[t[2]], v[t[0]]));
    if (dot(n, add(add(v[t[0]], v[t[1]]), v[t[2]])) < 0.0) std::swap(t[1], t[2]);
    m.addTriangle(t[0], t[1], t[2], patchIdx);
  }
  return m;
}

}  // namespace ejecta::radiation
