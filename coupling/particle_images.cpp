#include "coupling/particle_images.hpp"

#include <stdexcept>

#include "render/png_io.hpp"
#include "sim/state/particle_fields.hpp"

namespace ejecta::coupling {

render::ParticleLayer particleLayer(const ParticleSet& p, Geometry geometry,
                                    const ParticleImageOptions& options,
                                    std::vector<double>& values) {
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
  std::vector<double> values;
  render::Picture scene;
  scene.particles.push_back(particleLayer(p, geometry, options, values));
  scene.annotations.title = options.title.empty() ? sceneName + ": " + options.field : options.title;
  scene.annotations.time = time;
  render::writePng(out, renderer.render(scene, particleView(geometry, options)).image);
}

}  // namespace ejecta::coupling
