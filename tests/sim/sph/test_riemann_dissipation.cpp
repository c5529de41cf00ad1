// The Riemann-solver dissipation (sph.dissipation = "riemann", Godunov SPH): the pair's star state
// (sim/sph/terms/riemann_dissipation.hpp) against the exact ideal-gas Riemann solution, the force
// pass's conservation, threads and mirror ghosts, and the scenes it is refused for. Its runs
// against exact shock solutions are in tests/sim/verify/test_verify_riemann_dissipation.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "sim/exact/riemann.hpp"
#include "sim/sph/terms/riemann_dissipation.hpp"
#include "support/fluid_option_checks.hpp"
#include "support/quarter_blast.hpp"

namespace ejecta {
namespace {

constexpr double kGamma = 1.4;  // (gamma + 1)/4 = 0.6 = kShockSlope: the solver's own gas

RiemannSide side(double rho, double u, double P) {
  return {rho, u, P, std::sqrt(kGamma * P / rho)};
}

StarState exactStar(const RiemannSide& L, const RiemannSide& R) {
  const exact::RiemannProblem problem({L.rho, L.u, L.P}, {R.rho, R.u, R.P}, kGamma);
  return {problem.starPressure(), problem.starVelocity()};
}

// Equal pressures and velocities across any density jump: no wave, nothing to dissipate.
TEST(RiemannDissipation, AContactFeelsNoDissipation) {
  for (double u : {0.0, 0.3, -250.0}) {
    const StarState s = twoShockStar(side(4.0, u, 1.0), side(1.0, u, 1.0));
    EXPECT_NEAR(s.P, 1.0, 1e-15);
    EXPECT_NEAR(s.u, u, 1e-15 * (1.0 + std::abs(u)));
  }
}

// Seen from the other side (left and right swapped, the axis reversed): the same pressure and the
// opposite velocity, so the pair's force and work are the same from both particles.
TEST(RiemannDissipation, IsTheSameFromEitherSide) {
  const RiemannSide L = side(1.0, 0.7, 1.0), R = side(0.125, -0.2, 0.1);
  const StarState a = twoShockStar(L, R),
                  b = twoShockStar({R.rho, -R.u, R.P, R.c}, {L.rho, -L.u, L.P, L.c});
  EXPECT_NEAR(a.P, b.P, 1e-14 * a.P);
  EXPECT_NEAR(a.u, -b.u, 1e-14);
}

// Two streams meeting at U each side: two equal shocks, and each side's jump is the ideal gas's own
// shock relation, so P* is exact (to round-off) at every strength.
TEST(RiemannDissipation, SymmetricCollisionGivesTheExactStarPressure) {
  for (const double P : {1e-4, 1.0, 100.0}) {  // Mach 85, 0.85, 0.085
    const RiemannSide L = side(1.0, 1.0, P), R = side(1.0, -1.0, P);
    const StarState s = twoShockStar(L, R), e = exactStar(L, R);
    EXPECT_NEAR(s.u, 0.0, 1e-15);
    EXPECT_NEAR(s.P / e.P, 1.0, 1e-12) << "P = " << P;
  }
}

// Two shocks of unequal strength (Toro 2009, Table 4.1, test 5: two colliding shock-heated
// streams; exact P* = 1691.64, u* = 8.68975): both waves shocks, so exact once Newton's steps
// have converged (to 1e-12 of the speeds here, 1e-14 in the exact solver).
TEST(RiemannDissipation, TwoShockTubeGivesTheExactStarState) {
  const RiemannSide L = side(5.99924, 19.5975, 460.894), R = side(5.99242, -6.19633, 46.0950);
  const StarState s = twoShockStar(L, R), e = exactStar(L, R);
  std::printf("  Toro test 5: P* %.6g (exact %.6g), u* %.6g (exact %.6g)\n", s.P, e.P, s.u, e.u);
  EXPECT_NEAR(e.P, 1691.64, 0.01);
  EXPECT_NEAR(s.P / e.P, 1.0, 1e-8);
  EXPECT_NEAR(s.u - e.u, 0.0, 1e-8 * std::abs(L.u - R.u));
}

// Weak waves (a pair's jump in a smooth flow is small): the acoustic limit, exact to second order.
TEST(RiemannDissipation, WeakWavesAreAcoustic) {
  for (const double jump : {1e-3, -1e-3}) {  // compression, expansion
    const RiemannSide L = side(1.0, 0.5 * jump, 1.0), R = side(0.9, -0.5 * jump, 0.95);
    const StarState s = twoShockStar(L, R), e = exactStar(L, R);
    // The waves' strengths are ~5% (the pressure step): second order leaves ~2.5e-3 of it.
    EXPECT_NEAR(s.P, e.P, 2e-4);
    EXPECT_NEAR(s.u, e.u, 2e-4);
  }
}

// Two gases pulled apart faster than their sound: the acoustic rarefactions would give a negative
// pressure, which a gas cannot hold.
TEST(RiemannDissipation, NoTensionFromGasesPulledApart) {
  const StarState s = twoShockStar(side(1.0, -10.0, 1.0), side(1.0, 10.0, 1.0));
  EXPECT_EQ(s.P, 0.0);
  // A material under tension keeps its own: the floor is the lower of the two pressures.
  EXPECT_EQ(twoShockStar({1.0, -10.0, -2.0, 1.0}, {1.0, 10.0, -3.0, 1.0}).P, -3.0);
}

// --- The force pass ---------------------------------------------------------------------------

TEST(RiemannDissipation, StrongBlastConservesEnergyAndMomentum) {
  test::expectBlastConserves({"sph.dissipation=riemann"});
}

TEST(RiemannDissipation, IsIndependentOfThreadCount) {
  test::expectThreadIndependent({"sph.dissipation=riemann"});
}

// Mirror ghosts carry their sources' reflected velocity gradients (the reconstruction's): the
// particles beside the walls of the quarter box see what they see in the full box.
TEST(RiemannDissipation, QuarterDomainWithMirrorWallsMatchesTheFullBox) {
  const test::QuarterMismatch m = test::quarterAgainstFullBox("[sph]\ndissipation = \"riemann\"\n");
  std::printf("  quarter against full box: position %.2e m, pressure %.2e of the peak\n",
              m.position, m.pressure);
  // The same particles and arithmetic with sums in another order: round-off, as the other fluid
  // options' same tests allow.
  EXPECT_LT(m.position, 1e-12);
  EXPECT_LT(m.pressure, 1e-10);
}

// --- Where it is refused, with the key named (tests/support/fluid_option_checks.hpp) --------

constexpr const char* kOn = "dissipation = \"riemann\"";

TEST(RiemannDissipation, RefusedWhereItIsNotBuilt) {
  using test::expectReaderRefuses, test::optionGasScene;
  const Scene accepted = parseScene(optionGasScene(kOn, "2d"), "gsph.toml");
  // The velocities are reconstructed unless the scene says otherwise.
  EXPECT_EQ(accepted.sph.viscosityReconstruction, ViscosityReconstruction::Monotone);
  EXPECT_EQ(parseScene(optionGasScene(kOn, "2d", "[sph.viscosity]\nreconstruction = \"none\"\n"),
                       "gsph.toml")
                .sph.viscosityReconstruction,
            ViscosityReconstruction::None);
  const std::string key = "sph.dissipation";
  expectReaderRefuses(optionGasScene(kOn, "2d", "gradients = \"iad\"\n"), key, "kernel gradient");
  expectReaderRefuses(optionGasScene(kOn, "2d", "volume_elements = \"generalised\"\n"), key,
                      "mass volumes");
  expectReaderRefuses(optionGasScene(kOn, "rz"), key, "RZ");
  expectReaderRefuses(optionGasScene(kOn, "2d", "density = \"continuity\"\n"), key,
                      "summation density");
  expectReaderRefuses(optionGasScene(kOn, "2d", "form = \"interface\"\n"), key, "Lagrangian form");
  expectReaderRefuses(optionGasScene(kOn, "2d", "", "stepping = \"individual\"\n"), key,
                      "global time steps");
  expectReaderRefuses(optionGasScene("dissipation = \"godunov\"", "2d"), key, "riemann");
  expectReaderRefuses(test::optionSolidScene(kOn), key, "granite");
}

TEST(RiemannDissipation, TheSimulationRefusesWhatTheReaderWouldHave) {
  test::expectSimulationRefusesIndividualSteps(kOn, "sph.dissipation");
}

}  // namespace
}  // namespace ejecta
