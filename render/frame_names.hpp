#pragma once
// Where a run's images go: <run>/images/<view>_NNNN.png, numbered from 0 with at least four
// digits, so that an alphabetical listing is the time order and tools (ffmpeg's %04d) find
// them.
#include <filesystem>
#include <string_view>

namespace ejecta::render {

// Throws std::invalid_argument for an empty view name, one with a path separator or a
// character outside [A-Za-z0-9_-.], or a negative index.
std::filesystem::path framePath(const std::filesystem::path& runDirectory, std::string_view view,
                                int index);

}  // namespace ejecta::render
