#pragma once
// Tick marks of a colour bar as a report would draw them: linear scales at round steps of 1, 2
// or 5 x 10^k, logarithmic ones at decades (with 2 and 5 between when the range is under two
// decades); large or small numbers share one power of ten written once with the label
// ("pressure [Pa], x1e9") so each tick reads as a short number.
#include <string>
#include <vector>

#include "render/color_scale.hpp"

namespace ejecta::render {

struct Tick {
  double value = 0.0;     // on the data's scale
  double position = 0.0;  // along the bar, in [0, 1]
  std::string text;       // the label, after the common factor
};

struct TickSet {
  std::vector<Tick> ticks;  // inside the scale's range, in increasing order
  std::string factor;       // "x1e9" (with a multiplication sign) when the labels share one; else empty
};

// About `target` ticks (linear: the 1-2-5 step that gives the count nearest it, at least 2).
TickSet colorBarTicks(const ColorScale& scale, int target = 5);

// The step 1, 2 or 5 x 10^k nearest (max - min) / target on a log scale.
double niceStep(double span, int target);

// A tick's text at a round step: plain decimals with as many places as the step needs while the
// number reads well that way (0.01 .. 9999), an exponent beyond. Colour bars and distance axes.
std::string roundLabel(double value, double step);

}  // namespace ejecta::render
