#include "render/color_scale.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace ejecta::render {

namespace {

// The p-th percentile (0..100) of `v` by linear interpolation between order statistics; v is
// reordered.
double percentile(std::vector<double>& v, double p) {
  const double position = p / 100.0 * static_cast<double>(v.size() - 1);
  const auto k = static_cast<std::size_t>(std::floor(position));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  const double below = v[k];
  if (k + 1 >= v.size()) return below;
  // The next order statistic is the smallest of the elements after k.
  const double above = *std::min_element(v.begin() + static_cast<std::ptrdiff_t>(k) + 1, v.end());
  return below + (position - static_cast<double>(k)) * (above - below);
}

}  // namespace

ColorScale::ColorScale(ColorMap map, double min, double max, ScaleKind kind)
    : map_(map), min_(min), max_(max), kind_(kind) {
  if (!std::isfinite(min) || !std::isfinite(max) || !(min < max))
    throw std::invalid_argument("colour scale: need finite min < max, got [" + std::to_string(min) +
                                ", " + std::to_string(max) + "]");
  if (kind == ScaleKind::Log && !(min > 0.0))
    throw std::invalid_argument("colour scale: a log scale needs min > 0, got " +
                                std::to_string(min));
  low_ = kind == ScaleKind::Log ? std::log10(min) : min;
  span_ = (kind == ScaleKind::Log ? std::log10(max) : max) - low_;
}

double ColorScale::normalise(double v) const {
  if (std::isnan(v)) return v;
  double s = v;
  if (kind_ == ScaleKind::Log) {
    if (!(v > 0.0)) return 0.0;
    s = std::log10(v);
  }
  return std::clamp((s - low_) / span_, 0.0, 1.0);
}

Rgb ColorScale::color(double v) const {
  const double t = normalise(v);
  return std::isnan(t) ? kNoData : map_.at(t);
}

ColorScale resolveScale(const ColorScaleSpec& spec, std::span<const double> values) {
  if (!(spec.lowPercentile >= 0.0 && spec.highPercentile <= 100.0 &&
        spec.lowPercentile <= spec.highPercentile))
    throw std::invalid_argument("colour scale: percentiles must satisfy 0 <= low <= high <= 100");
  const bool log = spec.kind == ScaleKind::Log;
  double lo = spec.min.value_or(0.0), hi = spec.max.value_or(0.0);
  if (!spec.min || !spec.max) {
    const auto usable = [log](double v) { return std::isfinite(v) && (!log || v > 0.0); };
    // The extremes in one pass; percentiles other than 0 and 100 need a copy to select from.
    double smallest = HUGE_VAL, largest = -HUGE_VAL;
    std::size_t count = 0;
    for (double v : values)
      if (usable(v)) {
        smallest = std::min(smallest, v);
        largest = std::max(largest, v);
        ++count;
      }
    std::vector<double> selectable;
    if (count > 0 && (spec.lowPercentile > 0.0 || spec.highPercentile < 100.0)) {
      selectable.reserve(count);
      for (double v : values)
        if (usable(v)) selectable.push_back(v);
    }
    const auto at = [&](double p) {
      if (p <= 0.0) return smallest;
      if (p >= 100.0) return largest;
      return percentile(selectable, p);
    };
    if (count == 0) {
      if (!spec.min) lo = spec.max ? (log ? *spec.max / 10.0 : *spec.max - 1.0) : (log ? 1.0 : 0.0);
      if (!spec.max)
        hi = spec.min ? (log ? *spec.min * 10.0 : *spec.min + 1.0) : (log ? 10.0 : 1.0);
    } else {
      if (!spec.min) lo = at(spec.lowPercentile);
      if (!spec.max) hi = at(spec.highPercentile);
    }
    if (!(lo < hi)) {
      // All values equal, or the data lies beyond the given end: widen about the given end (or
      // the common value) the end(s) taken from the data.
      const double centre = spec.min ? lo : hi;
      const double half = std::max(0.5 * std::abs(centre), 0.5);
      if (!spec.min) lo = log ? centre / std::sqrt(10.0) : centre - half;
      if (!spec.max) hi = log ? centre * std::sqrt(10.0) : centre + half;
    }
  }
  return ColorScale(ColorMap(spec.map), lo, hi, spec.kind);
}

}  // namespace ejecta::render
