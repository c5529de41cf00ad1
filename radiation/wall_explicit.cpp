#include "radiation/wall_explicit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "radiation/format_number.hpp"

namespace ejecta::radiation {

namespace {

// Relative slack on the stability limit: a step at exactly K = 1/2 computed in floating point
// may land an ulp above the limit and must not be refused or split.
constexpr double kSlack = 1e-12;

}  // namespace

ExplicitWallSolver::ExplicitWallSolver(WallGrid grid, WallBoundaries boundaries,
                                       double initialTemperature, ExplicitOptions options)
    : ExplicitWallSolver(grid, std::move(boundaries),
                         std::vector<double>(grid.size(), initialTemperature), options) {}

ExplicitWallSolver::ExplicitWallSolver(WallGrid grid, WallBoundaries boundaries,
                                       std::vector<double> initialField, ExplicitOptions options)
    : grid_(std::move(grid)),
      boundaries_(std::move(boundaries)),
      options_(options),
      temperature_(std::move(initialField)) {
  validateBoundaries(boundaries_);
  if (temperature_.size() != grid_.size())
    throw std::invalid_argument("explicit wall solver: initial field has " +
                                std::to_string(temperature_.size()) + " values, the grid " +
                                std::to_string(grid_.size()));
  for (const double t : temperature_)
    if (!std::isfinite(t))
      throw std::invalid_argument("explicit wall solver: initial field is not finite");
  fixed_ = fixedTemperatures(grid_, boundaries_);
  faceNodes_ = fluxFaceNodes(grid_, boundaries_, fixed_);
  rate_.assign(grid_.size(), 0.0);
  inverseCapacity_.assign(grid_.size(), 0.0);
  const auto& c = grid_.wall().capacity();
  for (int j = 0; j < grid_.ny(); ++j)
    for (int i = 0; i < grid_.nx(); ++i) {
      const std::size_t n = grid_.index(i, j);
      if (fixed_[n] >= 0.0) temperature_[n] = fixed_[n];
      else inverseCapacity_[n] = 1.0 / (c[static_cast<std::size_t>(i)] * grid_.faceWidth(j));
    }
  // Sum G / C of a node depends on i only: an end column has half the width and one along-face
  // neighbour, which gives the same along-face rate 2 k h / (C dy^2) as an inner column.
  const auto& g = grid_.wall().conductance();
  const auto& kh = grid_.wall().inPlaneConductance();
  const int nx = grid_.nx();
  conductionRate_.assign(static_cast<std::size_t>(nx), 0.0);
  for (int i = 0; i < nx; ++i) {
    const auto u = static_cast<std::size_t>(i);
    double sum = (i > 0 ? g[u - 1] : 0.0) + (i < nx - 1 ? g[u] : 0.0);
    if (grid_.is2D()) sum += 2.0 * kh[u] / (grid_.faceSpacing() * grid_.faceSpacing());
    conductionRate_[u] = sum / c[u];
  }
}

double ExplicitWallSolver::maximumRate(std::size_t* where) const {
  double best = 0.0;
  std::size_t at = 0;
  // Conduction: the worst free node of every row across the thickness.
  for (int i = 0; i < grid_.nx(); ++i)
    for (int j = 0; j < grid_.ny(); ++j) {
      const std::size_t n = grid_.index(i, j);
      if (fixed_[n] >= 0.0) continue;
      if (conductionRate_[static_cast<std::size_t>(i)] > best) {
        best = conductionRate_[static_cast<std::size_t>(i)];
        at = n;
      }
      break;  // every free node of row i has the same conduction rate
    }
  // Radiating face nodes add 4 eps sigma T^3 / c at their current temperature.
  for (const FluxFaceNode& f : faceNodes_) {
    if (f.face->emissivity == 0.0) continue;
    const double t = temperature_[f.node];
    const double r =
        (inverseCapacity_[f.node] * f.width) * radiativeConductance(f.face->emissivity, t) +
        conductionRate_[f.node % static_cast<std::size_t>(grid_.nx())];
    if (r > best) {
      best = r;
      at = f.node;
    }
  }
  if (where) *where = at;
  return best;
}

double ExplicitWallSolver::stableTimeStep() const {
  const double r = maximumRate(nullptr);
  return r > 0.0 ? 1.0 / r : std::numeric_limits<double>::infinity();
}

void ExplicitWallSolver::stepUnguarded(double dt) {
  grid_.conduction(temperature_, rate_);
  double faceRate = 0.0;
  for (const FluxFaceNode& f : faceNodes_) {
    const double q = absorbedFlux(f, time_) + emittedFlux(f, temperature_[f.node]);
    rate_[f.node] += q;
    faceRate += q;
  }
  const std::size_t n = temperature_.size();
  double* t = temperature_.data();
  const double* r = rate_.data();
  const double* inv = inverseCapacity_.data();
#pragma omp parallel for simd schedule(static) if (n > 40000)
  for (std::size_t k = 0; k < n; ++k) t[k] += dt * r[k] * inv[k];  // fixed nodes: inv = 0
  faceEnergy_ += dt * faceRate;
  time_ += dt;
  ++steps_;
}

void ExplicitWallSolver::advance(double dt) {
  if (!(dt > 0.0 && std::isfinite(dt)))
    throw std::invalid_argument("explicit wall solver: step must be positive and finite");
  if (options_.stability == StabilityPolicy::Refuse) {
    std::size_t at = 0;
    const double rate = maximumRate(&at);
    if (dt * rate > 1.0 + kSlack) {
      const int nx = grid_.nx();
      const int i = static_cast<int>(at % static_cast<std::size_t>(nx));
      const int j = static_cast<int>(at / static_cast<std::size_t>(nx));
      const std::size_t layer = grid_.wall().layerOfNode(i);
      const bool radiative = (i == 0 || i == nx - 1) &&
                             rate > conductionRate_[static_cast<std::size_t>(i)] * (1 + kSlack);
      std::string where = "node i = " + std::to_string(i);
      if (grid_.is2D()) where += ", j = " + std::to_string(j);
      where += " (x = " + formatNumber("%.4g", grid_.wall().position()[static_cast<std::size_t>(i)]) +
               " m, layer " + std::to_string(layer + 1) + " '" +
               grid_.wall().layers()[layer].material.name + "')";
      throw ExplicitStabilityError(
          "explicit wall solver: step " + formatNumber("%.6g", dt) + " s exceeds the stability limit " +
          formatNumber("%.6g", 1.0 / rate) + " s: K = alpha dt/dx^2" +
          (grid_.is2D() ? std::string(" summed over x and y") : std::string()) +
          (radiative ? " with the radiative term" : "") + " = " + formatNumber("%.4g", 0.5 * dt * rate) +
          " > 1/2 at " + where +
          "; take smaller steps, StabilityPolicy::Substep, or the Crank-Nicolson solver");
    }
    stepUnguarded(dt);
    checkFinite();
    return;
  }
  // Substep: equal sub-steps under the limit, re-checked before each one because a radiating
  // face's limit falls as it heats.
  double remaining = dt;
  while (remaining > 0.0) {
    const double limit = stableTimeStep();
    const auto pieces =
        std::max<long>(1, static_cast<long>(std::ceil(remaining / limit * (1.0 - kSlack))));
    const double h = remaining / static_cast<double>(pieces);
    long k = 0;
    for (; k < pieces; ++k) {
      if (k > 0 && h > stableTimeStep() * (1.0 + kSlack)) break;
      stepUnguarded(h);
    }
    remaining = k == pieces ? 0.0 : remaining - h * static_cast<double>(k);
  }
  checkFinite();
}

void ExplicitWallSolver::checkFinite() const {
  for (const double t : temperature_)
    if (!std::isfinite(t))
      throw std::runtime_error("explicit wall solver: temperatures are no longer finite at t = " +
                               formatNumber("%.6g", time_) + " s");
}

}  // namespace ejecta::radiation
