#include "render/diverging_map.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ejecta::render {

namespace {

constexpr double kPi = std::numbers::pi;
// D65 reference white in XYZ, the values of Moreland's reference implementation.
constexpr std::array<double, 3> kWhite{0.9505, 1.0, 1.089};
// Below this saturation angle a colour counts as unsaturated (its hue is meaningless); and the
// lightness of the white in the middle is at least 88 (both from Moreland's paper).
constexpr double kUnsaturated = 0.05;
constexpr double kMiddleMagnitude = 88.0;

double toLinear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }
double toEncoded(double c) {
  return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}
// CIELAB's cube-root curve with its linear segment near black (CIE 15:2004).
double labF(double t) { return t > 0.008856 ? std::cbrt(t) : 7.787 * t + 16.0 / 116.0; }
double labFInverse(double t) { return t > 0.206893 ? t * t * t : (t - 16.0 / 116.0) / 7.787; }

// A saturated colour's hue, moved so that interpolating towards an unsaturated colour of
// magnitude `m` does not bend the hue perceptually (Moreland, section 5).
double adjustHue(const Msh& saturated, double m) {
  if (saturated.m >= m) return saturated.h;
  const double spin = saturated.s * std::sqrt(m * m - saturated.m * saturated.m) /
                      (saturated.m * std::sin(saturated.s));
  return saturated.h > -kPi / 3.0 ? saturated.h + spin : saturated.h - spin;
}

}  // namespace

Msh toMsh(const std::array<double, 3>& srgb) {
  const double r = toLinear(srgb[0]), g = toLinear(srgb[1]), b = toLinear(srgb[2]);
  // Linear sRGB to XYZ (IEC 61966-2-1 primaries, D65).
  const double x = 0.4124 * r + 0.3576 * g + 0.1805 * b;
  const double y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
  const double z = 0.0193 * r + 0.1192 * g + 0.9505 * b;
  const double fx = labF(x / kWhite[0]), fy = labF(y / kWhite[1]), fz = labF(z / kWhite[2]);
  const double lightness = 116.0 * fy - 16.0, a = 500.0 * (fx - fy), bb = 200.0 * (fy - fz);
  Msh out;
  out.m = std::sqrt(lightness * lightness + a * a + bb * bb);
  out.s = out.m > 0.0 ? std::acos(std::clamp(lightness / out.m, -1.0, 1.0)) : 0.0;
  out.h = std::atan2(bb, a);
  return out;
}

std::array<double, 3> toSrgb(const Msh& msh) {
  const double lightness = msh.m * std::cos(msh.s);
  const double a = msh.m * std::sin(msh.s) * std::cos(msh.h);
  const double b = msh.m * std::sin(msh.s) * std::sin(msh.h);
  const double fy = (lightness + 16.0) / 116.0, fx = fy + a / 500.0, fz = fy - b / 200.0;
  const double x = labFInverse(fx) * kWhite[0], y = labFInverse(fy) * kWhite[1],
               z = labFInverse(fz) * kWhite[2];
  // XYZ to linear sRGB: the inverse of the matrix above, to the 4 digits the standard gives.
  const double r = 3.2406 * x - 1.5372 * y - 0.4986 * z;
  const double g = -0.9689 * x + 1.8758 * y + 0.0415 * z;
  const double bl = 0.0557 * x - 0.2040 * y + 1.0570 * z;
  return {toEncoded(r), toEncoded(g), toEncoded(bl)};
}

std::array<double, 3> divergingColor(const Msh& low, const Msh& high, double t) {
  Msh a = low, b = high;
  t = std::clamp(t, 0.0, 1.0);
  // Two saturated, distinct hues: pass through white, each half interpolated on its own.
  if (a.s > kUnsaturated && b.s > kUnsaturated && std::abs(a.h - b.h) > kPi / 3.0) {
    const double middle = std::max({a.m, b.m, kMiddleMagnitude});
    if (t < 0.5) {
      b = {middle, 0.0, 0.0};
      t = 2.0 * t;
    } else {
      a = {middle, 0.0, 0.0};
      t = 2.0 * t - 1.0;
    }
  }
  if (a.s < kUnsaturated && b.s > kUnsaturated)
    a.h = adjustHue(b, a.m);
  else if (b.s < kUnsaturated && a.s > kUnsaturated)
    b.h = adjustHue(a, b.m);
  const Msh mixed{(1.0 - t) * a.m + t * b.m, (1.0 - t) * a.s + t * b.s, (1.0 - t) * a.h + t * b.h};
  return toSrgb(mixed);
}

}  // namespace ejecta::render
