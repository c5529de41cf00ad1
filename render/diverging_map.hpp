#pragma once
// Diverging colour maps by K. Moreland's method ("Diverging Color Maps for Scientific
// Visualization", Advances in Visual Computing, LNCS 5876, 92-103, 2009): the two end colours
// are interpolated in Msh, a polar form of CIELAB (M: magnitude, s: saturation angle, h: hue
// angle), through an unsaturated white in the middle, so that lightness rises linearly to the
// centre and falls again, and the hue of each half stays put.
#include <array>

namespace ejecta::render {

struct Msh {
  double m = 0.0, s = 0.0, h = 0.0;  // [CIELAB units, rad, rad]
};

// The end colours of Moreland's cool-to-warm map, as given in Msh in his paper (section 6):
// blue (80, 1.08, -1.1) and red (80, 1.08, 0.5); in 8-bit sRGB about (59, 76, 192) and
// (180, 4, 38).
inline constexpr Msh kCoolWarmCool{80.0, 1.08, -1.1};
inline constexpr Msh kCoolWarmWarm{80.0, 1.08, 0.5};

// sRGB-encoded colour in [0, 1]^3 (unclamped) <-> Msh. Conversions: sRGB transfer curve and
// primaries (IEC 61966-2-1), CIELAB with the D65 white (0.9505, 1.0, 1.089) Moreland uses.
Msh toMsh(const std::array<double, 3>& srgb);
std::array<double, 3> toSrgb(const Msh& msh);

// The colour at t in [0, 1] of the diverging map from `low` (t = 0) to `high` (t = 1).
std::array<double, 3> divergingColor(const Msh& low, const Msh& high, double t);

}  // namespace ejecta::render
