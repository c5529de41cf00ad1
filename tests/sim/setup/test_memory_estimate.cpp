// The memory check's estimate (sim/setup/memory_estimate.hpp): the particles counted from the
// bodies before any is built, and the bytes per particle the options take. The per-particle
// figures are measured by `ejecta_bench_memory` (bench/memory.cpp); these tests check that a run
// is charged what its options add, which a constant alone missed for Godunov SPH (its shared pair
// states took 3D runs to 1.21 of the assumed 2 kB).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "sim/setup/memory_estimate.hpp"
#include "sim/setup/scene.hpp"
#include "sim/setup/scene_catalog.hpp"

namespace ejecta {
namespace {

Scene shipped(const std::string& name, const std::vector<std::string>& overrides = {}) {
  const ShippedScene* s = findShippedScene(name);
  EXPECT_NE(s, nullptr) << name;
  return parseScene(std::string(s->text), name, overrides);
}

TEST(MemoryEstimate, CountsTheLatticeOfABox) {
  // The 3D Sedov: a unit cube at 1/36 spacing, 36^3 lattice points.
  const RunMemoryEstimate e = estimateRunMemory(shipped("verification/sedov_3d"));
  EXPECT_NEAR(e.particles, 46656.0, 1e-6 * 46656.0);
  EXPECT_DOUBLE_EQ(e.bytes, e.particles * kBytesPerParticle);
}

TEST(MemoryEstimate, GodunovSphIsChargedItsSharedPairStates) {
  for (const char* name : {"verification/sedov_3d", "verification/sedov_2d"}) {
    const Scene viscosity = shipped(name);
    const Scene godunov = shipped(name, {"sph.dissipation=riemann"});
    const int dim = spatialDimension(godunov.geometry);
    EXPECT_DOUBLE_EQ(bytesPerParticle(viscosity), kBytesPerParticle) << name;
    EXPECT_DOUBLE_EQ(bytesPerParticle(godunov), kBytesPerParticle + kRiemannBytesPerParticle[dim])
        << name;
    EXPECT_GT(estimateRunMemory(godunov).bytes, estimateRunMemory(viscosity).bytes) << name;
  }
  // Measured in 3D: 2,485 bytes per particle, which the estimate must cover.
  EXPECT_GE(bytesPerParticle(shipped("verification/sedov_3d", {"sph.dissipation=riemann"})), 2485.0);
}

}  // namespace
}  // namespace ejecta
