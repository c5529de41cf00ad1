#include "sim/sph/cell_grid.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "sim/parallel/thread_team.hpp"

namespace ejecta {

namespace {

std::string nonFinitePosition(const ParticleSet& p, int d) {
  for (std::size_t i = 0; i < p.size(); ++i)
    if (!std::isfinite(p.x[d][i]))
      return "neighbour search: particle " + std::to_string(i) +
             (i < p.id.size() ? " (id " + std::to_string(p.id[i]) + ")" : std::string()) +
             " has position component " + std::to_string(d) + " = " + std::to_string(p.x[d][i]) +
             " (not finite)";
  return "neighbour search: the particles span an infinite extent along axis " + std::to_string(d);
}

}  // namespace

void CellGrid::build(const ParticleSet& p, int dim, double cellSize) {
  dim_ = dim;
  const std::size_t n = p.size();
  // The bounding box (min and max are exact, so the threads' split does not change it).
  std::array<double, 3> lo{0, 0, 0}, hi{0, 0, 0};
  for (int d = 0; d < dim; ++d) {
    const double* x = p.x[d].data();
    double low = std::numeric_limits<double>::max(), high = std::numeric_limits<double>::lowest();
    bool finite = true;
#pragma omp parallel for schedule(static) if (n >= kThreadTeamFrom) reduction(min : low) reduction(max : high) \
    reduction(&& : finite)
    for (std::size_t i = 0; i < n; ++i) {
      low = std::min(low, x[i]);
      high = std::max(high, x[i]);
      finite = finite && std::isfinite(x[i]);
    }
    lo[d] = n == 0 ? 0.0 : low;
    hi[d] = n == 0 ? 0.0 : high;
    // A NaN or infinite position has no cell (and an infinite extent no cell size that bounds
    // the count): refuse rather than loop.
    if (!finite || !std::isfinite(hi[d] - lo[d])) throw std::runtime_error(nonFinitePosition(p, d));
  }
  if (n > 0 && (!(cellSize >= 0.0) || !std::isfinite(cellSize)))
    throw std::runtime_error("neighbour search: the cell size is " + std::to_string(cellSize) +
                             " (smoothing lengths not finite and positive)");
  // Bound the cell count (a sparse cloud with one small-h cluster must not allocate a huge grid).
  const double maxCells = 4.0 * static_cast<double>(std::max<std::size_t>(n, 64));
  cellSize_ = std::max(cellSize, 1e-300);
  for (;;) {
    double total = 1.0;
    for (int d = 0; d < dim; ++d) total *= std::floor((hi[d] - lo[d]) / cellSize_) + 1.0;
    if (total <= maxCells) break;
    cellSize_ *= 1.5;
  }
  for (int d = 0; d < 3; ++d) {
    origin_[d] = lo[d];
    cells_[d] = d < dim ? static_cast<long>(std::floor((hi[d] - lo[d]) / cellSize_)) + 1 : 1;
  }
  const std::size_t numCells = static_cast<std::size_t>(cells_[0] * cells_[1] * cells_[2]);

  // Counting sort by cell; a stable order within each cell (by particle index). Each thread takes
  // a range of cells and scans every particle for its own (a scan of 4-byte cell numbers is cheap
  // beside the scattered writes), so the order is the serial one whatever the team.
  std::vector<std::uint32_t>& cellOf = cellOf_;
  cellOf.resize(n);
  const int dims = dim;
#pragma omp parallel for schedule(static) if (n >= kThreadTeamFrom)
  for (std::size_t i = 0; i < n; ++i) {
    long c = 0;
    for (int d = dims - 1; d >= 0; --d) c = c * cells_[d] + cellCoord(p.x[d][i], d);
    cellOf[i] = static_cast<std::uint32_t>(c);
  }
  cellStart_.resize(numCells + 1);
  cellStart_[0] = 0;
  sorted_.resize(n);
  fill_.resize(numCells);
  std::vector<std::uint32_t> rangeTotal(static_cast<std::size_t>(omp_get_max_threads()) + 1, 0);
#pragma omp parallel if (n >= kThreadTeamFrom)
  {
    const std::size_t threads = static_cast<std::size_t>(omp_get_num_threads());
    const std::size_t t = static_cast<std::size_t>(omp_get_thread_num());
    const std::size_t first = numCells * t / threads, last = numCells * (t + 1) / threads;
    std::uint32_t* start = cellStart_.data();
    std::fill(start + first + 1, start + last + 1, 0u);
    for (std::size_t i = 0; i < n; ++i)
      if (cellOf[i] - first < last - first) ++start[cellOf[i] + 1];
    std::uint32_t running = 0;  // this range's counts summed, then offset by the ranges before
    for (std::size_t c = first; c < last; ++c) start[c + 1] = running += start[c + 1];
    rangeTotal[t + 1] = running;
#pragma omp barrier
    std::uint32_t offset = 0;
    for (std::size_t r = 1; r <= t; ++r) offset += rangeTotal[r];
    for (std::size_t c = first; c < last; ++c) start[c + 1] += offset;
#pragma omp barrier
    std::uint32_t* next = fill_.data();  // each cell's next free slot
    for (std::size_t c = first; c < last; ++c) next[c] = start[c];
    for (std::size_t i = 0; i < n; ++i)
      if (cellOf[i] - first < last - first) sorted_[next[cellOf[i]]++] = static_cast<std::uint32_t>(i);
  }
  for (int d = 0; d < 3; ++d) {
    sortedPos_[d].resize(n);
    if (d >= dim) { std::fill(sortedPos_[d].begin(), sortedPos_[d].end(), 0.0); continue; }
    double* to = sortedPos_[d].data();
    const double* from = p.x[d].data();
#pragma omp parallel for schedule(static) if (n >= kThreadTeamFrom)
    for (std::size_t k = 0; k < n; ++k) to[k] = from[sorted_[k]];
  }
}

void CellGrid::recordReach(const ParticleSet& p, double support) {
  const std::size_t numCells = cellStart_.size() - 1;
  std::vector<double>& own = ownReach_;  // the widest support of the particles in each cell
  own.resize(numCells);
  sortedSupport_.resize(sorted_.size());
#pragma omp parallel for schedule(static) if (numCells >= kThreadTeamFrom)
  for (std::size_t c = 0; c < numCells; ++c) {
    double widest = 0.0;
    for (std::uint32_t k = cellStart_[c]; k < cellStart_[c + 1]; ++k) {
      sortedSupport_[k] = support * p.h[sorted_[k]];
      widest = std::max(widest, sortedSupport_[k]);
    }
    own[c] = widest;
  }
  // Spread each cell's support over the cells it may reach (a cube of them: conservative). Each
  // thread writes its own slab of rows along the last axis and clips every cube to it: a
  // maximum, so the result does not depend on the split.
  reach_.assign(numCells, 0.0);
  const int slow = dim_ - 1;
#pragma omp parallel if (numCells >= kThreadTeamFrom)
  {
    const long threads = omp_get_num_threads(), t = omp_get_thread_num();
    const long slabBegin = cells_[slow] * t / threads, slabEnd = cells_[slow] * (t + 1) / threads;
    long at[3];
    for (std::size_t c = 0; c < numCells; ++c) {
      if (own[c] == 0.0) continue;
      at[0] = static_cast<long>(c) % cells_[0];
      at[1] = (static_cast<long>(c) / cells_[0]) % cells_[1];
      at[2] = static_cast<long>(c) / (cells_[0] * cells_[1]);
      const long span = static_cast<long>(std::ceil(own[c] / cellSize_));
      long lo[3], hi[3];
      for (int d = 0; d < 3; ++d) {
        lo[d] = d < dim_ ? std::max(at[d] - span, 0L) : 0;
        hi[d] = d < dim_ ? std::min(at[d] + span, cells_[d] - 1) : 0;
      }
      lo[slow] = std::max(lo[slow], slabBegin);
      hi[slow] = std::min(hi[slow], slabEnd - 1);
      for (long z = lo[2]; z <= hi[2]; ++z)
        for (long y = lo[1]; y <= hi[1]; ++y)
          for (long x = lo[0]; x <= hi[0]; ++x) {
            double& r = reach_[static_cast<std::size_t>((z * cells_[1] + y) * cells_[0] + x)];
            r = std::max(r, own[c]);
          }
    }
  }
}

double CellGrid::reachInto(const double* point) const {
  long c = 0;
  for (int d = dim_ - 1; d >= 0; --d) c = c * cells_[d] + cellCoord(point[d], d);
  return reach_[static_cast<std::size_t>(c)];
}

std::vector<std::uint64_t> CellGrid::cellKeys(const ParticleSet& p, std::size_t count) const {
  std::vector<std::uint64_t> keys(count);
  for (std::size_t i = 0; i < count; ++i) {
    std::uint64_t c = 0;
    for (int d = dim_ - 1; d >= 0; --d)
      c = c * static_cast<std::uint64_t>(cells_[d]) +
          static_cast<std::uint64_t>(cellCoord(p.x[d][i], d));
    keys[i] = c;
  }
  return keys;
}

}  // namespace ejecta
