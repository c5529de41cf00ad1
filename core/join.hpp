#pragma once
// Lists in messages: "rock, ice, iron".
#include <functional>
#include <string>

namespace ejecta {

// The items of `range` joined with ", ", each as `name` gives it (the item itself by default:
// joinList(materials), joinList(library(), &Entry::name)).
template <typename Range, typename Name = std::identity>
std::string joinList(const Range& range, Name name = {}) {
  std::string out;
  for (const auto& item : range) {
    if (!out.empty()) out += ", ";
    out += std::invoke(name, item);
  }
  return out;
}

}  // namespace ejecta
