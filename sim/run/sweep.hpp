#pragma once
// Parameter sweeps (`ejecta sweep`): variants of one scene that differ in a few keys. Each
// `--vary key=v1,v2,...` is an axis; several axes vary together (zipped: variant k takes the k-th
// value of every axis), so a device can be moved with its charge, point and deposit in step.
// Values are scene values as --set takes them ("3 m", [0.0, "-2 m"]); commas inside brackets or
// quotes do not split.
#include <optional>
#include <string>
#include <vector>

namespace ejecta {

struct SweepAxis {
  std::string key;                  // dotted scene key, e.g. "detonations[0].point"
  std::vector<std::string> values;  // TOML values
};

// Splits on the commas outside brackets and quotes, each part trimmed; nothing when a bracket or
// quote is left open. "a, [1, 2], \"x,y\"" -> {"a", "[1, 2]", "\"x,y\""}.
std::optional<std::vector<std::string>> splitOutsideBrackets(const std::string& text);

// Parses "key=v1,v2,...". Throws std::invalid_argument naming the text and the reason.
SweepAxis parseSweepAxis(const std::string& text);

// The --set overrides of each variant (zipped axes). Throws std::invalid_argument when the axes'
// value counts differ or there are none.
std::vector<std::vector<std::string>> sweepVariants(const std::vector<SweepAxis>& axes);

}  // namespace ejecta
