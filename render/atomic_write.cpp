#include "render/atomic_write.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <random>
#include <stdexcept>
#include <string>
#include <system_error>

namespace ejecta::render {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail(const fs::path& path, const std::string& what, int err) {
  throw std::runtime_error("cannot write '" + path.string() + "': " + what + ": " +
                           std::strerror(err));
}

// Removes the temporary file unless it was renamed onto the target.
struct TemporaryFile {
  fs::path path;
  bool kept = false;
  ~TemporaryFile() {
    if (kept) return;
    std::error_code ignored;
    fs::remove(path, ignored);
  }
};

}  // namespace

fs::path temporarySibling(const fs::path& target) {
  std::random_device entropy;
  const unsigned long long tag = (static_cast<unsigned long long>(entropy()) << 32) ^ entropy() ^
                                 static_cast<unsigned long long>(::getpid());
  char suffix[32];
  std::snprintf(suffix, sizeof suffix, ".tmp-%016llx", tag);
  std::string name = ".";
  name += target.filename().string();
  name += suffix;
  return target.parent_path() / name;
}

void writeFileAtomically(const fs::path& path, std::string_view bytes) {
  if (path.filename().empty())
    throw std::runtime_error("cannot write '" + path.string() + "': not a file name");
  TemporaryFile temp{temporarySibling(path)};
  const int fd = ::open(temp.path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) {
    temp.kept = true;  // never created: nothing to remove, and never remove someone else's
    fail(path, "cannot create '" + temp.path.string() + "'", errno);
  }
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd, bytes.data(), bytes.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      const int err = errno;
      ::close(fd);
      fail(path, "write", err);
    }
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
  // Data on disk before the rename: a crash right after it cannot leave an empty file.
  if (::fsync(fd) != 0) {
    const int err = errno;
    ::close(fd);
    fail(path, "fsync", err);
  }
  if (::close(fd) != 0) fail(path, "close", errno);
  std::error_code ec;
  fs::rename(temp.path, path, ec);
  if (ec)
    throw std::runtime_error("cannot write '" + path.string() + "': rename from '" +
                             temp.path.string() + "': " + ec.message());
  temp.kept = true;
}

}  // namespace ejecta::render
