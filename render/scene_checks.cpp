#include <cmath>
#include <stdexcept>
#include <string>

#include "render/scene.hpp"

namespace ejecta::render {

namespace {

[[noreturn]] void fail(const std::string& layer, std::size_t index, const std::string& why) {
  throw std::invalid_argument(layer + " layer " + std::to_string(index) + ": " + why);
}

std::string count(std::size_t n, const char* what) { return std::to_string(n) + " " + what; }

}  // namespace

void validatePicture(const Picture& scene, const View& view) {
  for (std::size_t l = 0; l < scene.particles.size(); ++l) {
    const ParticleLayer& p = scene.particles[l];
    const std::size_t n = p.x.size();
    if (p.y.size() != n) fail("particle", l, count(n, "x") + " but " + count(p.y.size(), "y"));
    if (!p.z.empty() && p.z.size() != n)
      fail("particle", l, count(n, "x") + " but " + count(p.z.size(), "z (give n or none)"));
    if (p.h.size() != n) fail("particle", l, count(n, "x") + " but " + count(p.h.size(), "h"));
    if (!p.values.empty() && p.values.size() != n)
      fail("particle", l, count(n, "x") + " but " + count(p.values.size(), "values"));
    if (!(p.radiusInH > 0.0)) fail("particle", l, "radiusInH must be > 0");
    if (!p.radius.empty() && p.radius.size() != n)
      fail("particle", l, count(n, "x") + " but " + count(p.radius.size(), "radii (give n or none)"));
  }
  for (std::size_t l = 0; l < scene.meshes.size(); ++l) {
    const MeshLayer& m = scene.meshes[l];
    const std::size_t nv = m.vertices.size(), nt = m.triangles.size();
    for (std::size_t t = 0; t < nt; ++t)
      for (std::uint32_t v : m.triangles[t])
        if (v >= nv)
          fail("mesh", l,
               "triangle " + std::to_string(t) + " uses vertex " + std::to_string(v) + " of " +
                   count(nv, "vertices"));
    if (!m.vertexValues.empty() && m.vertexValues.size() != nv)
      fail("mesh", l,
           count(nv, "vertices") + " but " + count(m.vertexValues.size(), "vertexValues"));
    if (!m.triangleValues.empty() && m.triangleValues.size() != nt)
      fail("mesh", l,
           count(nt, "triangles") + " but " + count(m.triangleValues.size(), "triangleValues"));
    if (!m.vertexValues.empty() && !m.triangleValues.empty())
      fail("mesh", l, "give vertexValues or triangleValues, not both");
  }
  for (std::size_t l = 0; l < scene.slices.size(); ++l) {
    const SliceLayer& s = scene.slices[l];
    if (s.nx <= 0 || s.ny <= 0)
      fail("slice", l,
           "nx and ny must be > 0, got " + std::to_string(s.nx) + " x " + std::to_string(s.ny));
    const auto cells = static_cast<std::size_t>(s.nx) * static_cast<std::size_t>(s.ny);
    if (s.values.size() != cells)
      fail("slice", l,
           "nx * ny = " + std::to_string(cells) + " but " + count(s.values.size(), "values"));
    if (!(s.spacing[0] > 0.0) || !(s.spacing[1] > 0.0))
      fail("slice", l, "spacing must be > 0 in both directions");
  }
  if (view.clipPlanes.size() > 4)
    throw std::invalid_argument("view: at most 4 clip planes, got " +
                                std::to_string(view.clipPlanes.size()));
  for (std::size_t c = 0; c < view.clipPlanes.size(); ++c) {
    const Vec3& n = view.clipPlanes[c].normal;
    if (!(std::hypot(n[0], n[1], n[2]) > 0.0))
      throw std::invalid_argument("view: clip plane " + std::to_string(c) + " has a zero normal");
  }
}

}  // namespace ejecta::render
