// TimeBins' kicks at the end of a particle's step follow the leapfrog's contract
// (sim/run/leapfrog.hpp): fields are kicked in registry order, and a Cap-limited field's caps come
// from the state the kicks before it left (the crack's cap reads the state at the step's end).
#include <gtest/gtest.h>

#include <numeric>
#include <vector>

#include "sim/run/leapfrog.hpp"
#include "sim/run/time_bins.hpp"
#include "sim/state/particles.hpp"

namespace {

using ejecta::Leapfrog;
using ejecta::ParticleSet;
using ejecta::TimeBins;

// More particles than kThreadTeamFrom (sim/parallel/thread_team.hpp): at the block's end every
// particle finishes, so the kicks run in a thread team.
constexpr std::size_t kParticles = 4000;

TEST(TimeBins, ACrackCapSeesTheEnergyKickedBeforeIt) {
  ParticleSet p;
  for (std::size_t i = 0; i < kParticles; ++i)
    p.append({static_cast<double>(i), 0.0, 0.0}, {0.0, 0.0, 0.0}, 1.0, 1.0, 0.0, 1.0, 0);
  p.enableFracture();  // the crack (Cap-limited) comes after the specific energy in the registry
  Leapfrog leapfrog;
  // A stand-in for the flaws' cap: each particle's specific energy, so the cap tells which state
  // it was taken from.
  leapfrog.setCaps("crack", [](const ParticleSet& q) {
    return std::vector<double>(q.u.begin(), q.u.begin() + static_cast<std::ptrdiff_t>(q.numReal));
  });
  TimeBins bins(2, 0.0);
  bins.registerFields(p, leapfrog, false, false);
  bins.beginBlock(0.0, 1.0);
  std::vector<std::size_t> all(kParticles);
  std::iota(all.begin(), all.end(), std::size_t{0});
  bins.ownSteps(p).assign(kParticles, 1.0);  // one step over the whole block (bin 0)
  ASSERT_TRUE(bins.beginSteps(p, leapfrog, all, {}));

  // Rates at the step's start: u' = 0.5, and a crack fast enough to reach any cap (10 per second
  // over half steps of 0.5 s). The first half kick: u = 0.25; the crack, capped by u(t0) = 0,
  // stays 0. (Powers of two throughout: every value below is exact.)
  for (std::size_t i = 0; i < kParticles; ++i) {
    p.du_dt[i] = 0.5;
    p.dcrack_dt[i] = 10.0;
  }
  const std::vector<std::size_t> ended = bins.advanceTo(p, leapfrog, TimeBins::kBlockTicks, 1);
  ASSERT_EQ(ended.size(), kParticles);
  ASSERT_EQ(p.u[0], 0.5);  // predicted to the step's end with the old rate

  // New rates at the step's end: u' = 1, so u(t1) = 0.25 + 0.5 = 0.75; the crack grows to its
  // cap, which is 0.75 if taken after the energy's kick and 0.5 (the prediction) if before it.
  for (std::size_t i = 0; i < kParticles; ++i) p.du_dt[i] = 1.0;
  bins.finishSteps(p, leapfrog, ended, 1);
  for (std::size_t i = 0; i < kParticles; ++i) {
    ASSERT_EQ(p.u[i], 0.75) << "particle " << i;
    ASSERT_EQ(p.crack[i], 0.75) << "particle " << i << ": the cap was not taken after the energy's kick";
  }
  EXPECT_EQ(bins.updates(), kParticles);
}

}  // namespace
