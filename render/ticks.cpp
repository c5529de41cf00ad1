#include "render/ticks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/labels.hpp"

namespace ejecta::render {

double niceStep(double span, int target) {
  const double raw = span / std::max(1, target);
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  double best = decade;
  for (const double m : {1.0, 2.0, 5.0, 10.0})
    if (std::abs(std::log(m * decade / raw)) < std::abs(std::log(best / raw))) best = m * decade;
  return best;
}

std::string roundLabel(double v, double step) {
  if (std::abs(v) < step * 1e-9) return "0";
  const double magnitude = std::abs(v);
  if (magnitude >= 1e-2 && magnitude < 1e4) {
    const int places = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
    char text[32];
    std::snprintf(text, sizeof text, "%.*f", places, v);
    return text;
  }
  const int digits = std::clamp(static_cast<int>(std::floor(std::log10(magnitude))) -
                                    static_cast<int>(std::floor(std::log10(step))) + 1,
                                1, 6);
  return formatNumber(v, digits);
}

namespace {

TickSet linearTicks(const ColorScale& scale, int target) {
  TickSet out;
  const double lo = scale.min(), hi = scale.max();
  const double step = niceStep(hi - lo, target);
  // One power of ten for all labels when they would need an exponent (|v| >= 1e4 or < 1e-2).
  const double largest = std::max(std::abs(lo), std::abs(hi));
  const int exponent = static_cast<int>(std::floor(std::log10(largest) / 3.0)) * 3;
  const bool factor = exponent != 0 && (largest >= 1e4 || largest < 1e-2);
  const double unit = factor ? std::pow(10.0, exponent) : 1.0;
  if (factor) out.factor = "\xC3\x97" "1e" + std::to_string(exponent);  // ×1e9
  // A range a few rounding steps wide (a nearly uniform field) has no round ticks to speak of:
  // the caller marks its ends. So does one whose multiples of the step are past 2^53.
  if (hi - lo < 1e-9 * largest) return out;
  const double first = std::ceil(lo / step - 1e-9), last = std::floor(hi / step + 1e-9);
  if (!(last - first < 50)) return out;
  for (long k = 0; k <= static_cast<long>(last - first); ++k) {
    const double v = (first + static_cast<double>(k)) * step;
    out.ticks.push_back({v, scale.normalise(v), roundLabel(v / unit, step / unit)});
  }
  return out;
}

TickSet logTicks(const ColorScale& scale) {
  TickSet out;
  const double lo = std::log10(scale.min()), hi = std::log10(scale.max());
  const bool fine = hi - lo < 2.0;
  // At most about six decade labels, however wide the range.
  const int step = std::max(1, static_cast<int>(std::ceil((hi - lo) / 6.0 - 1e-9)));
  for (int d = static_cast<int>(std::floor(lo)); d <= static_cast<int>(std::ceil(hi)); ++d) {
    for (const double m : fine ? std::vector<double>{1, 2, 5} : std::vector<double>{1}) {
      if (m == 1 && d % step != 0 && !fine) continue;
      const double v = m * std::pow(10.0, d);
      const double lv = std::log10(v);
      if (lv < lo - 1e-9 || lv > hi + 1e-9) continue;
      out.ticks.push_back({v, scale.normalise(v), roundLabel(v, v)});
    }
  }
  return out;
}

}  // namespace

TickSet colorBarTicks(const ColorScale& scale, int target) {
  TickSet set = scale.kind() == ScaleKind::Log ? logTicks(scale) : linearTicks(scale, target);
  // A range narrower than one step still gets its two ends marked, with the digits that tell
  // them apart.
  if (set.ticks.size() < 2) {
    set = TickSet{};
    const double lo = scale.min(), hi = scale.max();
    int digits = 3;
    while (digits < 17 && formatNumber(lo, digits) == formatNumber(hi, digits)) ++digits;
    for (const double v : {lo, hi}) set.ticks.push_back({v, scale.normalise(v), formatNumber(v, digits)});
  }
  return set;
}

}  // namespace ejecta::render
