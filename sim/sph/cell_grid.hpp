#pragma once
// CellGrid: a uniform grid of cells over the particles' bounding box, with the particles binned
// by a counting sort (cell-linked list in compressed form). Rebuilt every step; queries return
// every particle within a radius of a point, visiting cells in a fixed order so results are
// deterministic.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "sim/state/particles.hpp"

namespace ejecta {

class CellGrid {
 public:
  // Bins particles [0, p.size()) in `dim` dimensions with cells of edge `cellSize` (enlarged if
  // needed to keep the number of cells at most a few times the number of particles).
  void build(const ParticleSet& p, int dim, double cellSize);

  // Appends the indices of all particles j with |x_j - point|^2 < radius^2 to `out`.
  template <int D>
  void query(const ParticleSet& p, const double* point, double radius,
             std::vector<std::uint32_t>& out) const;

  // For finding the pairs of a few particles without every particle's gather list (individual
  // time steps): notes for every cell the widest support `support` x h_j of any particle j whose
  // support may reach into it. A particle j can reach a point only if reachInto(point) >=
  // support h_j, so a query of that radius finds every such j. Call after h is final.
  void recordReach(const ParticleSet& p, double support);
  double reachInto(const double* point) const;
  // Appends every particle j within `radius` of `point` whose cell's widest support could reach
  // it: a query of radius reachInto(point) that skips the cells whose own particles' supports
  // stop short of the point (the wide kernels of a hot centre are visited only where they reach).
  // After recordReach; the caller tests r < support h_j itself. With `beyond` > 0 only the
  // particles at or past that distance whose cell's widest support exceeds it are wanted (the
  // partners a particle of support `beyond` does not reach itself): cells whose own supports
  // stop at `beyond`, cells wholly within it, and particles whose own support (as recordReach
  // recorded it: h must not change in between) stops there, are skipped.
  template <int D>
  void queryReaching(const double* point, double radius, std::vector<std::uint32_t>& out,
                     double beyond = 0.0) const;

  // Cell index of each real particle under this grid; used to reorder particles for locality.
  std::vector<std::uint64_t> cellKeys(const ParticleSet& p, std::size_t count) const;

  double cellSize() const { return cellSize_; }

 private:
  int dim_ = 3;
  double cellSize_ = 1.0;
  std::array<double, 3> origin_{};
  std::array<long, 3> cells_{1, 1, 1};
  std::vector<std::uint32_t> cellStart_;  // size numCells + 1
  std::vector<std::uint32_t> sorted_;     // particle indices ordered by cell
  std::vector<double> sortedPos_[3];      // positions in cell order, for cache-friendly queries
  std::vector<double> reach_;             // per cell: recordReach's widest support reaching it
  std::vector<double> ownReach_;          // per cell: the widest support of its own particles
  std::vector<double> sortedSupport_;     // recordReach's support of each particle, in cell order
  std::vector<std::uint32_t> cellOf_;     // build's scratch: each particle's cell
  std::vector<std::uint32_t> fill_;       // build's scratch: each cell's next free slot

  long cellCoord(double x, int d) const;
  // queryReaching's per-axis part of a cell's nearest and farthest squared distance from x.
  void axisBounds(int d, long at, double x, double& gap2, double& far2, bool& open) const;
};

inline long CellGrid::cellCoord(double x, int d) const {
  // floor((x - origin) / cell), clamped to the grid, without floor's library call: a quotient
  // below 1 (or NaN) is cell 0, and past it truncation is floor. Inline: the grid bins every
  // particle, and each query its bounds, at every sub-step of individual steps.
  const double q = (x - origin_[d]) / cellSize_;
  if (!(q >= 1.0)) return 0;
  const long last = cells_[d] - 1;
  return q >= static_cast<double>(last) ? last : static_cast<long>(q);
}

template <int D>
void CellGrid::query(const ParticleSet&, const double* point, double radius,
                     std::vector<std::uint32_t>& out) const {
  long lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  for (int d = 0; d < D; ++d) {
    lo[d] = cellCoord(point[d] - radius, d);
    hi[d] = cellCoord(point[d] + radius, d);
  }
  const double r2 = radius * radius;
  // The columns in locals: `out` could alias the members for all the compiler knows, which
  // would reload them at every particle.
  const double* pos[3] = {sortedPos_[0].data(), sortedPos_[D > 1 ? 1 : 0].data(),
                          sortedPos_[D > 2 ? 2 : 0].data()};
  const std::uint32_t* index = sorted_.data();
  for (long cz = lo[2]; cz <= hi[2]; ++cz) {
    for (long cy = lo[1]; cy <= hi[1]; ++cy) {
      const long rowBase = (cz * cells_[1] + cy) * cells_[0];
      const std::uint32_t begin = cellStart_[rowBase + lo[0]];
      const std::uint32_t end = cellStart_[rowBase + hi[0] + 1];
      // A row of cells is contiguous in the sorted order: one sweep, without branches (whether a
      // particle is within is as good as random to the branch predictor).
      std::size_t n = out.size();
      out.resize(n + (end - begin));
      std::uint32_t* to = out.data();
      for (std::uint32_t k = begin; k < end; ++k) {
        double d2 = 0.0;
        for (int d = 0; d < D; ++d) {
          const double dx = pos[d][k] - point[d];
          d2 += dx * dx;
        }
        to[n] = index[k];
        n += d2 < r2;
      }
      out.resize(n);
    }
  }
}

template <int D>
void CellGrid::queryReaching(const double* point, double radius, std::vector<std::uint32_t>& out,
                             double beyond) const {
  long lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  for (int d = 0; d < D; ++d) {
    lo[d] = cellCoord(point[d] - radius, d);
    hi[d] = cellCoord(point[d] + radius, d);
  }
  const double r2 = radius * radius;
  // Each axis's part of the distance from the point to a cell depends on that axis's coordinate
  // alone: the outer axes' parts are taken once per slab and row, and summed per cell in the
  // order of the axes (the same sums, to the bit, as taking all three per cell).
  double gap2[3] = {0.0, 0.0, 0.0}, far2[3] = {0.0, 0.0, 0.0};
  bool open[3] = {false, false, false};
  const double* pos[3] = {sortedPos_[0].data(), sortedPos_[D > 1 ? 1 : 0].data(),
                          sortedPos_[D > 2 ? 2 : 0].data()};  // in locals, as query's
  const std::uint32_t* index = sorted_.data();
  const double* support = sortedSupport_.data();
  for (long cz = lo[2]; cz <= hi[2]; ++cz) {
    if (D > 2) axisBounds(2, cz, point[2], gap2[2], far2[2], open[2]);
    for (long cy = lo[1]; cy <= hi[1]; ++cy) {
      if (D > 1) axisBounds(1, cy, point[1], gap2[1], far2[1], open[1]);
      for (long cx = lo[0]; cx <= hi[0]; ++cx) {
        const std::size_t c = static_cast<std::size_t>((cz * cells_[1] + cy) * cells_[0] + cx);
        const double own = ownReach_[c];
        if (own == 0.0 || own <= beyond) continue;
        axisBounds(0, cx, point[0], gap2[0], far2[0], open[0]);
        double gap = 0.0, far = 0.0;
        for (int d = 0; d < D; ++d) {
          gap += gap2[d];
          far += far2[d];
        }
        if (gap >= own * own) continue;
        const bool anyOpen = open[0] || (D > 1 && open[1]) || (D > 2 && open[2]);
        if (!anyOpen && far < beyond * beyond) continue;  // every particle in it nearer than `beyond`
        const double limit2 = std::min(r2, own * own), inner2 = beyond * beyond;
        const std::uint32_t begin = cellStart_[c], end = cellStart_[c + 1];
        std::size_t n = out.size();
        out.resize(n + (end - begin));
        std::uint32_t* to = out.data();
        for (std::uint32_t k = begin; k < end; ++k) {  // without branches, as query's sweep
          double d2 = 0.0;
          for (int d = 0; d < D; ++d) {
            const double dx = pos[d][k] - point[d];
            d2 += dx * dx;
          }
          // A support that stops at `beyond` cannot reach past it.
          to[n] = index[k];
          n += (d2 < limit2) & (d2 >= inner2) & (support[k] > beyond);
        }
        out.resize(n);
      }
    }
  }
}

inline void CellGrid::axisBounds(int d, long at, double x, double& gap2, double& far2,
                                 bool& open) const {
  // Nearest and farthest distance from x to the cell's span along axis d; the edge cells also
  // hold what lies beyond the grid (cellCoord clamps), so they are open on that side. The bounds
  // are widened by the rounding of the binning (a particle may lie a few ulps of its coordinates
  // outside the cell it was binned in), so that a skipped cell holds no particle the caller's
  // exact test would keep.
  const double low = origin_[d] + static_cast<double>(at) * cellSize_;
  const double high = low + cellSize_;
  const double pad = 1e-14 * (std::abs(low) + std::abs(high) + std::abs(x));
  double gap = 0.0;
  if (x < low && at > 0) gap = std::max(low - x - pad, 0.0);
  else if (x > high && at < cells_[d] - 1) gap = std::max(x - high - pad, 0.0);
  gap2 = gap * gap;
  const double far = std::max(std::abs(x - low), std::abs(high - x)) + pad;
  far2 = far * far;
  open = at == 0 || at == cells_[d] - 1;
}

}  // namespace ejecta
