#pragma once
// A small periodic 2D blast shared by tests: a strong shock, every particle moving, nothing
// touching a wall (1,600 particles, 0.02 s). `sphTables` is TOML inserted after [domain], e.g.
// "[sph.viscosity]\nswitch = \"morris_monaghan\"\n".
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "sim/io/snapshot.hpp"
#include "sim/run/run.hpp"
#include "sim/setup/scene.hpp"

namespace ejecta::test {

inline std::string periodicBlastScene(const std::string& sphTables = "") {
  return R"(
[scene]
name = "test_blast"
dimension = "2d"
[domain]
x = { min = -0.5, max = 0.5, boundary = "periodic" }
y = { min = -0.5, max = 0.5, boundary = "periodic" }
)" + sphTables + R"(
[time]
t_end = 0.02
[output]
snapshot_interval = 0.005
[[materials]]
name = "gas"
eos = "ideal_gas"
gamma = 1.4
[[bodies]]
name = "box"
material = "gas"
shape = "box"
min = [-0.5, -0.5]
max = [0.5, 0.5]
spacing = 0.025
density = 1.0
pressure = 1e-4
[[energy_deposits]]
name = "blast"
energy = 0.1
center = [0.0, 0.0]
radius = 0.06
)";
}

// The restart check of a scene with snapshots every quarter of its run: runs it into `full` and
// into `cut`, removes cut's snapshots 3 and 4 and resumes cut from its snapshot 2 (halfway), so
// that full/ and cut/ snapshots/snap_0004.h5 can be compared. Fails the calling test on error.
inline void runAndResumeFromSnapshot2(const std::string& source, const std::filesystem::path& full,
                                      const std::filesystem::path& cut, int threads = 2,
                                      const std::vector<std::shared_ptr<PhysicsPackage>>& packages = {}) {
  for (const std::filesystem::path& dir : {full, cut}) {
    RunOptions options;
    options.outDir = dir.string();
    options.sceneSource = source;
    options.threads = threads;
    options.packages = packages;
    const RunOutcome r = runScene(parseScene(source, "test_blast.toml"), options);
    ASSERT_TRUE(r.ok) << r.error;
  }
  ASSERT_TRUE(std::filesystem::remove(cut / "snapshots" / "snap_0003.h5"));
  ASSERT_TRUE(std::filesystem::remove(cut / "snapshots" / "snap_0004.h5"));
  RunOptions options;
  options.threads = threads;
  options.packages = packages;
  const RunOutcome resumed = restartRun(cut.string(), options);
  ASSERT_TRUE(resumed.ok) << resumed.error;
}

// After runAndResumeFromSnapshot2: full/ and cut/ last snapshots (snap_0004) are the same to the
// last bit: step, time, positions, velocities, energies, densities and smoothing lengths.
inline void expectLastSnapshotsMatch(const std::filesystem::path& full,
                                     const std::filesystem::path& cut) {
  SnapshotInfo infoA, infoB;
  const ParticleSet a = readSnapshot((full / "snapshots" / "snap_0004.h5").string(), infoA);
  const ParticleSet b = readSnapshot((cut / "snapshots" / "snap_0004.h5").string(), infoB);
  ASSERT_EQ(infoA.step, infoB.step);
  ASSERT_EQ(infoA.time, infoB.time);
  ASSERT_EQ(a.numReal, b.numReal);
  for (std::size_t i = 0; i < a.numReal; ++i) {
    for (int d = 0; d < 3; ++d) {
      ASSERT_EQ(a.x[d][i], b.x[d][i]) << "particle " << i;
      ASSERT_EQ(a.v[d][i], b.v[d][i]) << "particle " << i;
    }
    ASSERT_EQ(a.u[i], b.u[i]) << "particle " << i;
    ASSERT_EQ(a.rho[i], b.rho[i]) << "particle " << i;
    ASSERT_EQ(a.h[i], b.h[i]) << "particle " << i;
  }
}

}  // namespace ejecta::test
