#pragma once
// Perceptual colour maps, each a 256-entry table interpolated linearly:
//   viridis, inferno   van der Walt & Smith, matplotlib's defaults (CC0)
//   coolwarm           Moreland (2009) cool-to-warm diverging map, built by his Msh method
// docs/render.md shows them and says when to use which.
#include <array>
#include <string>
#include <string_view>

#include "render/image.hpp"

namespace ejecta::render {

enum class ColorMapName { Viridis, Inferno, CoolWarm };

// "viridis", "inferno", "coolwarm"; throws std::invalid_argument naming the choices otherwise.
ColorMapName colorMapFromName(std::string_view name);
std::string colorMapName(ColorMapName name);

class ColorMap {
 public:
  static constexpr int kEntries = 256;

  explicit ColorMap(ColorMapName name = ColorMapName::Viridis);

  ColorMapName name() const { return name_; }
  // The colour at t in [0, 1] (clamped): linear between neighbouring table entries, entry k
  // sitting at t = k / 255.
  Rgb at(double t) const;
  const std::array<Rgb, kEntries>& table() const { return table_; }

 private:
  ColorMapName name_;
  std::array<Rgb, kEntries> table_{};
};

}  // namespace ejecta::render
