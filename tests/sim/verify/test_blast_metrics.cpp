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

}  // namespace
}  // namespace ejecta::verify
