#pragma once
// Scene files compiled into the library (see cmake/EmbedScenes.cmake): the default scene of
// `ejecta run` and the verification problems of `ejecta verify`.
#include <string>
#include <string_view>
#include <vector>

namespace ejecta {

struct EmbeddedScene {
  std::string_view name;  // path under scenes/ without ".toml", e.g. "verification/sod_1d"
  std::string_view text;
};

const std::vector<EmbeddedScene>& embeddedScenes();
// The text of an embedded scene, or an empty view if there is none of that name.
std::string_view findEmbeddedScene(std::string_view name);

}  // namespace ejecta
