#pragma once
// Converged answers with error bars (`ejecta converge`, issue 23): a scene run at successively
// finer particle spacings, every quantity of interest (any number its summary.json holds)
// collected per level, and for each the observed order, the Richardson-extrapolated value and
// the Grid Convergence Index (sim/verify/grid_convergence.hpp, Celik et al. 2008).
//
// A level multiplies by its factor everything that is a length tied to the resolution: every
// body's spacing (h follows it), every Gaussian energy deposit's width (a source a fixed number
// of spacings wide), and any scene key given with --key (a grid voxel, a gauge's smoothing
// radius). Each level runs into a folder of its own (level_<factor>/); a level whose
// summary.json is already there, completed, is read back, not run again, so a study resumes.
#include <filesystem>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sim/verify/grid_convergence.hpp"

namespace ejecta::coupling {

// What a quantity can physically be (a share 0 to 1, a depth or a volume not negative): a band
// that runs past it is reported and drawn clipped to it. Either side may be infinite.
struct QuantityRange {
  double minimum = -std::numeric_limits<double>::infinity();
  double maximum = std::numeric_limits<double>::infinity();
};

// `ejecta converge --range`'s "QUANTITY=MIN:MAX" (either side may be left empty: no bound).
// Throws std::invalid_argument naming the text and what is wrong with it.
std::pair<std::string, QuantityRange> parseQuantityRange(const std::string& text);

struct ConvergenceOptions {
  std::vector<double> factors{};         // spacing multipliers, e.g. 1, 0.7, 0.5 (any order)
  std::vector<std::string> quantities{}; // summary keys: an extras key, or "energy_relative_error"
  std::vector<std::string> scaledKeys{}; // more scene keys scaled with the spacing
  std::vector<std::string> overrides{};  // --set, every level
  std::filesystem::path outDir{};
  int threads = 0;
  // The method's order for the quantities (1: SPH across shocks; 2: smooth flow): where the
  // levels are not in the asymptotic range the band falls back to it (grid_convergence.hpp).
  double formalOrder = 1.0;
  // By quantity (each one of `quantities`): the range its band is clipped to.
  std::map<std::string, QuantityRange> ranges{};
  // Told of each level as it ends (factor, particles, seconds; read back: seconds < 0).
  std::function<void(double, std::size_t, double)> onLevel{};
};

struct ConvergenceLevel {
  double factor = 0.0;
  double spacing = 0.0;                  // the first body's [m]
  std::size_t particles = 0;
  double wallSeconds = 0.0;              // the run's (as its summary.json says)
  std::map<std::string, double> values;  // by quantity
};

struct QuantityConvergence {
  std::string name;
  verify::GridConvergence convergence;   // invalid with fewer than 3 levels (note says why)
  // The finest value +- the band, clipped to the quantity's range where one is given
  // (bandClipped: the band ran past it); NaN where there is no band.
  double bandLow = std::numeric_limits<double>::quiet_NaN();
  double bandHigh = std::numeric_limits<double>::quiet_NaN();
  bool bandClipped = false;
};

struct ConvergenceResult {
  std::string scene;
  std::vector<ConvergenceLevel> levels;  // coarsest first
  std::vector<QuantityConvergence> quantities;
};

// The --set overrides that make `factor`'s level of the scene (its text and label, with the
// study's overrides): bodies[i].spacing, energy_deposits[j].width of Gaussian deposits, and
// each scaled key (read from the scene text, its unit kept). Throws SceneError naming a scaled
// key that is missing or not a number or quantity.
std::vector<std::string> levelOverrides(const std::string& sceneText, const std::string& label,
                                        const ConvergenceOptions& options, double factor);

// Runs (or reads back) every level and analyses every quantity. Throws std::invalid_argument
// for no factors, a non-positive or repeated factor, or no quantities; std::runtime_error when a
// level fails or its summary lacks a quantity (naming the keys it has).
ConvergenceResult runConvergenceStudy(const std::string& sceneText, const std::string& label,
                                      const ConvergenceOptions& options);

// The same for a verification problem (sim/verify/verification.hpp; `ejecta converge
// verify:NAME`): the problem's own runs at the factors, its metrics (e.g. shock_radius,
// L1_density) as the quantities, each checkable against the problem's exact answer. Throws
// std::invalid_argument for an unknown problem or metric (naming the metrics it has).
ConvergenceResult runVerificationConvergence(const std::string& problem, const ConvergenceOptions& options);

// levels.csv: factor, spacing, particles, wall seconds, one column per quantity.
std::string levelsCsv(const ConvergenceResult& result);
// convergence.csv: per quantity, the finest value, order, extrapolated value, GCI, band, the
// band's basis, and the least-squares fit's order, scatter and band (four or more levels).
std::string convergenceCsv(const ConvergenceResult& result);

}  // namespace ejecta::coupling
