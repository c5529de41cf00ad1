// The re-evaluated velocity gradients of inactive particles (sim/sph/velocity_gradient_refresh.hpp)
// against the density pass's own, and the partners it picks.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "sim/setup/bodies.hpp"
#include "sim/setup/scene.hpp"
#include "sim/solid/materials.hpp"
#include "sim/sph/density_pass.hpp"
#include "sim/sph/kernel.hpp"
#include "sim/sph/velocity_gradient_refresh.hpp"
#include "support/fluid_option_checks.hpp"

namespace ejecta {
namespace {

// A 2D gas square of 20 x 20 particles (tests/support/fluid_option_checks.hpp's box, finer) with
// no boundaries: edge particles have one-sided neighbourhoods, where the limiter and the
// corrected gradient matter most.
ParticleSet gasSquare() {
  const Scene scene = parseScene(test::optionGasScene("", "2d"), "gradients.toml",
                                 {"bodies[0].spacing=0.05"});
  return buildParticles(scene, MaterialTable::fromScene(scene));
}

// A smooth, nonlinear flow with a kink (where the monotone limiter acts).
void setVelocities(ParticleSet& p, double phase) {
  for (std::size_t i = 0; i < p.numReal; ++i) {
    const double x = p.x[0][i], y = p.x[1][i];
    p.v[0][i] = std::sin(3.0 * x + phase) * y + std::abs(x - 0.5);
    p.v[1][i] = x * x - std::cos(2.0 * y - phase);
  }
}

struct Workspace {
  HydroWorkspace ws;
  explicit Workspace(ViscosityReconstruction reconstruction)
      : ws([&] {
          SphOptions o;
          o.viscosityReconstruction = reconstruction;
          return o;
        }(), Geometry::Planar) {}
  // The density pass over every particle (the grid from the present positions).
  void densityPass(ParticleSet& p) {
    ws.grid.build(p, 2, 0.15);
    ws.lists.reset(p.size(), omp_get_max_threads());  // a gather buffer per thread of the pass
    ASSERT_FALSE(runDensityPass(p, ws).has_value());
  }
};

// Every third particle's gradient, wiped and re-evaluated, is the density pass's to the last bit
// (the same neighbours in the same order, the same weights), with and without the limiter; after
// the flow changes, the re-evaluated gradients are the new flow's (gradients of order 1 here),
// and the particles not re-evaluated keep theirs.
TEST(VelocityGradientRefresh, IsTheDensityPassGradient) {
  for (const auto reconstruction :
       {ViscosityReconstruction::Monotone, ViscosityReconstruction::VanLeer}) {
    ParticleSet p = gasSquare();
    setVelocities(p, 0.0);
    Workspace w(reconstruction);
    w.densityPass(p);
    std::vector<std::size_t> some;
    for (std::size_t i = 0; i < p.numReal; i += 3) some.push_back(i);
    const std::vector<double> before = w.ws.velocityGradient;
    for (std::size_t i : some)
      for (int c = 0; c < 9; ++c) w.ws.velocityGradient[9 * i + c] = 1e30;
    refreshVelocityGradients(p, w.ws, some);
    EXPECT_EQ(w.ws.velocityGradient, before);

    // The flow moves on: the refreshed particles follow it (to the density pass's Newton
    // tolerance on h, 1e-7, which the next pass moves h by), the others keep their old tensor.
    setVelocities(p, 0.7);
    refreshVelocityGradients(p, w.ws, some);
    const std::vector<double> refreshed = w.ws.velocityGradient;
    w.densityPass(p);
    double changed = 0.0;
    for (std::size_t i = 0; i < p.numReal; ++i)
      for (int c = 0; c < 9; ++c) {
        const std::size_t k = 9 * i + static_cast<std::size_t>(c);
        if (i % 3 == 0) ASSERT_NEAR(refreshed[k], w.ws.velocityGradient[k], 1e-6) << i << " " << c;
        else ASSERT_EQ(refreshed[k], before[k]) << i << " " << c;
        changed = std::max(changed, std::abs(w.ws.velocityGradient[k] - before[k]));
      }
    EXPECT_GT(changed, 0.5);  // the two flows' gradients differ: the check above can fail
  }
}

// The partners it re-evaluates are the inactive particles within either support of an active one
// (found here by brute force), and no active particle (the density pass has just evaluated
// those).
TEST(VelocityGradientRefresh, PicksTheInactivePartnersOfTheActive) {
  ParticleSet p = gasSquare();
  setVelocities(p, 0.0);
  Workspace w(ViscosityReconstruction::Monotone);
  w.densityPass(p);
  const std::vector<std::size_t> active = {0, 57, 210, 211, 399};
  w.ws.grid.recordReach(p, kKernelSupport);
  w.ws.lists.buildActivePairs<2>(p, w.ws.grid, kKernelSupport, active);
  std::vector<std::size_t> expected;
  for (std::size_t j = 0; j < p.numReal; ++j) {
    bool isActive = false, partner = false;
    for (std::size_t i : active) {
      isActive = isActive || i == j;
      const double r = std::hypot(p.x[0][i] - p.x[0][j], p.x[1][i] - p.x[1][j]);
      partner = partner || r < kKernelSupport * std::max(p.h[i], p.h[j]);
    }
    if (partner && !isActive) expected.push_back(j);
  }
  EXPECT_GT(expected.size(), 40u);
  EXPECT_EQ(inactivePartners(p, w.ws, active), expected);
}

}  // namespace
}  // namespace ejecta
