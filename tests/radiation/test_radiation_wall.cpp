// Wall heat model: materials table, layered-wall discretisation and its input errors, energy
// conservation of both schemes, stability limits, 2D/1D consistency, melting times, histories
// as CSV, flux histories from CSV, the radiative balance and shield sizing.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "radiation/constants.hpp"
#include "radiation/layered_wall.hpp"
#include "radiation/radiative_balance.hpp"
#include "radiation/shield_sizing.hpp"
#include "radiation/wall_boundary.hpp"
#include "radiation/wall_explicit.hpp"
#include "radiation/wall_implicit.hpp"
#include "radiation/wall_materials.hpp"

namespace ejecta::radiation {
namespace {

namespace fs = std::filesystem;
constexpr double kPi = std::numbers::pi;

// The message of the exception `f` throws ("" when it does not throw).
template <class F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

// A fresh directory for files of one test.
fs::path scratchDirectory(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("ejecta_wall_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

SurfaceFlux constantFlux(double q) {
  return [q](double, double) { return q; };
}

// ---------------------------------------------------------------------------------------------
// Materials

TEST(WallMaterials, TableHasTheSeedsMaterialsWithSourcesAndValidValues) {
  const std::vector<std::string> names = {"aluminium", "tungsten", "tantalum", "tantalum_carbide",
                                          "graphite",  "titanium", "hafnia"};
  ASSERT_EQ(wallMaterials().size(), names.size());
  for (std::size_t k = 0; k < names.size(); ++k) {
    const WallMaterial& m = wallMaterials()[k];
    EXPECT_EQ(m.name, names[k]);
    EXPECT_NO_THROW(validateWallMaterial(m)) << m.name;
    EXPECT_FALSE(m.source.empty()) << m.name;
    EXPECT_GT(m.boilingPoint, m.meltingPoint - 1e-9) << m.name;
  }
}

TEST(WallMaterials, LookupByNameAndAliasGivesSIValues) {
  const WallMaterial& al = wallMaterial("Aluminum");  // US spelling, any case
  EXPECT_EQ(al.name, "aluminium");
  EXPECT_DOUBLE_EQ(al.conductivity, 237.0);   // W/(m K), Incropera A.1 at 300 K
  EXPECT_DOUBLE_EQ(al.meltingPoint, 933.47);  // K
  // alpha = k/(rho c_p) = 237/(2702 * 903) = 9.71e-5 m^2/s (Incropera A.1 lists 97.1e-6).
  EXPECT_NEAR(al.diffusivity(), 97.1e-6, 0.05e-6);
  EXPECT_EQ(wallMaterial("W").name, "tungsten");
  EXPECT_DOUBLE_EQ(wallMaterial("W").density, 19300.0);  // kg/m^3
  EXPECT_EQ(wallMaterial("TaC").name, "tantalum_carbide");
  EXPECT_EQ(wallMaterial("tantalum carbide").name, "tantalum_carbide");
  EXPECT_EQ(wallMaterial("HfO2").name, "hafnia");
  // Pyrolytic graphite: across its planes 5.7 W/(m K) (the seed's value), along them 1950.
  const WallMaterial& c = wallMaterial("graphite");
  EXPECT_DOUBLE_EQ(c.conductivity, 5.70);
  EXPECT_DOUBLE_EQ(c.alongFaceConductivity(), 1950.0);
  EXPECT_DOUBLE_EQ(al.alongFaceConductivity(), 237.0);
  const WallMaterial seed = seedAluminium();
  EXPECT_DOUBLE_EQ(seed.emissivity, 0.02);
  EXPECT_DOUBLE_EQ(seed.absorptivity, 0.08);
  EXPECT_DOUBLE_EQ(seed.emissivity, kSeedAluminiumEmissivity);
  EXPECT_DOUBLE_EQ(seed.absorptivity, kSeedAluminiumAbsorptivity);
}

TEST(WallMaterials, UnknownNameIsAClearError) {
  const std::string message = errorOf([] { wallMaterial("unobtainium"); });
  EXPECT_TRUE(contains(message, "unknown wall material 'unobtainium'")) << message;
  EXPECT_TRUE(contains(message, "tungsten")) << message;  // lists the known ones
  EXPECT_THROW(wallLayer("unobtainium", 1e-3, 4), std::invalid_argument);
}

TEST(WallMaterials, BadPropertiesAreNamed) {
  WallMaterial m = wallMaterial("tungsten");
  m.density = -1.0;
  EXPECT_TRUE(contains(errorOf([&] { validateWallMaterial(m); }), "'tungsten': density"));
  m = wallMaterial("tungsten");
  m.emissivity = 1.5;
  EXPECT_TRUE(contains(errorOf([&] { validateWallMaterial(m); }), "emissivity"));
}

// ---------------------------------------------------------------------------------------------
// Layered wall

TEST(LayeredWall, NodesSitOnFacesAndInterfacesWithHalfCellsOfEachMaterial) {
  const WallMaterial w = wallMaterial("tungsten"), al = wallMaterial("aluminium");
  const LayeredWall wall({{w, 0.2e-3, 4}, {al, 3e-3, 6}});
  ASSERT_EQ(wall.nodeCount(), 11);
  EXPECT_EQ(wall.firstNode(0), 0);
  EXPECT_EQ(wall.lastNode(0), 4);
  EXPECT_EQ(wall.firstNode(1), 4);
  EXPECT_EQ(wall.lastNode(1), 10);
  EXPECT_EQ(wall.layerOfNode(3), 0u);
  EXPECT_EQ(wall.layerOfNode(4), 1u);  // the interface node: the cold-side layer
  EXPECT_NEAR(wall.position()[4], 0.2e-3, 1e-18);
  EXPECT_NEAR(wall.thickness(), 3.2e-3, 1e-18);
  const double dxW = 0.05e-3, dxAl = 0.5e-3;
  const double cW = w.density * w.specificHeat, cAl = al.density * al.specificHeat;
  EXPECT_NEAR(wall.capacity()[0], 0.5 * cW * dxW, 1e-12);
  EXPECT_NEAR(wall.capacity()[2], cW * dxW, 1e-12);
  EXPECT_NEAR(wall.capacity()[4], 0.5 * cW * dxW + 0.5 * cAl * dxAl, 1e-12);
  EXPECT_NEAR(wall.conductance()[3], w.conductivity / dxW, 1e-6);
  EXPECT_NEAR(wall.conductance()[4], al.conductivity / dxAl, 1e-9);
  EXPECT_NEAR(wall.inPlaneConductance()[4], 0.5 * (w.conductivity * dxW + al.conductivity * dxAl),
              1e-15);
  // Total heat capacity and areal mass are those of the layers.
  double total = 0.0;
  for (const double c : wall.capacity()) total += c;
  EXPECT_NEAR(total, cW * 0.2e-3 + cAl * 3e-3, 1e-9);
  EXPECT_NEAR(wall.arealMass(), 19300 * 0.2e-3 + 2702 * 3e-3, 1e-12);
}

TEST(LayeredWall, BadLayersAreClearErrors) {
  const WallMaterial w = wallMaterial("tungsten"), al = wallMaterial("aluminium");
  std::string m = errorOf([&] { LayeredWall({{w, 0.2e-3, 4}, {al, 0.0, 6}}); });
  EXPECT_TRUE(contains(m, "layer 2 of 2 ('aluminium')") && contains(m, "thickness")) << m;
  m = errorOf([&] { LayeredWall({{w, std::nan(""), 4}}); });
  EXPECT_TRUE(contains(m, "layer 1 of 1 ('tungsten')") && contains(m, "thickness")) << m;
  m = errorOf([&] { LayeredWall({{w, -1e-3, 4}}); });
  EXPECT_TRUE(contains(m, "thickness")) << m;
  m = errorOf([&] { LayeredWall({{w, 1e-3, 0}}); });
  EXPECT_TRUE(contains(m, "cells")) << m;
  m = errorOf([] { LayeredWall(std::vector<WallLayer>{}); });
  EXPECT_TRUE(contains(m, "no layers")) << m;
  WallMaterial broken = al;
  broken.specificHeat = 0.0;
  m = errorOf([&] { LayeredWall({{w, 1e-3, 2}, {broken, 1e-3, 2}}); });
  EXPECT_TRUE(contains(m, "layer 2 of 2") && contains(m, "specificHeat")) << m;
  m = errorOf([&] { WallGrid(LayeredWall({{w, 1e-3, 2}}), 0.0, 5); });
  EXPECT_TRUE(contains(m, "faceLength")) << m;
}

// ---------------------------------------------------------------------------------------------
// Energy conservation: with insulated faces and a known absorbed flux, the stored heat
// Sum C (T - T0) equals the energy put in, to round-off.

struct EnergyCase {
  const char* name;
  std::unique_ptr<WallSolver> solver;
};

TEST(WallEnergy, InsulatedWallStoresExactlyTheAbsorbedEnergy) {
  const WallGrid grid{
      LayeredWall({wallLayer("tungsten", 0.2e-3, 5), wallLayer("aluminium", 3e-3, 12)})};
  const double q0 = 3e7, tau = 2e-3, end = 1e-3, dt = 2e-5, t0 = 300.0;
  const std::vector<double> initial(grid.size(), t0);
  // Constant flux: both schemes exactly q0 * t.
  for (int scheme = 0; scheme < 2; ++scheme) {
    WallBoundaries bc;
    bc.hot = FaceCondition::irradiated(constantFlux(q0), 1.0, 0.0);
    std::unique_ptr<WallSolver> s;
    if (scheme == 0)
      s = std::make_unique<ExplicitWallSolver>(grid, bc, t0);
    else
      s = std::make_unique<CrankNicolsonWallSolver>(grid, bc, t0);
    s->run(end, dt);
    const double stored = storedHeat(grid, s->temperature(), initial);
    EXPECT_NEAR(stored / (q0 * end), 1.0, 1e-12) << scheme;
    EXPECT_NEAR(s->faceEnergy() / (q0 * end), 1.0, 1e-12) << scheme;
  }
  // Flux linear in time, q0 (1 + t/tau): pure CN's trapezoidal face term integrates it exactly,
  // q0 (t + t^2/(2 tau)); with the backward-Euler start-up, and in the explicit scheme, the
  // stored heat is exactly what the scheme's own face quadrature put in.
  const SurfaceFlux ramp = [=](double t, double) { return q0 * (1.0 + t / tau); };
  WallBoundaries bc;
  bc.hot = FaceCondition::irradiated(ramp, 1.0, 0.0);
  CrankNicolsonOptions pure;
  pure.startupSteps = 0;
  CrankNicolsonWallSolver cn(grid, bc, t0, pure);
  cn.run(end, dt);
  EXPECT_NEAR(storedHeat(grid, cn.temperature(), initial) / (q0 * (end + end * end / (2 * tau))),
              1.0, 1e-12);
  CrankNicolsonWallSolver started(grid, bc, t0);
  started.run(end, dt);
  EXPECT_NEAR(storedHeat(grid, started.temperature(), initial) / started.faceEnergy(), 1.0, 1e-12);
  ExplicitWallSolver ex(grid, bc, t0);
  ex.run(end, dt);
  EXPECT_NEAR(storedHeat(grid, ex.temperature(), initial) / ex.faceEnergy(), 1.0, 1e-12);
  EXPECT_NEAR(ex.faceEnergy() / (q0 * (end + end * end / (2 * tau))), 1.0, 1e-2);
}

TEST(WallEnergy, RadiatingFacesKeepTheBalanceToRoundOff) {
  // Absorbed flux and T^4 re-radiation on the hot face, re-radiation on the cold face: what the
  // faces exchanged (as each scheme applied it, CN's linearised T^4 included) is what is stored.
  const WallGrid grid{
      LayeredWall({wallLayer("tungsten", 0.2e-3, 6), wallLayer("aluminium", 1e-3, 6)})};
  WallBoundaries bc;
  bc.hot = FaceCondition::irradiated(constantFlux(5e7), 0.43, 0.15);
  bc.cold = FaceCondition::radiating(0.06, 3.0);
  const std::vector<double> initial(grid.size(), 1200.0);
  ExplicitWallSolver ex(grid, bc, 1200.0);
  CrankNicolsonWallSolver cn(grid, bc, 1200.0);
  ex.run(5e-3, 1e-4);
  cn.run(5e-3, 1e-4);
  for (const WallSolver* s :
       {static_cast<const WallSolver*>(&ex), static_cast<const WallSolver*>(&cn)}) {
    const double stored = storedHeat(grid, s->temperature(), initial);
    EXPECT_GT(stored, 0.0);
    EXPECT_NEAR(stored / s->faceEnergy(), 1.0, 1e-11);
  }
  // The two schemes agree to their truncation error (a few 0.01 K here).
  EXPECT_NEAR(ex.temperature()[0], cn.temperature()[0], 0.1);
}

TEST(WallEnergy, TwoDimensionalWallIntegratesAFluxVaryingAlongTheFace) {
  // q(y) = q0 (1 + y/L) along a 2D face (per unit depth): energy q0 * 1.5 L * t, exact for the
  // trapezoidal node widths since q is linear in y.
  const double q0 = 2e7, length = 0.01, end = 5e-4, t0 = 300.0;
  const WallGrid grid(
      LayeredWall({wallLayer("tungsten", 0.2e-3, 4), wallLayer("aluminium", 2e-3, 8)}), length, 21);
  WallBoundaries bc;
  bc.hot = FaceCondition::irradiated([=](double, double y) { return q0 * (1.0 + y / length); }, 1.0,
                                     0.0);
  const std::vector<double> initial(grid.size(), t0);
  ExplicitWallSolver ex(grid, bc, t0);
  CrankNicolsonWallSolver cn(grid, bc, t0);
  ex.run(end, 1e-5);
  cn.run(end, 1e-5);
  const double expected = q0 * 1.5 * length * end;
  EXPECT_NEAR(storedHeat(grid, ex.temperature(), initial) / expected, 1.0, 1e-12);
  // The LDL^T solve leaves a residual of a few ulps of the matrix scale.
  EXPECT_NEAR(storedHeat(grid, cn.temperature(), initial) / expected, 1.0, 1e-10);
  // Heat spreads along the face: the hotter end (y = L) is hotter.
  EXPECT_GT(cn.temperature()[grid.index(0, 20)], cn.temperature()[grid.index(0, 0)]);
}

// ---------------------------------------------------------------------------------------------
// Stability limits and consistency between 1D and 2D

TEST(ExplicitWall, StableStepIsKOneHalfIn1DAndKxPlusKyOneHalfIn2D) {
  const WallMaterial al = wallMaterial("aluminium");
  const double a = al.diffusivity(), dx = 1e-3 / 10;
  WallBoundaries bc;  // insulated
  ExplicitWallSolver oneD(WallGrid(LayeredWall({{al, 1e-3, 10}})), bc, 300.0);
  EXPECT_NEAR(oneD.stableTimeStep(), 0.5 * dx * dx / a, 1e-15);
  const double dy = 0.02 / 40;
  ExplicitWallSolver twoD(WallGrid(LayeredWall({{al, 1e-3, 10}}), 0.02, 41), bc, 300.0);
  EXPECT_NEAR(twoD.stableTimeStep(), 0.5 / (a * (1 / (dx * dx) + 1 / (dy * dy))), 1e-15);
  EXPECT_NEAR(twoD.effectiveK(twoD.stableTimeStep()), 0.5, 1e-12);
  // A radiating face at 3000 K adds 4 eps sigma T^3 over the face node's half-cell capacity.
  bc.hot = FaceCondition::radiating(1.0);
  ExplicitWallSolver hot(WallGrid(LayeredWall({{al, 1e-3, 10}})), bc, 3000.0);
  const double c0 = 0.5 * al.density * al.specificHeat * dx;
  const double rate = 2 * a / (dx * dx) + 4 * kStefanBoltzmann * 27e9 / c0;
  EXPECT_NEAR(hot.stableTimeStep() * rate, 1.0, 1e-12);
}

TEST(ExplicitWall, RefusalNamesTheLimitingLayer) {
  const WallGrid grid{
      LayeredWall({wallLayer("tungsten", 0.2e-3, 8), wallLayer("aluminium", 3e-3, 6)})};
  ExplicitOptions refuse;
  refuse.stability = StabilityPolicy::Refuse;
  ExplicitWallSolver solver(grid, {}, 300.0, refuse);
  const std::string m = errorOf([&] { solver.advance(10.0 * solver.stableTimeStep()); });
  EXPECT_TRUE(contains(m, "'tungsten'") && contains(m, "exceeds the stability limit")) << m;
  EXPECT_EQ(solver.time(), 0.0);  // nothing was done
}

TEST(WallSolvers, UniformFaceIn2DMatchesThe1DSolutionInEveryColumn) {
  const LayeredWall wall({wallLayer("tantalum", 0.3e-3, 6), wallLayer("titanium", 2e-3, 10)});
  WallBoundaries bc;
  bc.hot = FaceCondition::irradiated(constantFlux(4e7), wallMaterial("tantalum"));
  bc.cold = FaceCondition::radiating(0.19);
  const WallGrid line(wall), strip(wall, 0.05, 7);
  for (int scheme = 0; scheme < 2; ++scheme) {
    std::unique_ptr<WallSolver> a, b;
    if (scheme == 0) {
      a = std::make_unique<ExplicitWallSolver>(line, bc, 300.0);
      b = std::make_unique<ExplicitWallSolver>(strip, bc, 300.0);
    } else {
      a = std::make_unique<CrankNicolsonWallSolver>(line, bc, 300.0);
      b = std::make_unique<CrankNicolsonWallSolver>(strip, bc, 300.0);
    }
    a->run(2e-3, 5e-5);
    b->run(2e-3, 5e-5);
    for (int j = 0; j < strip.ny(); ++j)
      for (int i = 0; i < strip.nx(); ++i)
        EXPECT_NEAR(b->temperature()[strip.index(i, j)], a->temperature()[line.index(i, 0)], 1e-8)
            << scheme << " " << i << " " << j;
  }
}

TEST(WallSolvers, LinearisedAndIteratedCrankNicolsonAgreeAsTheStepShrinks) {
  // Linearising T^4 about the step's start costs O(dt^2) per unit time, like CN itself.
  const WallGrid grid{LayeredWall({wallLayer("tungsten", 0.5e-3, 10)})};
  WallBoundaries bc;
  bc.hot = FaceCondition::irradiated(constantFlux(1e8), 0.43, 0.15);
  auto surface = [&](int iterations, double dt) {
    CrankNicolsonOptions o;
    o.maxIterations = iterations;
    CrankNicolsonWallSolver s(grid, bc, 300.0, o);
    s.run(2e-2, dt);
    return s.temperature()[0];
  };
  const double d1 = std::abs(surface(1, 1e-3) - surface(20, 1e-3));
  const double d2 = std::abs(surface(1, 5e-4) - surface(20, 5e-4));
  EXPECT_GT(d1, 0.0);
  EXPECT_NEAR(std::log2(d1 / d2), 2.0, 0.3);
}

// ---------------------------------------------------------------------------------------------
// Histories

TEST(WallHistory, MeltingTimeMatchesTheSemiInfiniteSolution) {
  // A thick aluminium slab under a constant absorbed flux: its surface rises as
  // (2q/k) sqrt(alpha t/pi), reaching the melting point at
  // t_m = pi k^2 (T_m - T_0)^2 / (4 q^2 alpha).
  const WallMaterial al = wallMaterial("aluminium");
  const double q = 5e8, t0 = 300.0;
  const double tm =
      kPi * std::pow(al.conductivity * (al.meltingPoint - t0), 2) / (4 * q * q * al.diffusivity());
  const WallGrid grid{LayeredWall({{al, 2e-3, 400}})};
  WallBoundaries bc;
  bc.hot = FaceCondition::irradiated(constantFlux(q), 1.0, 0.0);
  CrankNicolsonWallSolver solver(grid, bc, t0);
  WallHistory history(grid);
  solver.run(2 * tm, tm / 200, &history);
  std::printf("  melting time: %.6e s, semi-infinite %.6e s\n", history.meltTime(0), tm);
  // 5 um cells and tm/200 steps resolve the 0.9 mm diffusion length: 0.5% covers their error.
  EXPECT_NEAR(history.meltTime(0) / tm, 1.0, 5e-3);
  EXPECT_TRUE(std::isnan(WallHistory(grid).meltTime(0)));
  EXPECT_EQ(history.size(), 401u);  // the initial state and 400 steps
  EXPECT_DOUBLE_EQ(history.peakTemperature(0), history.hotFace().back());
}

TEST(WallHistory, WritesCsvAtomicallyAndNamesAnUnwritableFile) {
  const WallGrid grid{
      LayeredWall({wallLayer("tungsten", 0.2e-3, 4), wallLayer("aluminium", 3e-3, 6)})};
  WallBoundaries bc;
  bc.hot = FaceCondition::irradiated(constantFlux(1e9), wallMaterial("tungsten"));
  CrankNicolsonWallSolver solver(grid, bc, 300.0);
  WallHistory history(grid);
  solver.run(1e-3, 1e-4, &history);
  const fs::path dir = scratchDirectory("csv");
  const fs::path file = dir / "history.csv";
  writeWallHistoryCsv(file, history);
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 2u + 1u + history.size());  // 2 layer comments, header, rows
  EXPECT_TRUE(contains(lines[0], "# layer 1 tungsten")) << lines[0];
  EXPECT_EQ(lines[2],
            "time_s,hot_face_K,interface_1_K,cold_face_K,max_1_tungsten_K,max_2_aluminium_K");
  EXPECT_EQ(lines[3].substr(0, 2), "0,");
  std::istringstream last(lines.back());
  std::string cell;
  std::getline(last, cell, ',');
  EXPECT_NEAR(std::stod(cell), 1e-3, 1e-12);
  std::getline(last, cell, ',');
  EXPECT_NEAR(std::stod(cell), history.hotFace().back(), 1e-6 * history.hotFace().back());
  int entries = 0;
  for (const auto& e : fs::directory_iterator(dir)) entries += e.is_regular_file();
  EXPECT_EQ(entries, 1);  // no temporary left behind
  const std::string m = errorOf([&] { writeWallHistoryCsv(dir / "missing" / "h.csv", history); });
  EXPECT_TRUE(contains(m, "missing/h.csv")) << m;
  fs::remove_all(dir);
}

// ---------------------------------------------------------------------------------------------
// Flux histories and the radiative balance

TEST(FluxHistory, CsvPerPatchInterpolatesAndRejectsBadLinesByNumber) {
  const fs::path dir = scratchDirectory("flux");
  const fs::path good = dir / "flux.csv";
  std::ofstream(good) << "# approach history\ntime_s, side0, side1\n0, 0, 10\n1e-3, 1e6, 20\n\n"
                         "2e-3, 3e6, 30\n";
  const std::vector<FluxSeries> series = readFluxSeriesCsv(good);
  ASSERT_EQ(series.size(), 2u);
  EXPECT_DOUBLE_EQ(series[0](0.5e-3), 0.5e6);
  EXPECT_DOUBLE_EQ(series[0](1.5e-3), 2e6);
  EXPECT_DOUBLE_EQ(series[0](-1.0), 0.0);  // held at the ends
  EXPECT_DOUBLE_EQ(series[1](5.0), 30.0);
  const SurfaceFlux along = patchFlux(series, {0.0, 0.5, 1.0});
  EXPECT_DOUBLE_EQ(along(1e-3, 0.2), 1e6);
  EXPECT_DOUBLE_EQ(along(1e-3, 0.7), 20.0);
  EXPECT_DOUBLE_EQ(along(1e-3, 1.0), 20.0);  // the last patch includes its end
  EXPECT_DOUBLE_EQ(uniformFlux(series[0])(2e-3, 123.0), 3e6);

  auto errorFor = [&](const std::string& text) {
    const fs::path bad = dir / "bad.csv";
    std::ofstream(bad) << text;
    return errorOf([&] { readFluxSeriesCsv(bad); });
  };
  std::string m = errorFor("t,q\n0,1\n1e-3\n");
  EXPECT_TRUE(contains(m, "bad.csv:3:") && contains(m, "expected 2 values")) << m;
  m = errorFor("t,q\n0,1\n1e-3,abc\n");
  EXPECT_TRUE(contains(m, "bad.csv:3:") && contains(m, "'abc' is not a finite number")) << m;
  m = errorFor("t,q\n0,1\n0,2\n");
  EXPECT_TRUE(contains(m, "bad.csv:3:") && contains(m, "does not increase")) << m;
  m = errorFor("t,q\n");
  EXPECT_TRUE(contains(m, "no data rows")) << m;
  m = errorOf([&] { readFluxSeriesCsv(dir / "absent.csv"); });
  EXPECT_TRUE(contains(m, "absent.csv")) << m;
  fs::remove_all(dir);
}

TEST(RadiativeBalance, EquilibriumTemperatureBalancesAbsorbedAndEmittedFlux) {
  // Eq. 4.8: alpha q = eps sigma T^4.
  const double q = 9.7e7, alpha = kSeedAluminiumAbsorptivity, eps = kSeedAluminiumEmissivity;
  const double t = equilibriumTemperature(q, alpha, eps);
  EXPECT_NEAR(netAbsorbedFlux(q, alpha, eps, t), 0.0, 1e-9 * alpha * q);
  EXPECT_NEAR(incidentFluxForTemperature(t, alpha, eps), q, 1e-9 * q);
  // A face at the seed's side-0 temperature (Table 4.2, 9100.2 K) with its optics needs
  // eps sigma T^4 / alpha = 9.7e7 W/m^2 incident.
  EXPECT_NEAR(incidentFluxForTemperature(9100.2, alpha, eps), 9.73e7, 0.01e7);
  // Radiating to a sink at T_s: alpha q + eps sigma T_s^4 = eps sigma T^4.
  EXPECT_NEAR(equilibriumTemperature(0.0, 0.5, 0.5, 300.0), 300.0, 1e-9);
  EXPECT_NEAR(radiativeConductance(0.5, 1000.0), 2.0 * kStefanBoltzmann * 1e9, 1e-6);
  const auto many = equilibriumTemperatures({0.0, q}, alpha, eps);
  EXPECT_EQ(many[0], 0.0);
  EXPECT_DOUBLE_EQ(many[1], t);
  EXPECT_THROW(equilibriumTemperature(-1.0, alpha, eps), std::invalid_argument);
  EXPECT_THROW(equilibriumTemperature(q, alpha, 0.0), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------
// Shield sizing on a synthetic history: a constant absorbed flux for 1 ms (fixed optics,
// alpha = 1, eps = 0) on 2 mm of aluminium. Bare, the surface would rise by
// (2q/k) sqrt(alpha t/pi) = 1.48e-6 q K: q >= 4.3e8 W/m^2 melts it.

ShieldSizingProblem syntheticProblem(double q) {
  ShieldSizingProblem p;
  p.structure = wallLayer("aluminium", 2e-3, 16);
  p.hotFace = FaceCondition::irradiated(constantFlux(q), 1.0, 0.0);
  p.useCoatingOptics = false;
  p.duration = 1e-3;
  p.timeStep = 1e-6;
  p.patchArea = 13.0;
  p.maxThickness = 3e-3;
  return p;
}

TEST(ShieldSizing, FindsTheThinnestSafeCoatingAndMoreFluxNeedsMore) {
  const WallMaterial w = wallMaterial("tungsten");
  const ShieldSizingProblem low = syntheticProblem(6e8), high = syntheticProblem(8e8);
  const ShieldSizing a = sizeCoating(low, w), b = sizeCoating(high, w);
  std::printf(
      "  tungsten on 2 mm Al, 1 ms: %.4f mm (%.1f kg on 13 m^2, %d runs) at 6e8 W/m^2, "
      "%.4f mm at 8e8 W/m^2\n",
      a.thickness * 1e3, a.addedMass, a.runs, b.thickness * 1e3);
  ASSERT_TRUE(a.feasible);
  ASSERT_TRUE(b.feasible);
  EXPECT_GT(a.thickness, 0.0);
  EXPECT_GT(b.thickness, 1.1 * a.thickness);  // monotonic in the flux
  EXPECT_NEAR(a.addedMass, w.density * a.thickness * 13.0, 1e-9);
  EXPECT_DOUBLE_EQ(a.limit, 933.47);
  // The result keeps the structure below its limit; 10% thinner does not.
  const CoatingTrial atResult = evaluateCoating(low, w, a.thickness);
  const CoatingTrial thinner = evaluateCoating(low, w, 0.9 * a.thickness);
  EXPECT_TRUE(atResult.withinLimit);
  EXPECT_LT(atResult.structurePeak, 933.47);
  EXPECT_FALSE(thinner.withinLimit);
  EXPECT_GT(thinner.structurePeak, 933.47);
  EXPECT_DOUBLE_EQ(atResult.structurePeak, a.structurePeak);
  // Two end runs, then halvings from [0, 3 mm] down to 1e-3 of 0.1 mm: log2(3e4) = 15.
  EXPECT_LE(a.runs, 17);
}

TEST(ShieldSizing, ReportsBareSuccessInfeasibleCandidatesAndMarginLimits) {
  // A weak flux: the bare structure survives.
  const ShieldSizing bare = sizeCoating(syntheticProblem(1e8), wallMaterial("tungsten"));
  EXPECT_TRUE(bare.feasible);
  EXPECT_EQ(bare.thickness, 0.0);
  EXPECT_EQ(bare.addedMass, 0.0);
  // Too thin a maximum: not feasible, and the note says how hot the structure got.
  ShieldSizingProblem p = syntheticProblem(6e8);
  p.maxThickness = 10e-6;
  const ShieldSizing thin = sizeCoating(p, wallMaterial("tungsten"));
  EXPECT_FALSE(thin.feasible);
  EXPECT_TRUE(contains(thin.note, "above its limit")) << thin.note;
  // Several candidates at once (OpenMP over candidates) give each one's own result.
  p.maxThickness = 3e-3;
  const std::vector<WallMaterial> candidates = {wallMaterial("tungsten"), wallMaterial("graphite"),
                                                wallMaterial("tantalum")};
  const std::vector<ShieldSizing> r = sizeShield(p, candidates);
  ASSERT_EQ(r.size(), 3u);
  for (std::size_t k = 0; k < r.size(); ++k) {
    EXPECT_EQ(r[k].material, candidates[k].name);
    EXPECT_TRUE(r[k].feasible) << r[k].material;
    EXPECT_EQ(r[k].thickness, sizeCoating(p, candidates[k]).thickness) << r[k].material;
    std::printf("  %-10s %.4f mm, %.2f kg on 13 m^2, structure peak %.1f K, coating peak %.1f K\n",
                r[k].material.c_str(), r[k].thickness * 1e3, r[k].addedMass, r[k].structurePeak,
                r[k].coatingPeak);
  }
  // Graphite (k = 5.7 across its planes) holds the heat near its surface: the thinnest layer,
  // but its surface passes its sublimation point (4098 K), which the result flags; tungsten's
  // stays solid.
  EXPECT_LT(r[1].thickness, r[0].thickness);
  EXPECT_TRUE(r[1].coatingMelts);
  EXPECT_TRUE(contains(r[1].note, "ablate")) << r[1].note;
  EXPECT_FALSE(r[0].coatingMelts);
  // A 100 K margin below melting needs a thicker coating than the melting point itself.
  ShieldSizingProblem margin = syntheticProblem(6e8);
  margin.limit = {ShieldLimit::Kind::MarginBelowMelting, 100.0};
  const ShieldSizing m = sizeCoating(margin, wallMaterial("tungsten"));
  EXPECT_DOUBLE_EQ(m.limit, 833.47);
  EXPECT_GT(m.thickness, sizeCoating(syntheticProblem(6e8), wallMaterial("tungsten")).thickness);
  // Bad problems name the field.
  ShieldSizingProblem bad = syntheticProblem(6e8);
  bad.duration = 0.0;
  EXPECT_TRUE(contains(errorOf([&] { sizeCoating(bad, wallMaterial("tungsten")); }), "duration"));
}

TEST(ShieldSizing, ExplicitAndCrankNicolsonAgree) {
  ShieldSizingProblem p = syntheticProblem(6e8);
  p.tolerance = 1e-2;
  const ShieldSizing cn = sizeCoating(p, wallMaterial("tantalum"));
  p.scheme = WallScheme::Explicit;
  const ShieldSizing ex = sizeCoating(p, wallMaterial("tantalum"));
  ASSERT_TRUE(cn.feasible && ex.feasible);
  EXPECT_NEAR(ex.thickness / cn.thickness, 1.0, 0.03);
}

}  // namespace
}  // namespace ejecta::radiation
