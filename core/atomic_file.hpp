#pragma once
// Atomic replacement of output files: write everything to a temporary file next to the target,
// flush it to disk, then rename it over the target. A reader (or a crash) sees either the
// complete old file or the complete new one, never a half-written file.
#include <filesystem>
#include <string_view>

namespace ejecta {

// Replaces `path` with `contents` atomically. Throws std::runtime_error (naming the file) on
// failure, in which case any earlier file at `path` is left untouched.
void writeFileAtomically(const std::filesystem::path& path, std::string_view contents);

// A temporary path in the target's directory (same file system, so rename is atomic).
// Write to tempPath(), then commit(); if the object is destroyed without a successful commit
// the temporary file is removed and the target is unchanged.
class AtomicFileTarget {
 public:
  explicit AtomicFileTarget(std::filesystem::path target);
  ~AtomicFileTarget();
  AtomicFileTarget(const AtomicFileTarget&) = delete;
  AtomicFileTarget& operator=(const AtomicFileTarget&) = delete;

  const std::filesystem::path& target() const { return target_; }
  const std::filesystem::path& tempPath() const { return temp_; }

  // Syncs the temporary file to disk and renames it onto the target. Throws on failure
  // (the temporary is then removed by the destructor).
  void commit();
  bool committed() const { return committed_; }

 private:
  std::filesystem::path target_;
  std::filesystem::path temp_;
  bool committed_ = false;
};

}  // namespace ejecta
