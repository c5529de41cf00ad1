#include "render/labels.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace ejecta::render {

std::string formatNumber(double value, int significant) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*g", significant, value);
  std::string s = text;
  const auto e = s.find('e');
  if (e == std::string::npos) return s;
  std::string mantissa = s.substr(0, e), exponent = s.substr(e + 1);
  std::string sign;
  if (!exponent.empty() && (exponent[0] == '+' || exponent[0] == '-')) {
    if (exponent[0] == '-') sign = "-";
    exponent.erase(0, 1);
  }
  while (exponent.size() > 1 && exponent[0] == '0') exponent.erase(0, 1);
  return mantissa + "e" + sign + exponent;
}

std::string formatTime(double seconds) {
  const double magnitude = std::abs(seconds);
  const char* unit = "s";
  double shown = seconds;
  if (magnitude == 0.0 || magnitude >= 1.0) {
  } else if (magnitude >= 1e-3) {
    unit = "ms";
    shown = seconds * 1e3;
  } else if (magnitude >= 1e-6) {
    unit = "\xC2\xB5s";  // µs
    shown = seconds * 1e6;
  } else {
    unit = "ns";
    shown = seconds * 1e9;
  }
  return "t = " + formatNumber(shown, 4) + " " + unit;
}

double roundLength(double target) {
  if (!(target > 0.0) || !std::isfinite(target))
    throw std::invalid_argument("roundLength: the target length must be positive and finite");
  const double decade = std::pow(10.0, std::floor(std::log10(target)));
  // Guard against log10 landing just below an exact power of ten.
  const double base = target / decade >= 10.0 * (1.0 - 1e-12) ? decade * 10.0 : decade;
  for (double step : {5.0, 2.0, 1.0})
    if (step * base <= target * (1.0 + 1e-12)) return step * base;
  return base / 2.0;
}

std::string formatLength(double metres) {
  const double magnitude = std::abs(metres);
  if (magnitude >= 1e3) return formatNumber(metres / 1e3, 4) + " km";
  if (magnitude >= 1.0 || magnitude == 0.0) return formatNumber(metres, 4) + " m";
  if (magnitude >= 1e-3) return formatNumber(metres * 1e3, 4) + " mm";
  return formatNumber(metres * 1e6, 4) + " \xC2\xB5m";
}

std::string fieldLabel(const std::string& name, const std::string& units) {
  return units.empty() ? name : name + " [" + units + "]";
}

}  // namespace ejecta::render
