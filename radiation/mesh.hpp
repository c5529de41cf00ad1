#pragma once
// Triangle mesh with named patches: the receiving and blocking surfaces of the radiation code
// (a spacecraft's faces, test plates, the asteroid surface). Every triangle belongs to one patch;
// a patch is what view factors and fluxes are reported for. Triangles are one-sided: the front
// is the side the right-hand normal (v1 - v0) x (v2 - v0) points to (counter-clockwise seen from
// the front), and only the front emits and receives. Method and conventions: docs/view_factors.md.
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/input_error.hpp"

namespace ejecta::radiation {

using Vec3 = std::array<double, 3>;

// Small vector helpers in their own namespace, so they meet nothing else of the same name.
namespace vec3 {
inline Vec3 add(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3 scale(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
// a / |a|; the zero vector stays zero.
inline Vec3 normalized(const Vec3& a) {
  const double n = norm(a);
  return n > 0.0 ? scale(a, 1.0 / n) : Vec3{0.0, 0.0, 0.0};
}
inline bool finite(const Vec3& a) {
  return std::isfinite(a[0]) && std::isfinite(a[1]) && std::isfinite(a[2]);
}
}  // namespace vec3

// A malformed mesh file or mesh: the message names the file, the line (or triangle) and why.
class MeshError : public InputError {
 public:
  using InputError::InputError;
};

struct TriangleMesh {
  std::vector<Vec3> vertices;                        // [m]
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::uint32_t> patchOf;                // patch index of each triangle
  std::vector<std::string> patchNames;               // unique

  std::size_t triangleCount() const { return triangles.size(); }
  std::size_t patchCount() const { return patchNames.size(); }

  // The index of the patch called `name`, or -1.
  int findPatch(const std::string& name) const;
  // The index of `name`, adding an empty patch of that name if there is none.
  std::uint32_t patchIndex(const std::string& name);
  // Appends a triangle to patch `patch` (vertex indices must already exist).
  void addTriangle(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t patch);
  std::uint32_t addVertex(const Vec3& v);

  double triangleArea(std::size_t t) const;
  // Unit normal of triangle t (zero for a degenerate triangle).
  Vec3 triangleNormal(std::size_t t) const;
  double patchArea(std::size_t patch) const;
  // Area-weighted centroid and unit mean normal of a patch (for a plane patch: its normal).
  Vec3 patchCentroid(std::size_t patch) const;
  Vec3 patchNormal(std::size_t patch) const;
  // Half the diagonal of the axis-aligned bounding box of all vertices (0 when empty).
  double boundingRadius() const;
  Vec3 boundingCenter() const;

  // Appends `other`, merging patches by name (a patch of the same name gains its triangles).
  void append(const TriangleMesh& other);
  // Reverses every triangle's orientation: inward-facing faces of a primitive become an
  // enclosure seen from inside.
  void flip();
};

// Checks a mesh before use and throws MeshError naming `source` and the reason: no triangles,
// a vertex index out of range, a non-finite vertex, an unnamed or empty patch list, patchOf of
// the wrong length. Degenerate (zero-area) triangles are allowed: they are never sampled and
// never hit.
void validateMesh(const TriangleMesh& mesh, const std::string& source);

}  // namespace ejecta::radiation
