#include "fields/grid_file_seal.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace ejecta::fields {

namespace {

constexpr std::array<char, 8> kMagic{'E', 'J', 'V', 'D', 'B', 'S', 'U', 'M'};
constexpr std::size_t kTrailer = 16;
// The header with the file metadata comes first; 1 MiB holds it for any grid count ejecta writes.
constexpr std::size_t kHeaderScan = 1 << 20;

// FNV-1a, 64 bit (Fowler, Noll and Vo; http://www.isthe.com/chongo/tech/comp/fnv/), streamed.
struct Fnv1a64 {
  std::uint64_t hash = 14695981039346656037ull;
  void add(const char* data, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) hash = (hash ^ static_cast<unsigned char>(data[i])) * 1099511628211ull;
  }
};

// The checksum of the first `length` bytes of `in`.
std::uint64_t checksumOf(std::ifstream& in, std::uintmax_t length) {
  in.seekg(0);
  Fnv1a64 sum;
  std::vector<char> buffer(1 << 20);
  while (length > 0) {
    const std::size_t n = static_cast<std::size_t>(std::min<std::uintmax_t>(length, buffer.size()));
    if (!in.read(buffer.data(), static_cast<std::streamsize>(n))) throw std::runtime_error("read failed");
    sum.add(buffer.data(), n);
    length -= n;
  }
  return sum.hash;
}

[[noreturn]] void corrupt(const std::filesystem::path& path, const std::string& why) {
  throw std::runtime_error(path.string() + ": the grid file is damaged (" + why +
                           "): it is not what ejecta wrote; write it again with ejecta fields");
}

}  // namespace

void sealGridFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot open to seal");
  const std::uint64_t sum = checksumOf(in, std::filesystem::file_size(path));
  in.close();
  std::ofstream out(path, std::ios::binary | std::ios::app);
  out.write(kMagic.data(), kMagic.size());
  out.write(reinterpret_cast<const char*>(&sum), sizeof sum);  // little-endian hosts only (x86-64, arm64)
  if (!out.flush()) throw std::runtime_error(path.string() + ": cannot write the checksum");
}

void verifyGridFile(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw std::runtime_error(path.string() + ": is a directory, not a grid file");
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) throw std::runtime_error(path.string() + ": cannot read the grid file (" + ec.message() + ")");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot open the grid file");
  std::vector<char> head(static_cast<std::size_t>(std::min<std::uintmax_t>(size, kHeaderScan)));
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  const std::string key = kSealKey;
  if (std::search(head.begin(), head.end(), key.begin(), key.end()) == head.end()) return;  // not sealed
  if (size < kTrailer) corrupt(path, "shorter than its checksum");
  std::array<char, kTrailer> trailer{};
  in.clear();
  in.seekg(static_cast<std::streamoff>(size - kTrailer));
  in.read(trailer.data(), kTrailer);
  if (!std::equal(kMagic.begin(), kMagic.end(), trailer.begin()))
    corrupt(path, "its checksum trailer is missing: truncated?");
  std::uint64_t stored = 0;
  std::memcpy(&stored, trailer.data() + kMagic.size(), sizeof stored);
  in.clear();
  if (checksumOf(in, size - kTrailer) != stored) corrupt(path, "checksum mismatch");
}

}  // namespace ejecta::fields
