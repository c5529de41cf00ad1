#include "render/frame_names.hpp"

#include <cstdio>
#include <stdexcept>
#include <string>

namespace ejecta::render {

std::filesystem::path framePath(const std::filesystem::path& runDirectory, std::string_view view,
                                int index) {
  const std::string name(view);
  if (name.empty() || name == "." || name == "..")
    throw std::invalid_argument("frame view name '" + name + "' is not a usable file name");
  for (char c : name) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '_' || c == '-' || c == '.';
    if (!ok)
      throw std::invalid_argument("frame view name '" + name +
                                  "' may hold only letters, digits, '_', '-' and '.'");
  }
  if (index < 0)
    throw std::invalid_argument("frame index must be >= 0, got " + std::to_string(index));
  char number[16];
  std::snprintf(number, sizeof number, "%04d", index);
  return runDirectory / "images" / (name + "_" + number + ".png");
}

}  // namespace ejecta::render
