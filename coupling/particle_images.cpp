#include "coupling/particle_images.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "render/png_io.hpp"
#include "sim/state/particle_fields.hpp"

namespace ejecta::coupling {

std::vector<double> particleDiscRadii(const ParticleSet& p, Geometry geometry) {
  const std::size_t n = p.numReal;
  std::vector<double> radii(n);
  const int d = spatialDimension(geometry);
  for (std::size_t i = 0; i < n; ++i) {
    double volume = p.mass[i] / p.rho[i];
    if (geometry == Geometry::Axisymmetric)
      volume /= 2.0 * std::numbers::pi * std::max(std::abs(p.x[0][i]), 0.25 * p.h[i]);
    const double spacing = d == 3 ? std::cbrt(volume) : d == 2 ? std::sqrt(volume) : volume;
    radii[i] = std::isfinite(spacing) && spacing > 0 ? 0.75 * spacing : 0.5 * p.h[i];
  }
  return radii;
}

render::ParticleLayer particleLayer(const ParticleSet& p, Geometry geometry,
                                    const ParticleImageOptions& options, ParticleLayerArrays& arrays) {
  std::vector<double>& values = arrays.values;
  const ParticleFieldInfo* info = findParticleScalarField(options.field);
  if (!info)
    throw std::invalid_argument("unknown field '" + options.field + "' (known: " +
                                particleScalarFieldList() + ")");
  const std::size_t n = p.numReal;
  values = particleScalarField(p, options.field);
  render::ParticleLayer layer;
  layer.x = std::span<const double>(p.x[0].data(), n);
  layer.y = std::span<const double>(p.x[1].data(), n);
  if (spatialDimension(geometry) == 3) layer.z = std::span<const double>(p.x[2].data(), n);
  layer.h = std::span<const double>(p.h.data(), n);
  arrays.radii = particleDiscRadii(p, geometry);
  layer.radius = arrays.radii;
  layer.values = values;
  layer.scale.kind = options.log ? render::ScaleKind::Log : render::ScaleKind::Linear;
  // A robust range: a few extreme particles (a jet, the hottest ejecta) do not wash out the rest.
  layer.scale.lowPercentile = 0.5;
  layer.scale.highPercentile = 99.5;
  layer.field = std::string(info->name);
  layer.units = std::string(info->units);
  return layer;
}

render::Camera renderCamera(const ImageCamera& camera) {
  render::Camera c;
  c.position = camera.position;
  c.target = camera.target;
  c.up = camera.up;
  c.fovYDegrees = camera.fovDegrees;
  return c;
}

render::View particleView(Geometry geometry, const std::string& cut) {
  ParticleImageOptions options;
  options.cut = cut;
  return particleView(geometry, options);
}

render::View particleView(Geometry geometry, const ParticleImageOptions& options) {
  render::View view;
  const std::string& cut = options.cut;
  if (spatialDimension(geometry) != 3 && options.center) {
    view.center = options.center;
    view.width = options.width;
  }
  if (geometry == Geometry::Axisymmetric) {
    view.kind = render::ViewKind::Axisymmetric;
  } else if (spatialDimension(geometry) == 3) {
    view.kind = render::ViewKind::Perspective;
    view.camera = options.camera;
    if (cut == "x" || cut == "y" || cut == "z") {
      render::ClipPlane plane;
      plane.normal = {cut == "x" ? 1.0 : 0.0, cut == "y" ? 1.0 : 0.0, cut == "z" ? 1.0 : 0.0};
      plane.offset = options.cutAt;
      view.clipPlanes.push_back(plane);
    } else if (cut != "none") {
      throw std::invalid_argument("cut '" + cut + "': expected none, x, y or z");
    }
  } else {
    view.kind = render::ViewKind::Plane;
  }
  return view;
}

void writeParticleImage(render::Renderer& renderer, const ParticleSet& p, Geometry geometry,
                        double time, const std::string& sceneName,
                        const ParticleImageOptions& options, const std::filesystem::path& out) {
  ParticleLayerArrays arrays;
  render::Picture scene;
  scene.particles.push_back(particleLayer(p, geometry, options, arrays));
  scene.annotations.title = options.title.empty() ? sceneName + ": " + options.field : options.title;
  scene.annotations.time = time;
  setDistanceAxes(scene.annotations, geometry, options.axes);
  render::writePng(out, renderer.render(scene, particleView(geometry, options)).image);
}

void setDistanceAxes(render::Annotations& annotations, Geometry geometry, bool on) {
  annotations.axes = on && spatialDimension(geometry) != 3;
  if (geometry == Geometry::Axisymmetric) annotations.axisNames = {"r", "z"};
}

}  // namespace ejecta::coupling
