#pragma once
// JSON text pieces for the commands that write their JSON by hand (thermal.json, whipple.json's
// chart spec): a string literal and a number.
#include <string>

#include "radiation/format_number.hpp"

namespace ejecta::coupling {

// A JSON string literal of `s` (quotes and backslashes escaped, control characters dropped).
inline std::string jsonString(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) >= 0x20) out += c;
  }
  return out + "\"";
}

// A JSON number with 10 significant digits.
inline std::string jsonNumber(double x) { return radiation::formatNumber("%.10g", x); }

}  // namespace ejecta::coupling
