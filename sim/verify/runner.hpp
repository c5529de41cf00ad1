#pragma once
// Internal to the verification problems: running a verification scene and collecting its
// particles and run statistics. The problems themselves are grouped by subject in
// verification.cpp (gas dynamics), strength.cpp (solids), porosity.cpp (porous materials).
#include <functional>
#include <string>
#include <vector>

#include "sim/state/particles.hpp"
#include "sim/setup/scene.hpp"
#include "sim/run/simulation.hpp"
#include "sim/verify/verification.hpp"

namespace ejecta::verify::detail {

struct Finished {
  ParticleSet particles;
  ResolutionRun run;
  double time = 0.0;
};

// The embedded scene scenes/verification/NAME.toml with the options' --set overrides.
Scene problemScene(const std::string& name, const Options& options);

// How a convergence study coarsens a scene: the bodies' spacings alone, or also the widths of
// its Gaussian energy deposits (a source a fixed number of spacings wide at every level).
enum class Coarsen { Bodies, BodiesAndDeposits };

// Runs the scene with every body's spacing (and, with Coarsen::BodiesAndDeposits, every
// Gaussian deposit's width) multiplied by `coarsen`; `observer` (optional) sees the simulation
// after every step.
Finished runAt(Scene scene, double coarsen, const Options& options,
               std::function<void(const Simulation&)> observer = {},
               Coarsen what = Coarsen::Bodies);

// Writes rows as NAME_nPARTICLES.csv under options.outDir (nothing if it is empty).
void writeProfile(const Options& options, const std::string& name, const ResolutionRun& run,
                  const std::string& header, const std::vector<std::vector<double>>& rows);

// The rightmost position where the x-velocity profile first falls below `level`: the front of a
// 1D wave running in +x into material at rest. Throws std::runtime_error if there is none.
double waveFront(const ParticleSet& p, double level);

// A report of one run at the scene's own resolution.
Report singleRunReport(const std::string& name, const Scene& scene, std::string reference,
                       ResolutionRun run);

// The solid-mechanics problems (strength.cpp).
std::vector<Problem> strengthProblems();
// The energy-source problems (sources.cpp).
std::vector<Problem> sourceProblems();
// The porous-material problems (porosity.cpp).
std::vector<Problem> porosityProblems();

// Runs `levels` resolutions, coarsest first: spacing x 2^(levels-1), ..., x 1 (the scene's own),
// calling measure(scene, finished) on each; observed orders for every L1_ metric. `observer`
// (optional) sees every step of every run, before that run's measure.
Report convergenceStudy(const std::string& name, const Options& options, int defaultLevels,
                        const std::function<void(const Scene&, Finished&)>& measure,
                        const std::function<void(const Simulation&)>& observer = {},
                        Coarsen what = Coarsen::Bodies);

}  // namespace ejecta::verify::detail
