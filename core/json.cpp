#include "core/json.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

namespace ejecta {

std::string jsonString(std::string_view text) {
  // nlohmann_json's serializer is the escaper summary.json already goes through, so every
  // JSON file ejecta writes escapes strings the same way.
  return nlohmann::json(std::string(text))
      .dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string jsonNumber(double x, int significantDigits) {
  if (!std::isfinite(x)) return "null";
  // 17 digits tell every double apart; more only pad, and could overflow the buffer.
  const int digits = std::clamp(significantDigits, 1, 17);
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, x);
  return buffer;
}

}  // namespace ejecta
