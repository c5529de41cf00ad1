#include "radiation/wall_implicit.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>

#include "radiation/format_number.hpp"

namespace ejecta::radiation {

// The matrix of a step over the free nodes,
//   A = diag(C / dt + extra) + theta * L,
// with L the conduction matrix (Sum G on the diagonal, -G between free neighbours; couplings to
// fixed nodes moved to the right-hand side), and the identity on fixed nodes. Symmetric
// positive definite.
class CrankNicolsonWallSolver::LinearSystem {
 public:
  virtual ~LinearSystem() = default;
  virtual void factorize(double inverseDt, double theta, const std::vector<double>& extra) = 0;
  virtual void solve(const std::vector<double>& rhs, std::vector<double>& x) = 0;
  // Refactorising costs about as much as a solve (1D): then every pass refactorises (Newton).
  virtual bool cheap() const = 0;
  double diagonal(std::size_t node) const { return diagonal_[node]; }

 protected:
  std::vector<double> diagonal_;
};

namespace {

using LinearSystem = CrankNicolsonWallSolver::LinearSystem;

// 1D: the Thomas algorithm (no pivoting needed: A is diagonally dominant).
class Tridiagonal final : public LinearSystem {
 public:
  Tridiagonal(const WallGrid& grid, const std::vector<double>& fixed,
              const std::vector<double>& capacity)
      : g_(grid.wall().conductance()), fixed_(fixed), capacity_(capacity) {
    const std::size_t n = capacity_.size();
    diagonal_.assign(n, 0.0);
    lower_.assign(n, 0.0);
    upper_.assign(n, 0.0);
    inverse_.assign(n, 0.0);
    upperFactor_.assign(n, 0.0);
    forward_.assign(n, 0.0);
  }

  void factorize(double inverseDt, double theta, const std::vector<double>& extra) override {
    const std::size_t n = capacity_.size();
    for (std::size_t i = 0; i < n; ++i) {
      if (fixed_[i] >= 0.0) {
        diagonal_[i] = 1.0;
        lower_[i] = upper_[i] = 0.0;
        continue;
      }
      const double gl = i > 0 ? g_[i - 1] : 0.0, gu = i + 1 < n ? g_[i] : 0.0;
      diagonal_[i] = capacity_[i] * inverseDt + theta * (gl + gu) + extra[i];
      lower_[i] = i > 0 && fixed_[i - 1] < 0.0 ? -theta * gl : 0.0;
      upper_[i] = i + 1 < n && fixed_[i + 1] < 0.0 ? -theta * gu : 0.0;
    }
    inverse_[0] = 1.0 / diagonal_[0];
    upperFactor_[0] = upper_[0] * inverse_[0];
    for (std::size_t i = 1; i < n; ++i) {
      inverse_[i] = 1.0 / (diagonal_[i] - lower_[i] * upperFactor_[i - 1]);
      upperFactor_[i] = upper_[i] * inverse_[i];
    }
  }

  void solve(const std::vector<double>& rhs, std::vector<double>& x) override {
    const std::size_t n = capacity_.size();
    forward_[0] = rhs[0] * inverse_[0];
    for (std::size_t i = 1; i < n; ++i)
      forward_[i] = (rhs[i] - lower_[i] * forward_[i - 1]) * inverse_[i];
    x[n - 1] = forward_[n - 1];
    for (std::size_t i = n - 1; i-- > 0;) x[i] = forward_[i] - upperFactor_[i] * x[i + 1];
  }

  bool cheap() const override { return true; }

 private:
  const std::vector<double>& g_;
  const std::vector<double>& fixed_;
  const std::vector<double>& capacity_;
  std::vector<double> lower_, upper_, inverse_, upperFactor_, forward_;
};

// 2D: sparse LDL^T with a fill-reducing (AMD) ordering analysed once.
class SparseLdlt final : public LinearSystem {
 public:
  SparseLdlt(const WallGrid& grid, const std::vector<double>& fixed,
             const std::vector<double>& capacity)
      : fixed_(fixed), capacity_(capacity) {
    const auto n = static_cast<Eigen::Index>(capacity.size());
    std::vector<Eigen::Triplet<double>> entries;
    std::vector<double> diagonalOfL(capacity.size(), 0.0);
    auto edge = [&](std::size_t a, std::size_t b, double conductance) {
      const bool freeA = fixed[a] < 0.0, freeB = fixed[b] < 0.0;
      if (freeA) diagonalOfL[a] += conductance;
      if (freeB) diagonalOfL[b] += conductance;
      if (freeA && freeB) {
        entries.emplace_back(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b),
                             -conductance);
        entries.emplace_back(static_cast<Eigen::Index>(b), static_cast<Eigen::Index>(a),
                             -conductance);
      }
    };
    const auto& g = grid.wall().conductance();
    const auto& kh = grid.wall().inPlaneConductance();
    for (int j = 0; j < grid.ny(); ++j)
      for (int i = 0; i < grid.nx(); ++i) {
        const auto u = static_cast<std::size_t>(i);
        if (i + 1 < grid.nx())
          edge(grid.index(i, j), grid.index(i + 1, j), grid.faceWidth(j) * g[u]);
        if (j + 1 < grid.ny())
          edge(grid.index(i, j), grid.index(i, j + 1), kh[u] / grid.faceSpacing());
      }
    for (Eigen::Index k = 0; k < n; ++k)
      entries.emplace_back(k, k, diagonalOfL[static_cast<std::size_t>(k)]);
    conduction_.resize(n, n);
    conduction_.setFromTriplets(entries.begin(), entries.end());
    conduction_.makeCompressed();
    matrix_ = conduction_;
    diagonalPosition_.assign(capacity.size(), 0);
    for (Eigen::Index col = 0; col < n; ++col)
      for (Eigen::Index p = conduction_.outerIndexPtr()[col];
           p < conduction_.outerIndexPtr()[col + 1]; ++p)
        if (conduction_.innerIndexPtr()[p] == col)
          diagonalPosition_[static_cast<std::size_t>(col)] = p;
    ldlt_.analyzePattern(matrix_);
    diagonal_.assign(capacity.size(), 0.0);
  }

  void factorize(double inverseDt, double theta, const std::vector<double>& extra) override {
    double* a = matrix_.valuePtr();
    const double* l = conduction_.valuePtr();
    const Eigen::Index nonZeros = conduction_.nonZeros();
    for (Eigen::Index p = 0; p < nonZeros; ++p) a[p] = theta * l[p];
    for (std::size_t k = 0; k < capacity_.size(); ++k) {
      double& d = a[diagonalPosition_[k]];
      d = fixed_[k] >= 0.0 ? 1.0 : d + capacity_[k] * inverseDt + extra[k];
      diagonal_[k] = d;
    }
    ldlt_.factorize(matrix_);
    if (ldlt_.info() != Eigen::Success)
      throw std::runtime_error("Crank-Nicolson wall solver: sparse factorisation failed");
  }

  void solve(const std::vector<double>& rhs, std::vector<double>& x) override {
    const auto n = static_cast<Eigen::Index>(rhs.size());
    Eigen::Map<Eigen::VectorXd>(x.data(), n) =
        ldlt_.solve(Eigen::Map<const Eigen::VectorXd>(rhs.data(), n));
  }

  bool cheap() const override { return false; }

 private:
  const std::vector<double>& fixed_;
  const std::vector<double>& capacity_;
  Eigen::SparseMatrix<double> conduction_, matrix_;
  std::vector<Eigen::Index> diagonalPosition_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt_;
};

}  // namespace

CrankNicolsonWallSolver::CrankNicolsonWallSolver(WallGrid grid, WallBoundaries boundaries,
                                                 double initialTemperature,
                                                 CrankNicolsonOptions options)
    : CrankNicolsonWallSolver(grid, std::move(boundaries),
                              std::vector<double>(grid.size(), initialTemperature), options) {}

CrankNicolsonWallSolver::CrankNicolsonWallSolver(WallGrid grid, WallBoundaries boundaries,
                                                 std::vector<double> initialField,
                                                 CrankNicolsonOptions options)
    : grid_(std::move(grid)),
      boundaries_(std::move(boundaries)),
      options_(options),
      temperature_(std::move(initialField)) {
  validateBoundaries(boundaries_);
  if (options_.startupSteps < 0 || options_.maxIterations < 1 || !(options_.tolerance > 0.0) ||
      !(options_.refactorFraction > 0.0 && options_.refactorFraction < 1.0))
    throw std::invalid_argument("Crank-Nicolson wall solver: options need startupSteps >= 0, "
                                "maxIterations >= 1, tolerance > 0, 0 < refactorFraction < 1");
  const std::size_t n = grid_.size();
  if (temperature_.size() != n)
    throw std::invalid_argument("Crank-Nicolson wall solver: initial field has " +
                                std::to_string(temperature_.size()) + " values, the grid " +
                                std::to_string(n));
  for (const double t : temperature_)
    if (!std::isfinite(t))
      throw std::invalid_argument("Crank-Nicolson wall solver: initial field is not finite");
  fixed_ = fixedTemperatures(grid_, boundaries_);
  faceNodes_ = fluxFaceNodes(grid_, boundaries_, fixed_);
  for (const auto& f : faceNodes_) radiates_ = radiates_ || f.face->emissivity > 0.0;
  capacity_.assign(n, 0.0);
  std::vector<double> fixedOnly(n, 0.0);
  for (int j = 0; j < grid_.ny(); ++j)
    for (int i = 0; i < grid_.nx(); ++i) {
      const std::size_t k = grid_.index(i, j);
      capacity_[k] = grid_.wall().capacity()[static_cast<std::size_t>(i)] * grid_.faceWidth(j);
      if (fixed_[k] >= 0.0) temperature_[k] = fixedOnly[k] = fixed_[k];
    }
  // Conduction of the fixed temperatures alone: at a free node, Sum over fixed neighbours of
  // G T_fixed, the coupling that moves to the right-hand side.
  fromFixed_.assign(n, 0.0);
  grid_.conduction(fixedOnly, fromFixed_);
  previous_ = iterate_ = rate_ = base_ = rhs_ = extraDiagonal_ = std::vector<double>(n, 0.0);
  faceH_ = absorbedNew_ = factoredH_ = std::vector<double>(faceNodes_.size(), 0.0);
  if (grid_.is2D()) system_ = std::make_unique<SparseLdlt>(grid_, fixed_, capacity_);
  else system_ = std::make_unique<Tridiagonal>(grid_, fixed_, capacity_);
}

CrankNicolsonWallSolver::~CrankNicolsonWallSolver() = default;

void CrankNicolsonWallSolver::advance(double dt) {
  if (!(dt > 0.0 && std::isfinite(dt)))
    throw std::invalid_argument("Crank-Nicolson wall solver: step must be positive and finite");
  if (steps_ < options_.startupSteps) {
    step(0.5 * dt, 1.0);
    step(0.5 * dt, 1.0);
  } else {
    step(dt, 0.5);
  }
  ++steps_;
  for (const double t : temperature_)
    if (!std::isfinite(t))
      throw std::runtime_error("Crank-Nicolson wall solver: temperatures are no longer finite "
                               "at t = " + formatNumber("%.6g", time_) + " s");
}

void CrankNicolsonWallSolver::step(double dt, double theta) {
  const std::size_t n = temperature_.size();
  const double newTime = time_ + dt;
  // A step within 1e-12 of the factorised one (a run's steps differ in the last bits) is taken
  // as that step, keeping the factorisation; the difference is far below any truncation error.
  double inverseDt = 1.0 / dt;
  if (std::abs(inverseDt - factoredInverseDt_) <= 1e-12 * inverseDt) {
    inverseDt = factoredInverseDt_;
    dt = 1.0 / inverseDt;
  }
  previous_ = temperature_;

  // The explicit half: (1 - theta) [Cond(T) + F(T, t)].
  double oldFaceFlux = 0.0;
  if (theta < 1.0) {
    grid_.conduction(previous_, rate_);
    for (const FluxFaceNode& f : faceNodes_) {
      const double q = absorbedFlux(f, time_) + emittedFlux(f, previous_[f.node]);
      rate_[f.node] += q;
      oldFaceFlux += q;
    }
  }
  // The part of the right-hand side that the T^4 passes do not change.
  for (std::size_t k = 0; k < n; ++k)
    base_[k] = fixed_[k] >= 0.0 ? fixed_[k]
                               : capacity_[k] * inverseDt * previous_[k] +
                                     (theta < 1.0 ? (1.0 - theta) * rate_[k] : 0.0) +
                                     theta * fromFixed_[k];
  for (std::size_t f = 0; f < faceNodes_.size(); ++f)
    absorbedNew_[f] = absorbedFlux(faceNodes_[f], newTime);

  iterate_ = previous_;
  double newFaceFlux = 0.0;
  bool converged = false;
  const bool factored = factorizations_ > 0;
  bool stepChanged =
      !factored || inverseDt != factoredInverseDt_ || theta != factoredTheta_;
  for (int pass = 0; pass < options_.maxIterations; ++pass) {
    // Linearise T^4 about the latest temperature: its radiative conductance per face node.
    bool misses = false;
    for (std::size_t f = 0; f < faceNodes_.size(); ++f) {
      const FluxFaceNode& node = faceNodes_[f];
      faceH_[f] = node.width * radiativeConductance(node.face->emissivity, iterate_[node.node]);
      if (theta * std::abs(faceH_[f] - factoredH_[f]) >
          options_.refactorFraction * system_->diagonal(node.node))
        misses = true;
    }
    if (stepChanged || (radiates_ && (system_->cheap() || misses))) {
      std::fill(extraDiagonal_.begin(), extraDiagonal_.end(), 0.0);
      for (std::size_t f = 0; f < faceNodes_.size(); ++f)
        extraDiagonal_[faceNodes_[f].node] += theta * faceH_[f];
      system_->factorize(inverseDt, theta, extraDiagonal_);
      factoredH_ = faceH_;
      factoredInverseDt_ = inverseDt;
      factoredTheta_ = theta;
      stepChanged = false;
      ++factorizations_;
    }
    // theta [alpha q(t') - eps sigma Tk^4 + H (Tk - T')]: the H T' part is in the matrix.
    rhs_ = base_;
    for (std::size_t f = 0; f < faceNodes_.size(); ++f) {
      const FluxFaceNode& node = faceNodes_[f];
      const double tk = iterate_[node.node];
      rhs_[node.node] +=
          theta * (absorbedNew_[f] + emittedFlux(node, tk) + factoredH_[f] * tk);
    }
    system_->solve(rhs_, temperature_);
    ++solves_;
    double change = 0.0, scale = 1.0;
    newFaceFlux = 0.0;
    for (std::size_t f = 0; f < faceNodes_.size(); ++f) {
      const FluxFaceNode& node = faceNodes_[f];
      const double tk = iterate_[node.node];
      newFaceFlux += absorbedNew_[f] + emittedFlux(node, tk) +
                     factoredH_[f] * (tk - temperature_[node.node]);
    }
    for (std::size_t k = 0; k < n; ++k) {
      change = std::max(change, std::abs(temperature_[k] - iterate_[k]));
      scale = std::max(scale, std::abs(temperature_[k]));
    }
    iterate_.swap(temperature_);
    temperature_ = iterate_;
    if (!radiates_ || change <= options_.tolerance * scale) {
      converged = true;
      break;
    }
  }
  if (!converged && options_.maxIterations > 1) {
    temperature_ = previous_;  // the failed step leaves the state as it was
    throw std::runtime_error(
        "Crank-Nicolson wall solver: the T^4 face iteration did not converge in " +
        std::to_string(options_.maxIterations) + " passes in the step to t = " +
        formatNumber("%.6g", newTime) + " s; take smaller steps");
  }
  faceEnergy_ += dt * ((1.0 - theta) * oldFaceFlux + theta * newFaceFlux);
  time_ = newTime;
}

}  // namespace ejecta::radiation
