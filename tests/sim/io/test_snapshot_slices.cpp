// readSnapshot(path, info, part, parts): the slice of the stored rows each rank of a distributed
// restart reads. The slices of any count, in order, are the whole snapshot, bit for bit.
#include <gtest/gtest.h>

#include <filesystem>
#include <unistd.h>

#include "sim/io/particle_difference.hpp"
#include "sim/io/snapshot.hpp"

namespace ejecta {
namespace {

TEST(SnapshotSlices, TheSlicesOfAnyCountAreTheWholeSnapshot) {
  ParticleSet p;
  for (int i = 0; i < 11; ++i)
    p.append({0.1 * i, -0.2 * i, 0.3}, {1.0 + i, 2.0, -3.0 * i}, 1.0 + i, 2.0 + 0.5 * i, 3.0 * i, 0.05, i % 2);
  p.enableStrength(6);
  for (std::size_t i = 0; i < p.numReal; ++i) p.stress[3][i] = 1e6 * static_cast<double>(i);
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("ejecta_slices_" + std::to_string(::getpid()) + ".h5");
  SnapshotInfo info;
  info.time = 1.5;
  writeSnapshot(file.string(), p, info);
  SnapshotInfo back;
  const ParticleSet whole = readSnapshot(file.string(), back);
  for (int parts : {1, 2, 3, 4, 11, 13}) {
    ParticleSet joined = whole.withSameFields();
    std::size_t counted = 0;
    for (int part = 0; part < parts; ++part) {
      const ParticleSet slice = readSnapshot(file.string(), back, part, parts);
      EXPECT_EQ(back.time, 1.5);
      // Near-equal slices: no two differ by more than one particle.
      EXPECT_LE(slice.numReal, (whole.numReal + parts - 1) / parts);
      EXPECT_GE(slice.numReal, whole.numReal / parts);
      if (slice.numReal > 0) {
        EXPECT_EQ(static_cast<std::size_t>(slice.id.front()), counted) << parts;  // rows in file order
      }
      counted += slice.numReal;
      joined.resize(counted);
      for (const Field& f : slice.fields()) {
        if (f.storage.kind == FieldStorage::Kind::Derived) continue;
        for (std::size_t i = 0; i < slice.numReal; ++i) {
          const std::size_t at = counted - slice.numReal + i;
          if (f.storage.kind == FieldStorage::Kind::Int32) (joined.*f.storage.int32)[at] = (slice.*f.storage.int32)[i];
          else if (f.storage.kind == FieldStorage::Kind::Int64) (joined.*f.storage.int64)[at] = (slice.*f.storage.int64)[i];
          else
            for (int c = 0; c < f.spec.components; ++c) joined.column(f, c)[at] = slice.column(f, c)[i];
        }
      }
    }
    joined.numReal = counted;
    ASSERT_EQ(counted, whole.numReal) << parts;
    const FieldDifference d = largestDifference(particleDifferences(whole, joined));
    EXPECT_EQ(d.relative, 0.0) << parts << " slices: " << d.field;
  }
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace ejecta
