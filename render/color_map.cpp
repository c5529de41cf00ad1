#include "render/color_map.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "render/color_map_tables.hpp"
#include "render/diverging_map.hpp"

namespace ejecta::render {

namespace {

std::array<Rgb, ColorMap::kEntries> fromBytes(
    const std::array<std::array<std::uint8_t, 3>, 256>& bytes) {
  std::array<Rgb, ColorMap::kEntries> out{};
  for (int k = 0; k < ColorMap::kEntries; ++k)
    out[k] = {bytes[k][0] / 255.0f, bytes[k][1] / 255.0f, bytes[k][2] / 255.0f};
  return out;
}

std::array<Rgb, ColorMap::kEntries> coolWarm() {
  std::array<Rgb, ColorMap::kEntries> out{};
  for (int k = 0; k < ColorMap::kEntries; ++k) {
    const auto c = divergingColor(kCoolWarmCool, kCoolWarmWarm, k / 255.0);
    out[k] = {static_cast<float>(std::clamp(c[0], 0.0, 1.0)),
              static_cast<float>(std::clamp(c[1], 0.0, 1.0)),
              static_cast<float>(std::clamp(c[2], 0.0, 1.0))};
  }
  return out;
}

}  // namespace

ColorMapName colorMapFromName(std::string_view name) {
  if (name == "viridis") return ColorMapName::Viridis;
  if (name == "inferno") return ColorMapName::Inferno;
  if (name == "coolwarm") return ColorMapName::CoolWarm;
  throw std::invalid_argument("unknown colour map '" + std::string(name) +
                              "' (choose viridis, inferno or coolwarm)");
}

std::string colorMapName(ColorMapName name) {
  switch (name) {
    case ColorMapName::Viridis:
      return "viridis";
    case ColorMapName::Inferno:
      return "inferno";
    case ColorMapName::CoolWarm:
      return "coolwarm";
  }
  return "?";
}

ColorMap::ColorMap(ColorMapName name) : name_(name) {
  switch (name) {
    case ColorMapName::Viridis:
      table_ = fromBytes(tables::kViridis);
      break;
    case ColorMapName::Inferno:
      table_ = fromBytes(tables::kInferno);
      break;
    case ColorMapName::CoolWarm:
      table_ = coolWarm();
      break;
  }
}

Rgb ColorMap::at(double t) const {
  if (!(t > 0.0)) return table_.front();  // also NaN: callers colour missing data themselves
  if (t >= 1.0) return table_.back();
  const double position = t * (kEntries - 1);
  const int k = std::min(static_cast<int>(position), kEntries - 2);
  const float f = static_cast<float>(position - k);
  const Rgb& a = table_[k];
  const Rgb& b = table_[k + 1];
  return {a.r + f * (b.r - a.r), a.g + f * (b.g - a.g), a.b + f * (b.b - a.b)};
}

}  // namespace ejecta::render
