#pragma once
// The words and numbers of an image's annotations: tick labels, the time label, the length of
// a scale bar and its label.
#include <string>

namespace ejecta::render {

// `value` to `significant` digits, in plain or exponent form, whichever %g picks, with the
// exponent shortened ("1.5e+04" -> "1.5e4", "2e-05" -> "2e-5").
std::string formatNumber(double value, int significant = 3);

// "t = 12.5 ms": seconds shown in s, ms, µs or ns so that the number is below 1000.
std::string formatTime(double seconds);

// The longest length 1, 2 or 5 x 10^k [m] not above `target` (> 0).
double roundLength(double target);

// A length in the unit that keeps the number between 1 and 1000: "10 m", "2 km", "500 mm".
std::string formatLength(double metres);

// "name [units]", or just the name when there are no units.
std::string fieldLabel(const std::string& name, const std::string& units);

}  // namespace ejecta::render
