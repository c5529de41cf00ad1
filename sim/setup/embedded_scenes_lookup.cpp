#include "sim/setup/embedded_scenes.hpp"

namespace ejecta {

std::string_view findEmbeddedScene(std::string_view name) {
  for (const EmbeddedScene& s : embeddedScenes())
    if (s.name == name) return s.text;
  return {};
}

}  // namespace ejecta
