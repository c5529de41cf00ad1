// libFuzzer target: the snapshot reader (sim/io/snapshot.hpp) on arbitrary bytes written to a
// file, the way `ejecta run --restart`, `fields`, `render` and `thermal --from` meet them.
// The reader's promise: a file is either a snapshot that passes every check of
// sim/io/snapshot_checks.hpp or an error "snapshot 'PATH': reason"; never a crash, a hang, an
// unbounded allocation or an unnamed error. Seeds are small real snapshots (tests/fuzz/corpus);
// their metadata and data carry Fletcher-32 checksums, so most mutations must be caught there.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>

#include "sim/io/snapshot.hpp"

namespace {

// One file per fuzzing process (the pid keeps parallel jobs apart), rewritten for each input.
const std::string& scratchPath() {
  static const std::string path = "/tmp/ejecta-fuzz-snapshot-" + std::to_string(::getpid()) + ".h5";
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = scratchPath();
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    const ejecta::SnapshotInfo header = ejecta::readSnapshotInfo(path);
    ejecta::SnapshotInfo info;
    const ejecta::ParticleSet particles = ejecta::readSnapshot(path, info);
    // The two readers agree, and what passed the checks is consistent with itself.
    if (header.time != info.time || header.step != info.step ||
        particles.mass.size() != particles.numReal || particles.x[0].size() != particles.numReal) {
      std::fprintf(stderr, "snapshot read inconsistently: t %g/%g, %zu rows of %zu\n", header.time,
                   info.time, particles.mass.size(), particles.numReal);
      std::abort();
    }
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    if (message.rfind("snapshot '" + path + "'", 0) != 0) {
      std::fprintf(stderr, "snapshot refusal without the file name: %s\n", message.c_str());
      std::abort();
    }
  }
  return 0;
}
