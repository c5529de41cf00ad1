// Tests of the 1D Lagrangian hydrocode (sim/exact/radial_lagrangian.hpp), the converged reference
// of the UNDEX scenes (docs/undex.md, "The converged 1D reference"):
//   - planar C-J products against water at rest against the exact impedance match
//     (sim/exact/impedance_match.hpp): p*, u*, the shock's position, and their convergence;
//   - Sedov's point blast in an ideal gas (sim/exact/sedov.hpp), cylindrical and spherical:
//     shock radius and the density profile's L1 error, converging;
//   - a TNT slab detonated from a wall by the programmed burn against the Taylor wave
//     (sim/exact/taylor_wave.hpp);
//   - energy conserved to round-off (with the outer pressure's work), mass, the gauges;
//   - bad input refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "sim/eos/eos.hpp"
#include "sim/exact/impedance_match.hpp"
#include "sim/exact/radial_lagrangian.hpp"
#include "sim/exact/sedov.hpp"
#include "sim/exact/taylor_wave.hpp"
#include "sim/eos/jwl.hpp"
#include "sim/eos/mie_gruneisen.hpp"

namespace ejecta::exact {
namespace {

const JwlParams& tnt() { return jwlExplosive("TNT"); }
const ShockMaterial& water() { return shockMaterial("water"); }

RadialBurn tntBurn() {
  const JwlParams& p = tnt();
  return {p.dCJ, p.rho0, 1.0 - p.pCJ / (p.rho0 * p.dCJ * p.dCJ), 0.0};
}

// --- C-J products against water: the exact Riemann problem -------------------------------------

// As `ejecta verify undex_riemann_1d` (sim/verify/undex.cpp): 100 mm of products at the C-J state
// moving at u_CJ toward 60 mm of water at rest (P = 0), a wall at x = 0, to t = 8 us.
constexpr double kSlab = 0.1, kWater = 0.06, kRiemannTime = 8e-6;

RadialLagrangian supportedDetonation(double dx) {
  const ChapmanJouguetState cj = chapmanJouguetState(tnt());
  RadialSetup s;
  s.geometry = 1;
  s.zoneWidth = dx;
  s.regions.push_back({"products", kSlab, std::make_shared<Jwl>(tnt()), cj.rho, cj.u, cj.up, {}});
  s.regions.push_back({"water",
                       kSlab + kWater,
                       std::make_shared<MieGruneisen>(water()),
                       water().rho0,
                       0.0,
                       0.0,
                       {}});
  return RadialLagrangian(s);
}

struct RiemannErrors {
  double pressure, velocity, shockPosition, l1Pressure;
};

RiemannErrors riemannErrors(const RadialLagrangian& run, const InterfaceRiemannSolution& exact) {
  const double t = run.time(), pStar = exact.match().pressure(), uStar = exact.match().velocity();
  const double contact = kSlab + uStar * t, shock = kSlab + exact.match().target.us * t;
  // p* and u*: the mean over the shocked water between contact and shock, 20% of that span
  // left out at each end (the smeared shock and the contact's start-up error).
  double p = 0.0, u = 0.0;
  int count = 0;
  const double margin = 0.2 * (shock - contact);
  for (double x = contact + margin; x <= shock - margin; x += 1e-5, ++count) {
    const RadialSample s = run.at(x);
    p += s.pressure;
    u += s.velocity;
  }
  // The shock: the outermost point where the pressure crosses p*/2.
  double front = 0.0;
  for (double x = kSlab + kWater; x > contact; x -= 1e-6)
    if (run.at(x).pressure > 0.5 * pStar) {
      front = x;
      break;
    }
  // L1 of the pressure over every wave (fan head to the shock) plus 20%, in units of p* x span.
  const double left = kSlab + (exact.reflectedHeadSpeed() * t) * 1.2,
               right = kSlab + 1.2 * (shock - kSlab);
  double l1 = 0.0;
  const int samples = 20000;
  for (int k = 0; k < samples; ++k) {
    const double x = left + (k + 0.5) * (right - left) / samples;
    l1 += std::abs(run.at(x).pressure - exact.sample((x - kSlab) / t).p);
  }
  l1 /= samples * pStar;
  return {p / count / pStar - 1.0, u / count / uStar - 1.0, (front - shock) / (shock - kSlab), l1};
}

TEST(RadialLagrangian, PlanarProductsAgainstWaterMatchTheExactImpedanceMatch) {
  const InterfaceRiemannSolution exact(tnt(), water());
  const double shockTravel = exact.match().target.us * kRiemannTime;  // 47 mm
  RiemannErrors previous{};
  for (double dx : {0.4e-3, 0.2e-3, 0.1e-3}) {
    RadialLagrangian run = supportedDetonation(dx);
    const double e0 = run.totalEnergy();
    run.advanceTo(kRiemannTime);
    const RiemannErrors err = riemannErrors(run, exact);
    std::printf("dx %.2g mm: p* %+.2e u* %+.2e shock %+.2e L1(P)/p* %.4f, steps %ld, energy %.1e\n",
                dx * 1e3, err.pressure, err.velocity, err.shockPosition, err.l1Pressure,
                run.steps(), (run.totalEnergy() - e0) / e0);
    // The star state is a plateau the scheme holds exactly once the start-up transient has left
    // it: measured |errors| 3.5e-5, 1.3e-5, 4.3e-6 (p*) and 2.4e-5, 8.9e-6, 3.0e-6 (u*) at 0.4,
    // 0.2, 0.1 mm; 1e-4 is three times the largest (room for other compilers and libms).
    EXPECT_LT(std::abs(err.pressure), 1e-4) << dx;
    EXPECT_LT(std::abs(err.velocity), 1e-4) << dx;
    // The shock's half-height sits within a zone of the exact front (measured 0.3 zone behind it,
    // at every resolution: the smeared profile is a fixed number of zones wide).
    EXPECT_LT(std::abs(err.shockPosition) * shockTravel, dx) << dx;
    EXPECT_LT(err.l1Pressure, 0.01) << dx;  // measured 0.0050, 0.0025, 0.0013
    if (previous.l1Pressure > 0.0) {
      // First order at best across a shock, a contact and the fan's kinks (measured ratios 0.50,
      // 0.51): halving dx must cut the errors by at least 40%.
      EXPECT_LT(err.l1Pressure, 0.6 * previous.l1Pressure) << dx;
      EXPECT_LT(std::abs(err.shockPosition), 0.6 * std::abs(previous.shockPosition)) << dx;
    }
    previous = err;
  }
}

// --- Sedov's point blast
// --------------------------------------------------------------------------

struct SedovErrors {
  double shockRadius, l1Density;
};

// Energy E (Kamm & Timmes's values giving R = 1 at t = 1 for gamma = 1.4, rho0 = 1) in the first
// zone of a cold gas at rest, run to t = 1.
SedovErrors sedov(int j, double energy, double dx) {
  const double gamma = 1.4, rho0 = 1.0, rMax = 1.2;
  auto gas = std::make_shared<IdealGas>(gamma);
  RadialSetup s;
  s.geometry = j;
  s.zoneWidth = dx;
  // The measure of the first zone: dx, 2 pi dx^2 / 2, 4 pi dx^3 / 3.
  const double measure = j == 2 ? 2.0 * M_PI : 4.0 * M_PI;
  const double firstMass = rho0 * measure * std::pow(dx, j) / j;
  s.regions.push_back({"hot", dx, gas, rho0, energy / firstMass, 0.0, {}});
  s.regions.push_back({"cold", rMax, gas, rho0, 1e-12, 0.0, {}});
  RadialLagrangian run(s);
  const double e0 = run.totalEnergy();
  run.advanceTo(1.0);
  EXPECT_LT(std::abs(run.totalEnergy() - e0) / e0, 1e-13) << j << " " << dx;
  const SedovSolution exact(j, gamma, energy, rho0);
  // The shock: the outermost radius where the density crosses half-way to the exact post-shock
  // density.
  const double half = 0.5 * (rho0 + exact.postShockDensity());
  double front = 0.0;
  for (double r = rMax; r > 0.0; r -= 1e-5)
    if (run.at(r).density > half) {
      front = r;
      break;
    }
  double l1 = 0.0;
  const int samples = 24000;
  for (int k = 0; k < samples; ++k) {
    const double r = (k + 0.5) * rMax / samples;
    l1 += std::abs(run.at(r).density - exact.at(r, 1.0).rho) * rMax / samples;
  }
  std::printf("Sedov j=%d dx %.4f: shock %.5f (exact %.5f), L1(rho) %.4f, steps %ld\n", j, dx,
              front, exact.shockRadius(1.0), l1, run.steps());
  return {front / exact.shockRadius(1.0) - 1.0, l1};
}

TEST(RadialLagrangian, SedovBlastCylindricalAndSpherical) {
  for (auto [j, energy] : {std::pair{2, 0.311357}, std::pair{3, 0.851072}}) {
    const SedovErrors coarse = sedov(j, energy, 0.01), fine = sedov(j, energy, 0.005);
    // The Lagrangian shock lies ahead of the exact one by about half a zone of 1.2 m / 120
    // (measured +1.15% and +0.58% for j = 2, +0.87% and +0.43% for j = 3): within 1.5% and 0.75%,
    // and first order.
    EXPECT_LT(std::abs(coarse.shockRadius), 0.015) << j;
    EXPECT_LT(std::abs(fine.shockRadius), 0.0075) << j;
    // L1(rho) over [0, 1.2] (measured 0.094 -> 0.049 for both j): first order, the best a
    // captured shock allows; halving dx must cut it by 40%.
    EXPECT_LT(coarse.l1Density, 0.12) << j;
    EXPECT_LT(fine.l1Density, 0.6 * coarse.l1Density) << j;
  }
}

// --- A TNT slab detonated from a wall: the Taylor wave
// --------------------------------------------

TEST(RadialLagrangian, PlanarDetonationFollowsTheTaylorWave) {
  const TaylorWave exact(tnt());
  const double t = 10e-6;  // the front at 69.3 mm of the 100 mm slab
  double previousL1 = 0.0;
  for (double dx : {0.2e-3, 0.1e-3}) {
    RadialSetup s;
    s.geometry = 1;
    s.zoneWidth = dx;
    s.regions.push_back({"tnt", kSlab, std::make_shared<Jwl>(tnt()), tnt().rho0,
                         tnt().specificDetonationEnergy(), 0.0, tntBurn()});
    RadialLagrangian run(s);
    run.advanceTo(t);
    const double front = exact.detonationVelocity() * t;
    double l1 = 0.0, wall = 0.0, peak = 0.0;
    const int samples = 20000;
    for (int k = 0; k < samples; ++k) {
      const double x = (k + 0.5) * 1.1 * front / samples;
      const double p = run.at(x).pressure;
      l1 += std::abs(p - exact.sample(x / t).p) / samples;
      peak = std::max(peak, p);
    }
    l1 /= tnt().pCJ;
    // The wall plateau (x < c_wall t) away from the wall's own start-up zone.
    int count = 0;
    for (double x = 0.1 * exact.wallSoundSpeed() * t; x < 0.8 * exact.wallSoundSpeed() * t;
         x += 1e-5, ++count)
      wall += run.at(x).pressure;
    wall /= count;
    std::printf("Taylor dx %.2g mm: L1(P)/p_CJ %.4f, wall %+.2e, peak/p_CJ %.4f, steps %ld\n",
                dx * 1e3, l1, wall / exact.wall().p - 1.0, peak / tnt().pCJ, run.steps());
    // The wall plateau, exact behind the Taylor wave: measured +8.5e-4 and +4.9e-4.
    EXPECT_LT(std::abs(wall / exact.wall().p - 1.0), 1.5e-3) << dx;
    // The programmed burn rounds the C-J crest over its 1.5-zone ramp and the viscosity's
    // ~3 zones; measured L1(P)/p_CJ 0.0038 and 0.0022 over [0, 1.1 D t] (ratio 0.58), the peak
    // 0.985 and 0.984 p_CJ (no von Neumann spike: the burn releases the pressure behind the front).
    EXPECT_LT(l1, 0.006) << dx;
    EXPECT_GT(peak, 0.97 * tnt().pCJ) << dx;
    EXPECT_LT(peak, 1.01 * tnt().pCJ) << dx;
    if (previousL1 > 0.0) {
      EXPECT_LT(l1, 0.7 * previousL1);
    }
    previousL1 = l1;
  }
}

// --- Conservation
// ------------------------------------------------------------------------------------

TEST(RadialLagrangian, ConservesEnergyToRoundOffWithTheOuterWork) {
  for (int j : {1, 2, 3}) {
    RadialSetup s;
    s.geometry = j;
    s.zoneWidth = 0.5e-3;
    s.outerPressure = 101325.0;
    auto w = std::make_shared<MieGruneisen>(water());
    s.regions.push_back({"tnt", 0.02, std::make_shared<Jwl>(tnt()), tnt().rho0,
                         tnt().specificDetonationEnergy(), 0.0, tntBurn()});
    s.regions.push_back({"water", 0.1, w, 1000.0, w->specificEnergy(1000.0, 101325.0), 0.0, {}});
    RadialLagrangian run(s);
    const double e0 = run.totalEnergy(), m0 = run.totalMass();
    run.advanceTo(40e-6);
    const double error = (run.totalEnergy() - run.boundaryWork() - e0) / e0;
    std::printf("j=%d: energy error %.2e, boundary work %.3e J, steps %ld\n", j, error,
                run.boundaryWork(), run.steps());
    // Round-off: ~1e-16 per step and zone, summed over ~1000 steps with random signs.
    EXPECT_LT(std::abs(error), 1e-12) << j;
    EXPECT_EQ(run.totalMass(), m0);
    // The regions' energies add up to the totals (the centre node is at rest).
    EXPECT_NEAR(run.regionInternalEnergy(0) + run.regionInternalEnergy(1), run.internalEnergy(),
                1e-14 * run.totalEnergy());
    EXPECT_NEAR(run.regionKineticEnergy(0) + run.regionKineticEnergy(1), run.kineticEnergy(),
                1e-14 * run.totalEnergy());
    EXPECT_GT(run.regionKineticEnergy(1), 0.0);
    // The mass in the zones' current volumes equals the mass they were given.
    const double measure = j == 1 ? 1.0 : (j == 2 ? 2.0 * M_PI : 4.0 * M_PI);
    auto shell = [&](double a, double b) {
      return measure * (std::pow(b, j) - std::pow(a, j)) / j;
    };
    EXPECT_NEAR(run.regionMass(0), tnt().rho0 * shell(0.0, 0.02), 1e-12 * run.regionMass(0));
    double m = 0.0;
    for (std::size_t k = 0; k < run.zoneCount(); ++k)
      m += run.zoneDensity()[k] * shell(run.nodeRadius()[k], run.nodeRadius()[k + 1]);
    EXPECT_NEAR(m, m0, 1e-10 * m0) << j;
  }
}

TEST(RadialLagrangian, GaugesRecordEveryStepAndReadTheZones) {
  RadialSetup s;
  s.geometry = 3;
  s.zoneWidth = 1e-3;
  auto w = std::make_shared<MieGruneisen>(water());
  s.regions.push_back({"tnt", 0.02, std::make_shared<Jwl>(tnt()), tnt().rho0,
                       tnt().specificDetonationEnergy(), 0.0, tntBurn()});
  s.regions.push_back({"water", 0.2, w, 1000.0, w->specificEnergy(1000.0, 101325.0), 0.0, {}});
  s.outerPressure = 101325.0;
  RadialLagrangian run(s);
  run.addGauge("g05", 0.05);
  run.addGauge("outside", 0.5);
  run.advanceTo(30e-6);
  const RadialGauge& g = run.gauges()[0];
  EXPECT_EQ(g.time.size(), static_cast<std::size_t>(run.steps()) + 1);
  EXPECT_DOUBLE_EQ(g.time.back(), 30e-6);
  EXPECT_NEAR(g.pressure.front(), 101325.0, 1e-6);
  EXPECT_TRUE(std::isnan(run.gauges()[1].pressure.back()));
  // The last sample is the interpolant of the final zones.
  const RadialSample now = run.at(0.05);
  EXPECT_EQ(g.pressure.back(), now.pressure);
  EXPECT_EQ(g.density.back(), now.density);
  EXPECT_EQ(g.velocity.back(), now.velocity);
  // Between two zone centres the reading is their linear interpolant.
  const std::size_t k = 60;
  const double a = 0.5 * (run.nodeRadius()[k] + run.nodeRadius()[k + 1]);
  const double b = 0.5 * (run.nodeRadius()[k + 1] + run.nodeRadius()[k + 2]);
  const double mid = run.at(0.25 * a + 0.75 * b).pressure;
  EXPECT_NEAR(mid, 0.25 * run.zonePressure()[k] + 0.75 * run.zonePressure()[k + 1],
              1e-12 * std::abs(mid) + 1e-6);
  // The charge has burnt through: every explosive zone at F = 1.
  for (std::size_t z = 0; z < run.zoneCount(); ++z) {
    if (run.zoneRegion(z) == 0) {
      EXPECT_EQ(run.zoneBurnFraction()[z], 1.0) << z;
    }
  }
}

TEST(RadialLagrangian, SkippingTheQuietZonesChangesNothing) {
  // A small charge in water with the quiet zones skipped and with every zone stepped: the same
  // gauge histories up to round-off (the skipped run holds nodes whose velocity is below 1e-12 c,
  // the full one carries that round-off noise everywhere).
  auto w = std::make_shared<MieGruneisen>(water());
  const double e = w->specificEnergy(1000.0, 101325.0);
  RadialSetup s;
  s.zoneWidth = 0.5e-3;
  s.outerPressure = w->pressure(1000.0, e);
  s.regions.push_back({"tnt", 0.02, std::make_shared<Jwl>(tnt()), tnt().rho0,
                       tnt().specificDetonationEnergy(), 0.0, tntBurn()});
  s.regions.push_back({"water", 0.3, w, 1000.0, e, 0.0, {}});
  RadialSetup full = s;
  full.skipQuietZones = false;
  RadialLagrangian skipped(s), every(full);
  EXPECT_EQ(skipped.activeZones(), 40u);  // the charge
  EXPECT_EQ(every.activeZones(), every.zoneCount());
  for (RadialLagrangian* run : {&skipped, &every})
    for (double r : {0.05, 0.1, 0.15}) run->addGauge("g", r);
  skipped.advanceTo(50e-6);
  every.advanceTo(50e-6);
  // The shock (5 km/s at first, then about 2 km/s) has reached ~0.13 m: the zones beyond are idle.
  EXPECT_LT(skipped.activeZones(), 300u);
  EXPECT_GT(skipped.activeZones(), 200u);
  ASSERT_EQ(skipped.steps(), every.steps());
  double peak = 0.0, difference = 0.0;
  for (std::size_t g = 0; g < 3; ++g)
    for (std::size_t k = 0; k < every.gauges()[g].pressure.size(); ++k) {
      peak = std::max(peak, every.gauges()[g].pressure[k]);
      difference = std::max(
          difference, std::abs(skipped.gauges()[g].pressure[k] - every.gauges()[g].pressure[k]));
    }
  std::printf("skipped vs every zone: max |dp| / peak %.2e, active %zu of %zu\n", difference / peak,
              skipped.activeZones(), skipped.zoneCount());
  EXPECT_LT(difference, 1e-9 * peak);
  EXPECT_NEAR(skipped.totalEnergy() - skipped.boundaryWork(),
              every.totalEnergy() - every.boundaryWork(), 1e-12 * every.totalEnergy());
}

TEST(RadialLagrangian, RefusesBadInput) {
  auto gas = std::make_shared<IdealGas>(1.4);
  auto good = [&] {
    RadialSetup s;
    s.zoneWidth = 0.01;
    s.regions.push_back({"a", 1.0, gas, 1.0, 1.0, 0.0, {}});
    return s;
  };
  EXPECT_NO_THROW(RadialLagrangian{good()});
  auto refused = [&](auto change, const char* says) {
    RadialSetup s = good();
    change(s);
    try {
      RadialLagrangian r(s);
      ADD_FAILURE() << "accepted: " << says;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
  };
  refused([](RadialSetup& s) { s.geometry = 4; }, "geometry");
  refused([](RadialSetup& s) { s.regions.clear(); }, "no regions");
  refused([](RadialSetup& s) { s.zoneWidth = 0.0; }, "zone width");
  refused([](RadialSetup& s) { s.courant = 1.5; }, "Courant");
  refused([](RadialSetup& s) { s.linearViscosity = -1.0; }, "viscosity");
  refused([](RadialSetup& s) { s.regions[0].eos = nullptr; }, "'a': no equation of state");
  refused([](RadialSetup& s) { s.regions[0].density = -1.0; }, "'a': density");
  refused(
      [](RadialSetup& s) {
        s.regions.push_back(s.regions[0]);
        s.regions[1].name = "b";
      },
      "'b': outer radius");
  refused([](RadialSetup& s) { s.regions[0].burn.velocity = -1.0; }, "detonation velocity");
  refused([](RadialSetup& s) { s.outerPressure = NAN; }, "outer pressure");
  RadialLagrangian run(good());
  EXPECT_THROW(run.addGauge("g", -1.0), std::invalid_argument);
  run.advanceTo(1e-3);
  EXPECT_THROW(run.advanceTo(0.5e-3), std::invalid_argument);
}

}  // namespace
}  // namespace ejecta::exact
