#pragma once
// JSON text pieces for the outputs still written by hand (chart specs, the source fields
// apps/ and coupling/ add to thermal.json): one string escaper and one number format, so no
// writer can emit an unescaped control character or a bare `nan`/`inf`, which JSON readers
// reject. Whole documents built with nlohmann_json (summary.json, thermal.json, whipple.json,
// the view-factor report) need neither: its dump does both.
#include <string>
#include <string_view>

namespace ejecta {

// A JSON string literal of `text`, quotes included, escaped as nlohmann_json escapes: `"` and
// `\` with a backslash, \b \f \n \r \t by name, other control characters as \u00XX; UTF-8 passes
// through, and a byte that is not valid UTF-8 becomes U+FFFD (JSON text must be UTF-8).
std::string jsonString(std::string_view text);

// `x` as printf's "%.<significantDigits>g" ("1.5", "2.5e+09"; digits clamped to [1, 17]), or
// `null` when x is NaN or infinite: a missing value, not a number JSON cannot represent.
std::string jsonNumber(double x, int significantDigits);

}  // namespace ejecta
