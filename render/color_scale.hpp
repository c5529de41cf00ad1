#pragma once
// From a scalar field to colours: a colour map, a range and a linear or logarithmic scale.
// The range is given, or taken from the data (optionally between two percentiles, so that a
// few extreme particles do not wash out the picture).
#include <optional>
#include <span>

#include "render/color_map.hpp"
#include "render/image.hpp"

namespace ejecta::render {

enum class ScaleKind { Linear, Log };

struct ColorScaleSpec {
  ColorMapName map = ColorMapName::Viridis;
  ScaleKind kind = ScaleKind::Linear;
  // Given ends of the range; an end not given is taken from the data.
  std::optional<double> min{}, max{};
  // Percentiles of the data for the ends not given, in [0, 100]: 0 and 100 are the data's
  // extremes, 1 and 99 a robust range. Non-finite values (and, for log, values <= 0) are left
  // out.
  double lowPercentile = 0.0;
  double highPercentile = 100.0;
};

class ColorScale {
 public:
  // Throws std::invalid_argument unless min < max (both finite), and min > 0 for Log.
  ColorScale(ColorMap map, double min, double max, ScaleKind kind = ScaleKind::Linear);

  double min() const { return min_; }
  double max() const { return max_; }
  ScaleKind kind() const { return kind_; }
  const ColorMap& map() const { return map_; }

  // Position of v on the scale in [0, 1] (clamped; log: log10 v between log10 min and log10
  // max, so each decade has the same length; v <= 0 gives 0). NaN for NaN.
  double normalise(double v) const;
  // The map's colour at normalise(v); kNoData for NaN.
  Rgb color(double v) const;

  // Grey: a particle whose value is NaN.
  static constexpr Rgb kNoData{0.5f, 0.5f, 0.5f};

 private:
  ColorMap map_;
  double min_, max_;
  ScaleKind kind_;
  double low_, span_;  // the scale's own coordinates: v or log10 v
};

// The scale for `values` under `spec`. An empty data set (or one without a usable value) and
// no given ends: [0, 1] (log: [1, 10]). A degenerate range (all values equal) is widened to
// +-50% (log: half a decade each way) so that it still has a colour ramp.
// Throws std::invalid_argument for percentiles outside [0, 100] or low > high, or given ends
// that make an invalid scale.
ColorScale resolveScale(const ColorScaleSpec& spec, std::span<const double> values);

}  // namespace ejecta::render
