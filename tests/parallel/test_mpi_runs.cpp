// A scene run on 2 or 3 ranks (CTest runs this binary under mpirun -np 2 and -np 3) against the
// same scene on one rank, in the same process: every stored field of every particle, matched by
// id, after the whole run. The one-rank run of each test is made by every rank alike
// (SerialCommunicator) and compared on rank 0.
//
// Tolerance: the ranks sum each particle's neighbours in another order (a halo's copies come
// after the rank's own particles), so the runs differ by round-off, about 1e-16 relative per
// sum, which the steps carry forward and shocks amplify: ~1e-13 after a few hundred steps of
// Sod, and up to ~1e-10 through the impact's contact (measured: the worst field of each test is
// printed). 1e-9 of each field's largest magnitude bounds every test here with room to spare,
// and is still six orders of magnitude below any physical effect the decomposition could have
// (a missed neighbour moves the density of its particle by ~1e-2).
#include <gtest/gtest.h>

#include "parallel/mpi_support.hpp"
#include "support/lone_fragment.hpp"
#include "support/periodic_blast.hpp"

namespace ejecta::test {
namespace {

constexpr double kTolerance = 1e-9;

std::shared_ptr<const Communicator> world() { return worldCommunicator(); }

// Runs `scene` on one rank and on every rank, and compares them; returns the ranks' run (its
// particles gathered on rank 0).
RankedRun expectSameAsOneRank(const Scene& scene) {
  const RankedRun one = runOn(scene, std::make_shared<SerialCommunicator>());
  const RankedRun many = runOn(scene, world());
  // Every rank took part: it held particles and borrowed a halo.
  EXPECT_GT(many.stats.haloReceived, 0u) << scene.name << " rank " << world()->rank();
  const std::uint64_t migrated = world()->sum(many.stats.migrated);
  EXPECT_EQ(one.steps, many.steps) << scene.name;
  EXPECT_NEAR(one.totals.total(), many.totals.total(), 1e-12 * std::abs(one.totals.total()));
  if (!world()->isRoot()) return many;
  const FieldDifference d = compareParticles(one.particles, many.particles);
  EXPECT_LE(d.relative, kTolerance) << scene.name << ": field " << d.field;
  std::printf("[ ranks %d ] %s: %ld steps, %zu particles (%zu moved rank, %ld decompositions), "
              "worst field %s differs by %.2e of its largest value\n", world()->size(),
              scene.name.c_str(), many.steps, many.particles.numReal, static_cast<std::size_t>(migrated),
              many.stats.rebalances, d.field.c_str(), d.relative);
  return many;
}

TEST(MpiRuns, Sod1dWithWalls) { expectSameAsOneRank(sceneFile("verification/sod_1d.toml", {})); }

// Each rank builds its slice of the scene (no rank holds it whole) in the other tests; built
// whole on every rank, as a restart starts, the run is the same.
TEST(MpiRuns, SodBuiltWholeOnEveryRank) {
  const Scene scene = sceneFile("verification/sod_1d.toml", {"time.t_end=0.05 s"});
  const RankedRun sliced = runOn(scene, world());
  const RankedRun whole = runOn(scene, world(), true);
  if (!world()->isRoot()) return;
  EXPECT_EQ(sliced.steps, whole.steps);
  const FieldDifference d = compareParticles(sliced.particles, whole.particles);
  EXPECT_EQ(d.relative, 0.0) << d.field;
}

TEST(MpiRuns, Sedov2dWithWalls) {
  expectSameAsOneRank(sceneFile("verification/sedov_2d.toml",
                                {"bodies[0].spacing=0.025", "energy_deposits[0].width=0.05",
                                 "time.t_end=0.02 s"}));
}

TEST(MpiRuns, SedovRzWithTheAxisMirror) {
  expectSameAsOneRank(sceneFile("verification/sedov_rz.toml",
                                {"bodies[0].spacing=0.2", "energy_deposits[0].radius=0.45",
                                 "time.t_end=0.01 s"}));
}

TEST(MpiRuns, Sedov3dWithWalls) {
  expectSameAsOneRank(sceneFile("verification/sedov_3d.toml",
                                {"bodies[0].spacing=0.0833333333333", "energy_deposits[0].radius=0.2",
                                 "time.t_end=0.03 s"}));
}

TEST(MpiRuns, PeriodicBlast) {
  expectSameAsOneRank(parseScene(periodicBlastScene(), "periodic_blast.toml", {"time.t_end=0.01"}));
}

TEST(MpiRuns, ImpactRzWithStrengthFractureAndThreeMaterials) {
  expectSameAsOneRank(sceneFile("impact_rz.toml",
                                {"bodies[0].spacing=0.5 m", "bodies[1].spacing=1.5 m",
                                 "bodies[2].spacing=1.5 m", "time.t_end=0.6 ms"}));
}

TEST(MpiRuns, JwlBurnInRz) {
  expectSameAsOneRank(sceneFile("contact_jwl_rz.toml",
                                {"bodies[0].spacing=0.15 m", "bodies[1].spacing=0.25 m",
                                 "time.t_end=0.2 ms"}));
}

TEST(MpiRuns, DelayedDepositSpanningRanks) {
  expectSameAsOneRank(sceneFile("verification/sedov_2d.toml",
                                {"bodies[0].spacing=0.025", "energy_deposits[0].width=0.1",
                                 "energy_deposits[0].time=0.004 s", "time.t_end=0.02 s"}));
}

// Porous material (docs/porosity.md): P-alpha's distention and its rate, epsilon-alpha's strain
// and the most compressive strain reached, travel with their particles.
TEST(MpiRuns, PalphaCompaction) {
  expectSameAsOneRank(sceneFile("verification/compaction_1d.toml",
                                {"bodies[0].spacing=\"0.2 mm\"", "time.t_end=\"4 us\""}));
}

TEST(MpiRuns, EpsilonAlphaCompaction) {
  expectSameAsOneRank(sceneFile("verification/compaction_epsalpha_1d.toml",
                                {"bodies[0].spacing=\"0.2 mm\"", "time.t_end=\"4 us\""}));
}

// A porous solid (docs/porosity.md, "The matrix's share of the strain"): its compaction factor
// and the state its step started from travel with it, with global steps and on time bins.
TEST(MpiRuns, PorousSolidCompaction) {
  for (const char* stepping : {"global", "individual"})
    expectSameAsOneRank(sceneFile("verification/compaction_1d.toml",
                                  {"bodies[0].spacing=\"0.2 mm\"", "time.t_end=\"4 us\"",
                                   "materials[0].strength.model=\"elastic\"",
                                   "materials[0].strength.shear_modulus=\"26 GPa\"",
                                   std::string("time.stepping=\"") + stepping + "\""}));
}

// Individual time steps (docs/time_steps.md): each particle's bin, its step's ends and its
// start values travel with it; the sub-steps end where the earliest step on any rank ends, and
// a particle that begins a step wakes its neighbours on other ranks through their halos.
TEST(MpiRuns, IndividualTimeStepsSedov2d) {
  expectSameAsOneRank(sceneFile("verification/sedov_2d.toml",
                                {"bodies[0].spacing=0.025", "energy_deposits[0].width=0.05",
                                 "time.t_end=0.03 s", "time.stepping=individual"}));
}

TEST(MpiRuns, IndividualTimeStepsPeriodicBlast) {
  std::string source = periodicBlastScene();
  const std::string key = "t_end = 0.02\n";
  source.replace(source.find(key), key.size(), key + "stepping = \"individual\"\n");
  expectSameAsOneRank(parseScene(source, "test_blast.toml"));
}

TEST(MpiRuns, IndividualTimeStepsImpactRzWithStrengthAndFracture) {
  expectSameAsOneRank(sceneFile("impact_rz.toml",
                                {"bodies[0].spacing=0.5 m", "bodies[1].spacing=1.5 m",
                                 "bodies[2].spacing=1.5 m", "time.t_end=0.6 ms",
                                 "time.stepping=individual"}));
}

TEST(MpiRuns, IndividualTimeStepsAcrossADelayedDeposit) {
  expectSameAsOneRank(sceneFile("verification/sedov_2d.toml",
                                {"bodies[0].spacing=0.025", "energy_deposits[0].width=0.1",
                                 "energy_deposits[0].time=0.004 s", "time.t_end=0.02 s",
                                 "time.stepping=individual"}));
}

// Issue 18's closing-speed criterion on ranks, with global and individual steps: it reads the
// halos' positions and velocities as the force pass saw them.
TEST(MpiRuns, ImpactRzWithTheClosingSpeed) {
  for (const char* stepping : {"global", "individual"})
    expectSameAsOneRank(sceneFile(
        "impact_rz.toml", {"bodies[0].spacing=0.5 m", "bodies[1].spacing=1.5 m",
                           "bodies[2].spacing=1.5 m", "time.t_end=0.6 ms",
                           "time.closing_speed=true", std::string("time.stepping=") + stepping}));
}

// Issue 23's smoothing-length cap on ranks: a per-particle field that migrates with its particle.
// The lone fragment of tests/support/lone_fragment.hpp (a 40 x 40 block, one particle leaving it
// at 3 km/s under continuity density), with h_max_factor 1: in flight at 50 us it is held at its
// cap, on whichever rank holds it (as in tests/sim/run/test_stability_rarefied.cpp); with global
// and individual steps.
TEST(MpiRuns, ALeavingParticleHeldAtItsSmoothingLengthCap) {
  for (const char* stepping : {"global", "individual"}) {
    const std::string time = "t_end = \"50 us\"\nstepping = \"" + std::string(stepping) + "\"\n";
    const std::string toml = loneFragmentScene("h_max_factor = 1\n", time, false);
    const RankedRun many = expectSameAsOneRank(parseScene(toml, "capped_fragment.toml"));
    if (!world()->isRoot()) continue;
    const ParticleSet& p = many.particles;
    const Field* cap = p.field("smoothing_length_cap");
    ASSERT_NE(cap, nullptr);
    std::size_t fragment = p.numReal;
    for (std::size_t i = 0; i < p.numReal; ++i)
      if (p.x[0][i] > 0.5) fragment = i;  // 0.405 m + 3 km/s x 50 us = 0.555 m
    ASSERT_LT(fragment, p.numReal) << stepping;
    const double capped = p.column(*cap, 0)[fragment];
    // The continuity cap is held to 1e-3 (tests/sim/run/test_stability_rarefied.cpp).
    EXPECT_NEAR(capped, 1.2 * 0.01, 1e-12);
    EXPECT_NEAR(p.h[fragment], capped, 1e-3 * capped) << stepping;
  }
}

}  // namespace
}  // namespace ejecta::test
