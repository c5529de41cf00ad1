#include "core/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <random>
#include <stdexcept>
#include <string>
#include <system_error>

namespace ejecta {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void failWithErrno(const fs::path& path, const std::string& what, int err) {
  throw std::runtime_error("cannot write '" + path.string() + "': " + what + ": " +
                           std::strerror(err));
}

// ".name.tmp-<random hex>" in the target's directory. The leading dot keeps half-written files
// out of casual globs such as `*.h5`; the random suffix keeps concurrent writers apart.
fs::path temporaryNameFor(const fs::path& target) {
  std::random_device entropy;
  const unsigned long long tag =
      (static_cast<unsigned long long>(entropy()) << 32) ^ entropy() ^
      static_cast<unsigned long long>(::getpid());
  char suffix[32];
  std::snprintf(suffix, sizeof suffix, ".tmp-%016llx", tag);
  std::string name = ".";  // built stepwise: GCC 12 gives a false -Wrestrict on "." + string
  name += target.filename().string();
  name += suffix;
  return target.parent_path() / name;
}

// Pushes the file's data to stable storage before it replaces the target, so a crash right
// after the rename cannot leave an empty or partial file under the target's name.
void syncFile(const fs::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) failWithErrno(path, "open for sync", errno);
  const int rc = ::fsync(fd);
  const int err = errno;
  ::close(fd);
  if (rc != 0) failWithErrno(path, "fsync", err);
}

void writeAll(int fd, const fs::path& path, std::string_view contents) {
  while (!contents.empty()) {
    const ssize_t n = ::write(fd, contents.data(), contents.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      failWithErrno(path, "write", errno);
    }
    contents.remove_prefix(static_cast<std::size_t>(n));
  }
}

}  // namespace

AtomicFileTarget::AtomicFileTarget(fs::path target)
    : target_(std::move(target)), temp_(temporaryNameFor(target_)) {
  if (target_.filename().empty())
    throw std::runtime_error("cannot write '" + target_.string() + "': not a file name");
}

AtomicFileTarget::~AtomicFileTarget() {
  if (committed_) return;
  std::error_code ignored;  // best effort: a destructor must not throw
  fs::remove(temp_, ignored);
}

void AtomicFileTarget::commit() {
  if (committed_) throw std::logic_error("AtomicFileTarget::commit called twice");
  syncFile(temp_);
  std::error_code ec;
  fs::rename(temp_, target_, ec);
  if (ec)
    throw std::runtime_error("cannot write '" + target_.string() + "': rename from '" +
                             temp_.string() + "': " + ec.message());
  committed_ = true;
}

void writeFileAtomically(const fs::path& path, std::string_view contents) {
  AtomicFileTarget file(path);
  const fs::path& temp = file.tempPath();
  // O_EXCL: never clobber someone else's temporary; 0666 & umask gives ordinary permissions.
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) failWithErrno(path, "create '" + temp.string() + "'", errno);
  try {
    writeAll(fd, path, contents);
  } catch (...) {
    ::close(fd);
    throw;
  }
  if (::close(fd) != 0) failWithErrno(path, "close", errno);
  file.commit();
}

}  // namespace ejecta
