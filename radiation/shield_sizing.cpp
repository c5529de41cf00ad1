#include "radiation/shield_sizing.hpp"

#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>
#include <stdexcept>
#include <string>

#include "radiation/format_number.hpp"
#include "radiation/wall_explicit.hpp"
#include "radiation/wall_implicit.hpp"

namespace ejecta::radiation {

namespace {

std::unique_ptr<WallSolver> makeSolver(WallScheme scheme, WallGrid grid, WallBoundaries bc,
                                       double initialTemperature) {
  if (scheme == WallScheme::Explicit)
    return std::make_unique<ExplicitWallSolver>(std::move(grid), std::move(bc),
                                                initialTemperature);
  return std::make_unique<CrankNicolsonWallSolver>(std::move(grid), std::move(bc),
                                                   initialTemperature);
}

}  // namespace

double ShieldLimit::temperatureFor(const WallMaterial& structure) const {
  switch (kind) {
    case Kind::MeltingPoint: return structure.meltingPoint;
    case Kind::MarginBelowMelting: return structure.meltingPoint - value;
    case Kind::Temperature: return value;
  }
  return structure.meltingPoint;
}

void validateSizingProblem(const ShieldSizingProblem& p) {
  auto bad = [](const std::string& what) {
    throw std::invalid_argument("shield sizing: " + what);
  };
  static_cast<void>(LayeredWall({p.structure}));  // throws naming the structure layer
  validateBoundaries({p.hotFace, p.coldFace, {}});
  if (!(p.duration > 0.0 && std::isfinite(p.duration))) bad("duration must be > 0 s");
  if (!(p.timeStep >= 0.0 && std::isfinite(p.timeStep))) bad("timeStep must be >= 0 s");
  if (!(p.initialTemperature >= 0.0 && std::isfinite(p.initialTemperature)))
    bad("initialTemperature must be >= 0 K");
  if (!(p.patchArea >= 0.0 && std::isfinite(p.patchArea))) bad("patchArea must be >= 0 m^2");
  if (!(p.minThickness > 0.0 && p.maxThickness > p.minThickness && std::isfinite(p.maxThickness)))
    bad("need 0 < minThickness < maxThickness");
  if (!(p.tolerance > 0.0 && p.tolerance < 1.0)) bad("tolerance must lie in (0, 1)");
  if (p.coatingCells < 1) bad("coatingCells must be >= 1");
  const double limit = p.limit.temperatureFor(p.structure.material);
  if (!(limit > p.initialTemperature))
    bad("the limit " + formatNumber("%.6g", limit) + " K is not above the initial temperature");
}

CoatingTrial evaluateCoating(const ShieldSizingProblem& p, const WallMaterial& coating,
                             double thickness) {
  std::vector<WallLayer> layers;
  if (thickness > 0.0) layers.push_back({coating, thickness, p.coatingCells});
  layers.push_back(p.structure);
  const WallMaterial& surface = layers.front().material;
  WallBoundaries bc{p.hotFace, p.coldFace, {}};
  if (p.useCoatingOptics) {
    bc.hot.absorptivity = surface.absorptivity;
    bc.hot.emissivity = surface.emissivity;
  }
  WallGrid grid{LayeredWall(std::move(layers))};
  WallHistory history(grid);
  auto solver = makeSolver(p.scheme, grid, std::move(bc), p.initialTemperature);
  const double dt = p.timeStep > 0.0 ? p.timeStep : p.duration / 2000.0;
  solver->run(p.duration, dt, &history);
  const std::size_t structure = grid.wall().layerCount() - 1;
  CoatingTrial trial;
  trial.thickness = thickness;
  trial.structurePeak = history.peakTemperature(structure);
  trial.coatingPeak = thickness > 0.0 ? history.peakTemperature(0) : 0.0;
  trial.structureMeltTime = history.meltTime(structure);
  trial.withinLimit = trial.structurePeak < p.limit.temperatureFor(p.structure.material);
  return trial;
}

ShieldSizing sizeCoating(const ShieldSizingProblem& p, const WallMaterial& coating) {
  validateSizingProblem(p);
  validateWallMaterial(coating);
  ShieldSizing result;
  result.material = coating.name;
  result.limit = p.limit.temperatureFor(p.structure.material);
  auto finish = [&](const CoatingTrial& t) {
    result.thickness = t.thickness;
    result.addedMass = coating.density * t.thickness * p.patchArea;
    result.structurePeak = t.structurePeak;
    result.coatingPeak = t.coatingPeak;
    result.coatingMelts = t.thickness > 0.0 && t.coatingPeak >= coating.meltingPoint;
    if (result.coatingMelts)
      result.note = "the coating reaches its melting point (" +
                    formatNumber("%.1f", coating.meltingPoint) +
                    " K): it would ablate, which the model does not represent";
  };
  const CoatingTrial bare = evaluateCoating(p, coating, 0.0);
  ++result.runs;
  if (bare.withinLimit) {
    result.feasible = true;
    finish(bare);
    result.note = "the bare structure stays below the limit";
    return result;
  }
  CoatingTrial safe = evaluateCoating(p, coating, p.maxThickness);
  ++result.runs;
  if (!safe.withinLimit) {
    finish(safe);
    result.feasible = false;
    result.note = "even " + formatNumber("%.4g", p.maxThickness * 1e3) + " mm leaves the structure at " +
                  formatNumber("%.1f", safe.structurePeak) + " K, above its limit " +
                  formatNumber("%.1f", result.limit) + " K";
    return result;
  }
  // Bisection between a failing thickness (lo; 0 = bare) and a safe one.
  double lo = 0.0;
  while (safe.thickness - lo > p.tolerance * safe.thickness &&
         safe.thickness > p.minThickness) {
    const double mid = 0.5 * (lo + safe.thickness);
    const CoatingTrial trial = evaluateCoating(p, coating, mid);
    ++result.runs;
    if (trial.withinLimit) safe = trial;
    else lo = mid;
  }
  result.feasible = true;
  finish(safe);
  if (safe.thickness <= p.minThickness)
    result.note = "any coating thicker than " + formatNumber("%.3g", p.minThickness * 1e6) +
                  " um works: its optical properties alone protect the structure";
  return result;
}

std::vector<ShieldSizing> sizeShield(const ShieldSizingProblem& p,
                                     const std::vector<WallMaterial>& candidates) {
  validateSizingProblem(p);
  std::vector<ShieldSizing> results(candidates.size());
  std::vector<std::exception_ptr> errors(candidates.size());
  const auto count = static_cast<long>(candidates.size());
#pragma omp parallel for schedule(dynamic)
  for (long c = 0; c < count; ++c) {
    const auto k = static_cast<std::size_t>(c);
    try {
      results[k] = sizeCoating(p, candidates[k]);
    } catch (...) {
      errors[k] = std::current_exception();
    }
  }
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);
  return results;
}

}  // namespace ejecta::radiation
