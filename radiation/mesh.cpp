#include "radiation/mesh.hpp"

#include <algorithm>
#include <vector>
#include <limits>
#include <unordered_map>

namespace ejecta::radiation {

using namespace vec3;

int TriangleMesh::findPatch(const std::string& name) const {
  for (std::size_t i = 0; i < patchNames.size(); ++i)
    if (patchNames[i] == name) return static_cast<int>(i);
  return -1;
}

std::uint32_t TriangleMesh::patchIndex(const std::string& name) {
  const int found = findPatch(name);
  if (found >= 0) return static_cast<std::uint32_t>(found);
  patchNames.push_back(name);
  return static_cast<std::uint32_t>(patchNames.size() - 1);
}

void TriangleMesh::addTriangle(std::uint32_t a, std::uint32_t b, std::uint32_t c,
                               std::uint32_t patch) {
  triangles.push_back({a, b, c});
  patchOf.push_back(patch);
}

std::uint32_t TriangleMesh::addVertex(const Vec3& v) {
  vertices.push_back(v);
  return static_cast<std::uint32_t>(vertices.size() - 1);
}

double TriangleMesh::triangleArea(std::size_t t) const {
  const auto& tri = triangles[t];
  const Vec3& a = vertices[tri[0]];
  return 0.5 * norm(cross(sub(vertices[tri[1]], a), sub(vertices[tri[2]], a)));
}

Vec3 TriangleMesh::triangleNormal(std::size_t t) const {
  const auto& tri = triangles[t];
  const Vec3& a = vertices[tri[0]];
  return normalized(cross(sub(vertices[tri[1]], a), sub(vertices[tri[2]], a)));
}

double TriangleMesh::patchArea(std::size_t patch) const {
  double area = 0.0;
  for (std::size_t t = 0; t < triangles.size(); ++t)
    if (patchOf[t] == patch) area += triangleArea(t);
  return area;
}

Vec3 TriangleMesh::patchCentroid(std::size_t patch) const {
  Vec3 sum{};
  double area = 0.0;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    if (patchOf[t] != patch) continue;
    const auto& tri = triangles[t];
    const Vec3 c = scale(add(add(vertices[tri[0]], vertices[tri[1]]), vertices[tri[2]]), 1.0 / 3.0);
    const double a = triangleArea(t);
    sum = add(sum, scale(c, a));
    area += a;
  }
  return area > 0.0 ? scale(sum, 1.0 / area) : sum;
}

Vec3 TriangleMesh::patchNormal(std::size_t patch) const {
  Vec3 sum{};
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    if (patchOf[t] != patch) continue;
    const auto& tri = triangles[t];
    const Vec3& a = vertices[tri[0]];
    sum = add(sum, cross(sub(vertices[tri[1]], a), sub(vertices[tri[2]], a)));  // 2 x area x n
  }
  return normalized(sum);
}

Vec3 TriangleMesh::boundingCenter() const {
  if (vertices.empty()) return {};
  Vec3 lo = vertices[0], hi = vertices[0];
  for (const Vec3& v : vertices)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], v[k]);
      hi[k] = std::max(hi[k], v[k]);
    }
  return scale(add(lo, hi), 0.5);
}

double TriangleMesh::boundingRadius() const {
  if (vertices.empty()) return 0.0;
  Vec3 lo = vertices[0], hi = vertices[0];
  for (const Vec3& v : vertices)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], v[k]);
      hi[k] = std::max(hi[k], v[k]);
    }
  return 0.5 * norm(sub(hi, lo));
}

void TriangleMesh::append(const TriangleMesh& other) {
  const auto base = static_cast<std::uint32_t>(vertices.size());
  vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
  std::vector<std::uint32_t> patchMap(other.patchNames.size());
  for (std::size_t p = 0; p < other.patchNames.size(); ++p)
    patchMap[p] = patchIndex(other.patchNames[p]);
  for (std::size_t t = 0; t < other.triangles.size(); ++t) {
    const auto& tri = other.triangles[t];
    addTriangle(tri[0] + base, tri[1] + base, tri[2] + base, patchMap[other.patchOf[t]]);
  }
}

void TriangleMesh::flip() {
  for (auto& tri : triangles) std::swap(tri[1], tri[2]);
}

void validateMesh(const TriangleMesh& mesh, const std::string& source) {
  if (mesh.triangles.empty()) throw MeshError(source + ": the mesh has no triangles");
  if (mesh.patchOf.size() != mesh.triangles.size())
    throw MeshError(source + ": " + std::to_string(mesh.triangles.size()) + " triangles but " +
                    std::to_string(mesh.patchOf.size()) + " patch indices");
  if (mesh.vertices.size() > std::numeric_limits<std::uint32_t>::max())
    throw MeshError(source + ": more than 2^32 vertices");
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    if (!finite(mesh.vertices[v]))
      throw MeshError(source + ": vertex " + std::to_string(v) + " is not finite");
  std::unordered_map<std::string, int> seen;
  for (const std::string& name : mesh.patchNames) {
    if (name.empty()) throw MeshError(source + ": a patch has an empty name");
    if (++seen[name] > 1) throw MeshError(source + ": patch name '" + name + "' is used twice");
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (std::uint32_t idx : mesh.triangles[t])
      if (idx >= mesh.vertices.size())
        throw MeshError(source + ": triangle " + std::to_string(t) + " refers to vertex " +
                        std::to_string(idx) + " of " + std::to_string(mesh.vertices.size()));
    if (mesh.patchOf[t] >= mesh.patchNames.size())
      throw MeshError(source + ": triangle " + std::to_string(t) + " is in patch " +
                      std::to_string(mesh.patchOf[t]) + " of " +
                      std::to_string(mesh.patchNames.size()));
  }
  // A patch of degenerate triangles only (collinear vertices) receives nothing and has no
  // direction: refused here, where the file is known, rather than by the solver later.
  std::vector<double> area(mesh.patchNames.size(), 0.0);
  std::vector<char> used(mesh.patchNames.size(), 0);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    area[mesh.patchOf[t]] += mesh.triangleArea(t);
    used[mesh.patchOf[t]] = 1;
  }
  for (std::size_t patch = 0; patch < area.size(); ++patch)
    if (used[patch] && !(area[patch] > 0.0))
      throw MeshError(source + ": patch '" + mesh.patchNames[patch] +
                      "' has no area (every triangle of it is degenerate)");
}

}  // namespace ejecta::radiation
