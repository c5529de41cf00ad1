// The blast measures shared by `ejecta verify` and ejecta_bench_sedov (sim/verify/blast_metrics.hpp)
// on constructed particle sets whose answers are known by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/verify/blast_metrics.hpp"

namespace ejecta::verify {
namespace {

// Particles on the x axis at r = 0.01, 0.02, ... (3D distances), each at `factor(k)` times the
// exact pressure of the spherical Sedov solution at its radius.
template <class Factor>
ParticleSet lineOfParticles(std::size_t n, const exact::SedovSolution& sedov, double t,
                            Factor factor) {
  ParticleSet p;
  p.resize(n);
  p.numReal = n;
  for (std::size_t k = 0; k < n; ++k) {
    const double r = 0.01 * static_cast<double>(k + 1);
    p.x[0][k] = r;
    p.mass[k] = 1.0;
    p.rho[k] = 1.0;
    p.P[k] = factor(k) * sedov.at(r, t).p;
  }
  return p;
}

const exact::SedovSolution kSedov(3, 1.4, 1.0, 1.0);
constexpr double kTime = 0.0669;  // R = 0.35 m
const std::array<double, 3> kOrigin{0.0, 0.0, 0.0};

TEST(BlastMetrics, CentrePressureIsTheMedianRatioOfTheInnermostParticles) {
  // Exact pressures everywhere: 1.
  const ParticleSet exact = lineOfParticles(100, kSedov, kTime, [](std::size_t) { return 1.0; });
  EXPECT_NEAR(centrePressureRatio(exact, kOrigin, 3, kSedov, kTime), 1.0, 1e-12);
  // The 32 innermost at 2x, the rest at 10x: only the innermost count.
  const ParticleSet hot =
      lineOfParticles(100, kSedov, kTime, [](std::size_t k) { return k < 32 ? 2.0 : 10.0; });
  EXPECT_NEAR(centrePressureRatio(hot, kOrigin, 3, kSedov, kTime), 2.0, 1e-12);
  // A few extreme particles among them do not move the median.
  const ParticleSet outliers = lineOfParticles(100, kSedov, kTime, [](std::size_t k) {
    return k < 5 ? 1e6 : (k < 32 ? 1.5 : 10.0);
  });
  EXPECT_NEAR(centrePressureRatio(outliers, kOrigin, 3, kSedov, kTime), 1.5, 1e-12);
  // Fewer particles than asked for: all of them; none: 0.
  const ParticleSet few = lineOfParticles(3, kSedov, kTime, [](std::size_t k) { return k + 1.0; });
  EXPECT_NEAR(centrePressureRatio(few, kOrigin, 3, kSedov, kTime), 2.0, 1e-12);
  EXPECT_EQ(centrePressureRatio(ParticleSet{}, kOrigin, 3, kSedov, kTime), 0.0);
}

TEST(BlastMetrics, ShockIsTheDensestBinAndItsMeanDensity) {
  ParticleSet p = lineOfParticles(100, kSedov, kTime, [](std::size_t) { return 1.0; });
  // Bins 0.1 wide: the particles of bin 3 (r in [0.3, 0.4)) at density 4, the rest at 1, and two
  // more in bin 3 whose mass-weighted mean is 4 too (mass 3 at density 3, mass 1 at 7).
  for (std::size_t k = 0; k < 100; ++k)
    if (static_cast<int>(p.x[0][k] / 0.1) == 3) p.rho[k] = 4.0;
  p.resize(102);
  p.numReal = 102;
  for (std::size_t k : {100u, 101u}) {
    p.x[0][k] = 0.355;
    p.mass[k] = k == 100 ? 3.0 : 1.0;
    p.rho[k] = k == 100 ? 3.0 : 7.0;
  }
  const BlastShock s = blastShock(p, kOrigin, 3, 0.1, 1.0);
  EXPECT_NEAR(s.radius, 0.35, 1e-12);
  EXPECT_NEAR(s.density, 4.0, 1e-12);
}

TEST(BlastMetrics, PeakPressureIsTheShellsHighestBinMean) {
  ParticleSet p = lineOfParticles(100, kSedov, kTime, [](std::size_t) { return 1.0; });
  // Every particle at 1 Pa but bin 2 (r in [0.2, 0.3)) at 5 Pa, and two more there, mass 3 at
  // 3 Pa and mass 1 at 11 Pa (mean 5 too); the densest bin (3, at 4: the shock at 0.35 m) is not
  // the highest-pressure one; then one particle at 50 Pa in bin 4 (r = 0.45) among its others at
  // 1 Pa; bins outside the shell (centres below 0.175 m or above 0.525 m) do not count.
  for (std::size_t k = 0; k < 100; ++k) {
    p.P[k] = static_cast<int>(p.x[0][k] / 0.1) == 2 ? 5.0 : 1.0;
    if (static_cast<int>(p.x[0][k] / 0.1) == 3) p.rho[k] = 4.0;
  }
  p.resize(102);
  p.numReal = 102;
  for (std::size_t k : {100u, 101u}) {
    p.x[0][k] = 0.255;
    p.mass[k] = k == 100 ? 3.0 : 1.0;
    p.rho[k] = 1.0;
    p.P[k] = k == 100 ? 3.0 : 11.0;
  }
  EXPECT_NEAR(blastShock(p, kOrigin, 3, 0.1, 1.0).pressure, 5.0, 1e-12);
  p.P[0] = p.P[80] = 1e3;  // r = 0.01 (the centre) and 0.81: outside the shell
  EXPECT_NEAR(blastShock(p, kOrigin, 3, 0.1, 1.0).pressure, 5.0, 1e-12);
  p.P[44] = 50.0;  // r = 0.45
  double inBin = 0.0;
  for (std::size_t k = 0; k < 100; ++k) inBin += static_cast<int>(p.x[0][k] / 0.1) == 4 ? 1.0 : 0.0;
  const BlastShock s = blastShock(p, kOrigin, 3, 0.1, 1.0);
  EXPECT_NEAR(s.pressure, (inBin - 1.0 + 50.0) / inBin, 1e-12);
  EXPECT_NEAR(s.radius, 0.35, 1e-12);  // the shock is still the densest bin
}

}  // namespace
}  // namespace ejecta::verify
