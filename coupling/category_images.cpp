#include "coupling/category_images.hpp"

#include <array>

#include "render/png_io.hpp"

namespace ejecta::coupling {

namespace {

// Okabe & Ito (2008), "Color Universal Design": distinguishable under the common colour-vision
// deficiencies. Black last: it is the ink of the strip.
constexpr std::array<render::Rgb, 8> kPalette{{{0.902f, 0.624f, 0.000f},
                                               {0.337f, 0.706f, 0.914f},
                                               {0.000f, 0.620f, 0.451f},
                                               {0.941f, 0.894f, 0.259f},
                                               {0.000f, 0.447f, 0.698f},
                                               {0.835f, 0.369f, 0.000f},
                                               {0.800f, 0.475f, 0.655f},
                                               {0.300f, 0.300f, 0.300f}}};

enum Status { kNoStrength, kIntact, kPlastic, kDamaged, kFailed, kStatusCount };

}  // namespace

Categories materialCategories(const ParticleSet& p, const MaterialLegend& materials) {
  Categories c;
  const std::size_t count = std::max<std::size_t>(materials.names.size(), 1);
  for (std::size_t m = 0; m < count; ++m)
    c.legend.push_back({m < materials.names.size() ? materials.names[m] : "material " + std::to_string(m),
                        kPalette[m % kPalette.size()]});
  c.of.resize(p.numReal);
  for (std::size_t i = 0; i < p.numReal; ++i) {
    const int m = p.material[i];
    if (m >= static_cast<int>(c.legend.size()))  // an id the table lacks: named by its number
      for (int k = static_cast<int>(c.legend.size()); k <= m; ++k)
        c.legend.push_back({"material " + std::to_string(k), kPalette[static_cast<std::size_t>(k) % kPalette.size()]});
    c.of[i] = m;
  }
  return c;
}

Categories failureCategories(const ParticleSet& p, const MaterialLegend& materials) {
  static const std::array<render::LegendEntry, kStatusCount> kStates{{
      {"no strength", {0.80f, 0.80f, 0.80f}},
      {"intact", {0.337f, 0.706f, 0.914f}},
      {"plastic", {0.902f, 0.624f, 0.000f}},
      {"damaged", {0.835f, 0.369f, 0.000f}},
      {"failed", {0.45f, 0.05f, 0.05f}},
  }};
  std::array<int, kStatusCount> index{};
  index.fill(-1);
  std::vector<int> status(p.numReal);
  const bool plasticity = p.plasticStrain.size() >= p.numReal;
  for (std::size_t i = 0; i < p.numReal; ++i) {
    const auto m = static_cast<std::size_t>(p.material[i]);
    const bool strong = m < materials.strength.size() && materials.strength[m];
    const double d = p.damage(i);
    int s = kIntact;
    if (d >= 0.999) s = kFailed;
    else if (d > 0.01) s = kDamaged;
    else if (!strong) s = kNoStrength;
    else if (plasticity && p.plasticStrain[i] > 1e-4) s = kPlastic;
    status[i] = s;
  }
  Categories c;
  // The legend in the states' own order, with only those present.
  for (int s = 0; s < kStatusCount; ++s)
    for (const int seen : status)
      if (seen == s) {
        index[static_cast<std::size_t>(s)] = static_cast<int>(c.legend.size());
        c.legend.push_back(kStates[static_cast<std::size_t>(s)]);
        break;
      }
  c.of.resize(p.numReal);
  for (std::size_t i = 0; i < p.numReal; ++i) c.of[i] = index[static_cast<std::size_t>(status[i])];
  return c;
}

void writeCategoryImage(render::Renderer& renderer, const ParticleSet& p, Geometry geometry,
                        double time, const std::string& title, const Categories& categories,
                        const ParticleImageOptions& view, const std::filesystem::path& out) {
  const std::vector<double> radii = particleDiscRadii(p, geometry);
  const std::size_t layers = categories.legend.size();
  std::vector<std::array<std::vector<double>, 4>> columns(layers);  // x, y, z, radius
  std::vector<std::vector<double>> h(layers);
  for (std::size_t i = 0; i < p.numReal; ++i) {
    const auto k = static_cast<std::size_t>(categories.of[i]);
    columns[k][0].push_back(p.x[0][i]);
    columns[k][1].push_back(p.x[1][i]);
    columns[k][2].push_back(p.x[2][i]);
    columns[k][3].push_back(radii[i]);
    h[k].push_back(p.h[i]);
  }
  render::Picture scene;
  for (std::size_t k = 0; k < layers; ++k) {
    if (h[k].empty()) continue;
    render::ParticleLayer layer;
    layer.x = columns[k][0];
    layer.y = columns[k][1];
    if (spatialDimension(geometry) == 3) layer.z = columns[k][2];
    layer.radius = columns[k][3];
    layer.h = h[k];
    layer.color = categories.legend[k].color;
    layer.colorBar = false;
    scene.particles.push_back(layer);
  }
  scene.annotations.title = title;
  scene.annotations.time = time;
  scene.annotations.legend = categories.legend;
  setDistanceAxes(scene.annotations, geometry, view.axes);
  render::writePng(out, renderer.render(scene, particleView(geometry, view)).image);
}

}  // namespace ejecta::coupling
