#pragma once
// A checksum sealed onto every grid file ejecta writes, checked before OpenVDB parses one: a
// flipped or truncated byte is a clear error naming the file, not a crash or a runaway
// allocation inside the reader (which trusts the sizes it reads). The seal is a 16-byte
// trailer, "EJVDBSUM" and the FNV-1a-64 of every byte before it, after the grids' data where
// OpenVDB never reads; the header's metadata key `ejecta_sealed` says a trailer must be there,
// so truncation is caught too. Grid files of other tools (no key) are read unchecked.
// docs/robustness.md.
#include <filesystem>
#include <string>

namespace ejecta::fields {

// The file-level metadata key that marks a sealed file (its value: the trailer's format).
inline constexpr const char* kSealKey = "ejecta_sealed";
inline constexpr const char* kSealFormat = "fnv1a64-trailer-v1";

// Appends the trailer to the finished file at `path`.
void sealGridFile(const std::filesystem::path& path);

// Throws std::runtime_error naming `path` when it is marked sealed and its trailer is missing
// or does not match its contents.
void verifyGridFile(const std::filesystem::path& path);

}  // namespace ejecta::fields
