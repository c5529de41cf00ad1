#pragma once
// JSON text pieces for the commands that write their JSON by hand (thermal.json, whipple.json's
// chart spec): core's string escaper and its number format at 10 significant digits.
#include <string>

#include "core/json.hpp"

namespace ejecta::coupling {

using ejecta::jsonString;

// A JSON number with 10 significant digits; null where not finite.
inline std::string jsonNumber(double x) { return ejecta::jsonNumber(x, 10); }

}  // namespace ejecta::coupling
