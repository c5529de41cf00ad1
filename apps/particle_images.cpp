#include "apps/particle_images.hpp"

#include <stdexcept>

#include "render/png_io.hpp"
#include "sim/particle_fields.hpp"

namespace ejecta::app {

void writeParticleImage(render::Renderer& renderer, const ParticleSet& p, Geometry geometry,
                        double time, const std::string& sceneName,
                        const ParticleImageOptions& options, const std::filesystem::path& out) {
  const ParticleFieldInfo* info = findParticleScalarField(options.field);
  if (!info)
    throw std::invalid_argument("unknown field '" + options.field + "' (known: " +
                                particleScalarFieldList() + ")");
  const std::size_t n = p.numReal;
  const std::vector<double> values = particleScalarField(p, options.field);
  const std::span<const double> x(p.x[0].data(), n), y(p.x[1].data(), n), z(p.x[2].data(), n);
  render::ParticleLayer layer;
  layer.x = x;
  layer.y = y;
  if (spatialDimension(geometry) == 3) layer.z = z;
  layer.h = std::span<const double>(p.h.data(), n);
  layer.values = values;
  layer.scale.kind = options.log ? render::ScaleKind::Log : render::ScaleKind::Linear;
  // A robust range: a few extreme particles (a jet, the hottest ejecta) do not wash out the rest.
  layer.scale.lowPercentile = 0.5;
  layer.scale.highPercentile = 99.5;
  layer.field = std::string(info->name);
  layer.units = std::string(info->units);
  render::Scene scene;
  scene.particles.push_back(layer);
  scene.annotations.title = options.title.empty() ? sceneName + ": " + options.field : options.title;
  scene.annotations.time = time;
  render::View view;
  if (geometry == Geometry::Axisymmetric) {
    view.kind = render::ViewKind::Axisymmetric;
  } else if (spatialDimension(geometry) == 3) {
    view.kind = render::ViewKind::Perspective;
    if (options.cut == "x" || options.cut == "y" || options.cut == "z") {
      render::ClipPlane cut;
      cut.normal = {options.cut == "x" ? 1.0 : 0.0, options.cut == "y" ? 1.0 : 0.0,
                    options.cut == "z" ? 1.0 : 0.0};
      view.clipPlanes.push_back(cut);
    } else if (options.cut != "none") {
      throw std::invalid_argument("cut '" + options.cut + "': expected none, x, y or z");
    }
  } else {
    view.kind = render::ViewKind::Plane;
  }
  render::writePng(out, renderer.render(scene, view).image);
}

}  // namespace ejecta::app
