#include "sim/run/sweep.hpp"

#include <optional>
#include <stdexcept>

namespace ejecta {

namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

}  // namespace

std::optional<std::vector<std::string>> splitOutsideBrackets(const std::string& text) {
  std::vector<std::string> parts;
  std::string current;
  int depth = 0;
  char quote = 0;
  for (char c : text) {
    if (quote) {
      if (c == quote) quote = 0;
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '[' || c == '{') {
      ++depth;
    } else if (c == ']' || c == '}') {
      --depth;
    } else if (c == ',' && depth == 0) {
      parts.push_back(trim(current));
      current.clear();
      continue;
    }
    current += c;
  }
  if (quote || depth != 0) return std::nullopt;
  parts.push_back(trim(current));
  return parts;
}

SweepAxis parseSweepAxis(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    throw std::invalid_argument("--vary '" + text + "': expected key=v1,v2,...");
  SweepAxis axis;
  axis.key = trim(text.substr(0, eq));
  const auto values = splitOutsideBrackets(text.substr(eq + 1));
  if (!values) throw std::invalid_argument("--vary '" + text + "': unbalanced brackets or quotes");
  axis.values = *values;
  for (const std::string& v : axis.values)
    if (v.empty()) throw std::invalid_argument("--vary '" + text + "': an empty value");
  return axis;
}

std::vector<std::vector<std::string>> sweepVariants(const std::vector<SweepAxis>& axes) {
  if (axes.empty()) throw std::invalid_argument("a sweep needs at least one --vary key=v1,v2,...");
  const std::size_t n = axes.front().values.size();
  for (const SweepAxis& a : axes)
    if (a.values.size() != n)
      throw std::invalid_argument("--vary " + a.key + " has " + std::to_string(a.values.size()) +
                                  " values but --vary " + axes.front().key + " has " +
                                  std::to_string(n) + ": axes vary together and need as many");
  std::vector<std::vector<std::string>> variants(n);
  for (std::size_t k = 0; k < n; ++k)
    for (const SweepAxis& a : axes) variants[k].push_back(a.key + "=" + a.values[k]);
  return variants;
}

}  // namespace ejecta
