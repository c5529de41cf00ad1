#pragma once
// Categorical pictures of a run's particles, the first ones AUTODYN users look at: where each
// material is, and each particle's failure status (no strength / intact / plastic / damaged /
// failed), with a legend of names in the strip. Drawn by `ejecta run` with a scene's [images]
// frames and by `ejecta render --plot materials|failure`.
#include <filesystem>
#include <string>
#include <vector>

#include "coupling/particle_images.hpp"
#include "render/renderer.hpp"
#include "sim/state/particles.hpp"

namespace ejecta::coupling {

// What the plots need of the material table, by material id.
struct MaterialLegend {
  std::vector<std::string> names;
  std::vector<bool> strength;  // the material has a strength model (else: a fluid or rubble)
};

enum class CategoryPlot { Materials, Failure };

// Each real particle's category and the legend of the categories present.
struct Categories {
  std::vector<int> of;                      // index into `legend`, per particle
  std::vector<render::LegendEntry> legend;
};

// Materials by name, in a colour-blind-safe palette (Okabe & Ito 2008), one colour per id.
Categories materialCategories(const ParticleSet& p, const MaterialLegend& materials);

// Failure status. failed: damage D >= 0.999 (no tension, no shear left); damaged: D > 0.01;
// plastic: equivalent plastic strain > 1e-4 (0.01%); intact: otherwise; no strength: a
// material without a strength model. Only the states that occur are in the legend.
Categories failureCategories(const ParticleSet& p, const MaterialLegend& materials);

// Draws the categories (one layer per category, discs sized to each particle's spacing) in the
// view that suits the geometry, and writes the PNG atomically.
void writeCategoryImage(render::Renderer& renderer, const ParticleSet& p, Geometry geometry,
                        double time, const std::string& title, const Categories& categories,
                        const ParticleImageOptions& view, const std::filesystem::path& out);

}  // namespace ejecta::coupling
