#pragma once
// Atomic file replacement for render's outputs: the bytes go to a temporary file in the
// target's directory, are synced, then renamed over the target. A reader or a crash sees the
// old file or the new one, never half of one. (sim/ has the same for its outputs; render must
// not link sim, so it has its own.)
#include <filesystem>
#include <string_view>

namespace ejecta::render {

// Replaces `path` with `bytes`. Throws std::runtime_error naming the path and the reason on
// failure, leaving no temporary file behind and any earlier file at `path` untouched.
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

// A fresh temporary name next to `target`: ".<name>.tmp-<random hex>".
std::filesystem::path temporarySibling(const std::filesystem::path& target);

}  // namespace ejecta::render
