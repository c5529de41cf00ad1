// A distributed run's snapshot: one file, written by the ranks in turn (rank 0 creates it and
// writes its rows, then rank 1 its rows after them, ...), so that no rank holds another's
// particles. A small token travels along the ranks with the temporary file's name and the first
// error; it returns to rank 0, which renames the file into place or, after an error anywhere,
// removes it. Plain (serial) HDF5 suffices: only one rank has the file open at a time.
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

#include "core/atomic_file.hpp"
#include "sim/io/hdf5_io.hpp"
#include "sim/io/snapshot.hpp"
#include "sim/io/snapshot_rows.hpp"

namespace ejecta {

namespace {

// The token: the temporary file's name, then the first error (empty: none so far).
struct WriteToken {
  std::string tempPath;
  std::string error;
};

Bytes encode(const WriteToken& t) {
  const std::uint64_t length = t.tempPath.size();
  Bytes out;
  appendBytes(out, &length, 1);
  appendBytes(out, t.tempPath.data(), t.tempPath.size());
  appendBytes(out, t.error.data(), t.error.size());
  return out;
}

WriteToken decode(const Bytes& in) {
  std::uint64_t length = 0;
  std::copy(in.begin(), in.begin() + sizeof length, reinterpret_cast<std::byte*>(&length));
  const char* text = reinterpret_cast<const char*>(in.data()) + sizeof length;
  const std::size_t rest = in.size() - sizeof length;
  return {std::string(text, length), std::string(text + length, rest - length)};
}

void send(const Communicator& ranks, int to, const WriteToken& t) {
  const int partner[1] = {to};
  ranks.exchangeWith(partner, {encode(t)}, {});
}

WriteToken receive(const Communicator& ranks, int from) {
  const int partner[1] = {from};
  return decode(ranks.exchangeWith({}, {}, partner).front());
}

}  // namespace

void writeSnapshot(const std::string& path, const ParticleSet& p, const SnapshotInfo& info,
                   const Communicator& ranks) {
  if (ranks.size() == 1) {
    writeSnapshot(path, p, info);
    return;
  }
  // Each rank's rows follow those of the ranks before it.
  const std::uint64_t mine = p.numReal;
  std::size_t first = 0, total = 0;
  const std::vector<Bytes> counts = ranks.allGather({reinterpret_cast<const std::byte*>(&mine), sizeof mine});
  for (int r = 0; r < ranks.size(); ++r) {
    const std::uint64_t n = fromBytes<std::uint64_t>(counts[static_cast<std::size_t>(r)]).front();
    if (r < ranks.rank()) first += n;
    total += n;
  }
  const hdf5::QuietHdf5Errors quiet;
  const int next = (ranks.rank() + 1) % ranks.size();
  WriteToken token;
  std::optional<AtomicFileTarget> target;  // rank 0's
  if (ranks.isRoot()) {
    try {
      target.emplace(path);
      token.tempPath = target->tempPath().string();
      createSnapshotFile(target->tempPath(), p, info, total);
    } catch (const std::exception& e) {
      token.error = e.what();
    }
    send(ranks, next, token);
    token = receive(ranks, ranks.size() - 1);
    if (token.error.empty()) {
      try {
        target->commit();
      } catch (const std::exception& e) {
        token.error = e.what();
      }
    }
  } else {
    token = receive(ranks, ranks.rank() - 1);
    if (token.error.empty()) {
      try {
        writeSnapshotRows(token.tempPath, p, info.geometry, first, total);
      } catch (const std::exception& e) {
        token.error = "rank " + std::to_string(ranks.rank()) + ": " + e.what();
      }
    }
    send(ranks, next, token);
  }
  // Rank 0 holds the whole chain's outcome; every rank reports it alike. A failed file is
  // removed by rank 0's target; the earlier file at `path` is untouched.
  const std::string error = ranks.firstMessage(ranks.isRoot() ? token.error : std::string());
  if (!error.empty()) throw std::runtime_error("snapshot '" + path + "': " + error);
}

}  // namespace ejecta
