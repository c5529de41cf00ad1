// The force pass restricted to a sub-step's active particles (individual time steps,
// sim/sph/hydro_force.hpp) against the full pass on the same state: each active particle gets the
// full pass's derivatives to the last bit, and the others keep theirs. The restricted pass
// prepares each per-particle term (Balsara's factor, the stress divergence's scaled stress, the
// artificial stress's principal tensions, the pressure terms) for the particles its pairs read
// only (touchedBy): a partner missed there would enter its pairs unprepared. A 2D granite block
// with Balsara's switch, the artificial stress, the interface form and continuity density, and a
// gas block in the Lagrangian form (with the viscosity and with Godunov SPH), both with a
// nonuniform state and flow.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "sim/setup/bodies.hpp"
#include "sim/setup/scene.hpp"
#include "sim/solid/materials.hpp"
#include "sim/sph/density_pass.hpp"
#include "sim/sph/hydro_force.hpp"
#include "sim/sph/kernel.hpp"
#include "support/fluid_option_checks.hpp"

namespace ejecta {
namespace {

// A nonuniform state: pressure, sound speed, a compressing and shearing flow, and (solids) a
// deviatoric stress that varies over the block, so that every per-particle term differs between
// particles.
void setState(ParticleSet& p) {
  for (std::size_t i = 0; i < p.numReal; ++i) {
    const double x = p.x[0][i], y = p.x[1][i];
    p.P[i] = 1e8 * (1.0 + 0.3 * std::sin(5.0 * x) * std::cos(3.0 * y));
    p.cs[i] = 4000.0 + 500.0 * x;
    p.v[0][i] = -200.0 * x + 50.0 * y * y;
    p.v[1][i] = 80.0 * std::sin(4.0 * x) - 100.0 * y;
    if (p.stressComponents() == 0) continue;
    p.stress[0][i] = 3e7 * std::sin(6.0 * x + y);
    p.stress[1][i] = -2e7 * std::cos(2.0 * y);
    p.stress[2][i] = -p.stress[0][i] - p.stress[1][i];
    p.stress[3][i] = 4e7 * x * y;  // xy: with the others, tensions for the artificial stress
  }
}

// The derivatives a force pass writes, as one flat list of columns (drho/dt with continuity
// density only).
std::vector<std::vector<double>*> derivatives(ParticleSet& p, const SphOptions& options) {
  std::vector<std::vector<double>*> columns = {&p.a[0], &p.a[1], &p.du_dt};
  if (options.density == DensityMethod::Continuity) columns.push_back(&p.drho_dt);
  for (int c = 0; c < p.stressComponents(); ++c) columns.push_back(&p.dstress_dt[c]);
  if (p.stressComponents() > 0) columns.push_back(&p.strainRate);
  return columns;
}

void expectRestrictedPassMatchesFull(const std::string& toml, const SphOptions& options,
                                     bool solid) {
  const Scene scene = parseScene(toml, "restricted.toml", {"bodies[0].spacing=0.05"});
  ParticleSet p = buildParticles(scene, MaterialTable::fromScene(scene));
  if (solid) p.enableStrength(4);
  setState(p);
  HydroWorkspace ws(options, Geometry::Planar);
  if (solid) {
    ws.shearModulus = {30e9};
    ws.yieldCarriesDamage = {0};
    ws.artificialStress = 0.3;
  }
  ws.grid.build(p, 2, 0.15);
  ws.lists.reset(p.size(), omp_get_max_threads());
  ASSERT_FALSE(runDensityPass(p, ws).has_value());

  ws.lists.findGhostGathers<2>(p, ws.grid, kKernelSupport);
  ws.lists.buildPairs<2>(p, kKernelSupport);
  runForcePass(p, ws);
  std::vector<std::vector<double>> full;
  for (const std::vector<double>* column : derivatives(p, options)) full.push_back(*column);

  // Every fifth particle, edges and interior alike, and a cluster of neighbours.
  std::vector<std::size_t> active;
  for (std::size_t i = 0; i < p.numReal; i += 5) active.push_back(i);
  for (std::size_t i = 201; i < 205; ++i) active.push_back(i);
  std::sort(active.begin(), active.end());
  const double sentinel = -1234.5;
  for (std::vector<double>* column : derivatives(p, options)) column->assign(column->size(), sentinel);
  ws.grid.recordReach(p, kKernelSupport);
  ws.lists.buildActivePairs<2>(p, ws.grid, kKernelSupport, active);
  runForcePass(p, ws, nullptr, &active);

  std::vector<char> isActive(p.numReal, 0);
  for (std::size_t i : active) isActive[i] = 1;
  const std::vector<std::vector<double>*> after = derivatives(p, options);
  double largest = 0.0;
  for (std::size_t c = 0; c < after.size(); ++c)
    for (std::size_t i = 0; i < p.numReal; ++i) {
      const double expected = isActive[i] ? full[c][i] : sentinel;
      ASSERT_EQ(std::bit_cast<std::uint64_t>((*after[c])[i]), std::bit_cast<std::uint64_t>(expected))
          << "column " << c << ", particle " << i << (isActive[i] ? " (active)" : "");
      if (isActive[i]) largest = std::max(largest, std::abs(expected));
    }
  EXPECT_GT(largest, 0.0);  // the pass did compute something for the active particles
}

TEST(RestrictedForcePass, SolidActiveParticlesGetTheFullPassDerivatives) {
  SphOptions o;
  o.balsara = true;
  o.form = MomentumForm::Interface;
  o.density = DensityMethod::Continuity;
  expectRestrictedPassMatchesFull(test::optionSolidScene("") + R"(
[[bodies]]
name = "block"
material = "granite"
shape = "box"
min = [0.0, 0.0]
max = [1.0, 1.0]
spacing = 0.1
density = 2680.0
pressure = 0.0
)",
                                  o, true);
}

TEST(RestrictedForcePass, GasActiveParticlesGetTheFullPassDerivatives) {
  SphOptions o;
  o.balsara = true;
  o.conductivity = 1.0;
  expectRestrictedPassMatchesFull(test::optionGasScene("", "2d"), o, false);
}

// Godunov SPH solves a pair both particles sum once and hands the upper one the state mirrored
// (sim/sph/shared_pair_stars.hpp): here the full pass shares every real pair and the restricted
// one only those between active particles, so a state read with the wrong sign, from the wrong
// pair or by the wrong particle would part the two.
TEST(RestrictedForcePass, GodunovActiveParticlesGetTheFullPassDerivatives) {
  SphOptions o;
  o.dissipation = Dissipation::Riemann;
  o.viscosityReconstruction = ViscosityReconstruction::Monotone;
  expectRestrictedPassMatchesFull(test::optionGasScene("", "2d"), o, false);
}

}  // namespace
}  // namespace ejecta
