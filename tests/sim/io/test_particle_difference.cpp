// particleDifferences (sim/io/particle_difference.hpp): what "the same answer" is judged by.
#include <gtest/gtest.h>

#include <numeric>
#include <stdexcept>

#include "sim/io/particle_difference.hpp"

namespace ejecta {
namespace {

ParticleSet fourParticles() {
  ParticleSet p;
  for (int i = 0; i < 4; ++i) p.append({0.1 * i, 0.0, 0.0}, {1.0 * i, 0.0, 0.0}, 1.0, 2.0 + i, 3.0, 0.05, 0);
  return p;
}

TEST(ParticleDifference, TheSameParticlesInAnotherOrderDoNotDiffer) {
  const ParticleSet a = fourParticles();
  ParticleSet b = a;
  b.permute({3, 1, 0, 2});
  const FieldDifference worst = largestDifference(particleDifferences(a, b));
  EXPECT_EQ(worst.relative, 0.0) << worst.field;
}

TEST(ParticleDifference, AChangeIsMeasuredAgainstTheFieldsLargestValue) {
  const ParticleSet a = fourParticles();
  ParticleSet b = a;
  b.rho[1] += 1e-6;  // density runs 2 .. 5
  b.v[0][2] = -2.0;  // velocity x runs 0 .. 3: the larger change
  const std::vector<FieldDifference> all = particleDifferences(a, b);
  for (const FieldDifference& d : all) {
    if (d.field == "density") {
      EXPECT_NEAR(d.relative, 1e-6 / 5.0, 1e-15);
    }
    if (d.field == "velocity[0]") {
      EXPECT_DOUBLE_EQ(d.relative, 4.0 / 3.0);
    }
  }
  EXPECT_EQ(largestDifference(all).field, "velocity[0]");
  b.material[3] = 1;
  for (const FieldDifference& d : particleDifferences(a, b))
    if (d.field == "material") {
      EXPECT_EQ(d.relative, 1.0);
    }
}

TEST(ParticleDifference, SetsOfOtherParticlesAreRefusedNamingOne) {
  const ParticleSet a = fourParticles();
  ParticleSet b = a;
  b.id[2] = 17;
  try {
    particleDifferences(a, b);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("particle id 2 is in one of them only"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace ejecta
