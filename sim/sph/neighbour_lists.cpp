#include "sim/sph/neighbour_lists.hpp"

#include <omp.h>

#include <algorithm>
#include <numeric>

namespace ejecta {

void NeighbourLists::reset(std::size_t numParticles, int numThreads) {
  buffers_.resize(numThreads);
  for (auto& b : buffers_) b.clear();
  owner_.assign(numParticles, 0);
  start_.assign(numParticles, 0);
  count_.assign(numParticles, 0);
}

void NeighbourLists::storeGather(int t, std::size_t i, const std::uint32_t* js,
                                 std::size_t count) {
  std::vector<std::uint32_t>& buffer = buffers_[t];
  owner_[i] = static_cast<std::uint32_t>(t);
  start_[i] = buffer.size();
  count_[i] = static_cast<std::uint32_t>(count);
  buffer.insert(buffer.end(), js, js + count);
}

template <int D>
void NeighbourLists::findGhostGathers(const ParticleSet& p, const CellGrid& grid,
                                      double support) {
  const std::size_t n = p.size();
  const std::size_t nReal = p.numReal;
#pragma omp parallel
  {
    const int t = omp_get_thread_num();
    std::vector<std::uint32_t> found;
#pragma omp for schedule(dynamic, 256)
    for (std::size_t g = nReal; g < n; ++g) {
      found.clear();
      const double point[3] = {p.x[0][g], p.x[1][g], p.x[2][g]};
      grid.query<D>(p, point, support * p.h[g], found);
      // Only real neighbours matter: ghost-ghost pairs never enter the force pass.
      std::size_t kept = 0;
      for (std::uint32_t j : found)
        if (j < nReal) found[kept++] = j;
      storeGather(t, g, found.data(), kept);
    }
  }
}

template <int D>
void NeighbourLists::buildPairs(const ParticleSet& p, double support) {
  const std::size_t n = p.size();
  const std::size_t nReal = p.numReal;
  auto outside = [&](std::size_t i, std::size_t j) {
    double r2 = 0.0;
    for (int d = 0; d < D; ++d) {
      const double dx = p.x[d][i] - p.x[d][j];
      r2 += dx * dx;
    }
    const double reach = support * p.h[i];
    return r2 >= reach * reach;
  };
  // Extra partners: j reaches real i with its own kernel but i's kernel does not reach j. The
  // distance tests run in parallel over contiguous ranges of j; the (i, j) pairs found are then
  // placed in ascending j for every i, whatever the number of threads.
  std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t>>> found(static_cast<std::size_t>(omp_get_max_threads()));
#pragma omp parallel
  {
    auto& mine = found[omp_get_thread_num()];
    mine.clear();
#pragma omp for schedule(static)
    for (std::size_t j = 0; j < n; ++j)
      for (std::uint32_t i : gather(j))
        if (i < nReal && outside(i, j)) mine.emplace_back(i, static_cast<std::uint32_t>(j));
  }
  std::vector<std::uint32_t> extraCount(nReal, 0);
  for (const auto& list : found)
    for (const auto& [i, j] : list) ++extraCount[i];
  pairStart_.assign(nReal + 1, 0);
  for (std::size_t i = 0; i < nReal; ++i)
    pairStart_[i + 1] = pairStart_[i] + count_[i] + extraCount[i];
  pairs_.resize(pairStart_[nReal]);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < nReal; ++i) {
    const auto g = gather(i);
    std::copy(g.begin(), g.end(), pairs_.begin() + static_cast<std::ptrdiff_t>(pairStart_[i]));
  }
  std::vector<std::size_t> fill(nReal);
  for (std::size_t i = 0; i < nReal; ++i) fill[i] = pairStart_[i] + count_[i];
  for (const auto& list : found)  // threads hold ascending, contiguous ranges of j
    for (const auto& [i, j] : list) pairs_[fill[i]++] = j;
}

template <int D>
void NeighbourLists::buildActivePairs(const ParticleSet& p, const CellGrid& grid, double support,
                                      const std::vector<std::size_t>& active) {
  const std::size_t nReal = p.numReal;
  // The partners beyond i's own support whose larger kernel reaches i, ascending in j.
  std::vector<std::vector<std::uint32_t>> extra(active.size());
#pragma omp parallel
  {
    std::vector<std::uint32_t> found;
#pragma omp for schedule(dynamic, 64)
    for (std::size_t k = 0; k < active.size(); ++k) {
      const std::size_t i = active[k];
      const double xi[3] = {p.x[0][i], p.x[1][i], p.x[2][i]};
      const double own = support * p.h[i];
      const double reach = grid.reachInto(xi);
      if (reach <= own) continue;  // no kernel wider than i's own reaches here
      found.clear();
      grid.queryReaching<D>(xi, reach, found, own);
      std::vector<std::uint32_t>& mine = extra[k];
      for (std::uint32_t j : found) {
        double r2 = 0.0;
        for (int d = 0; d < D; ++d) {
          const double dx = p.x[d][i] - p.x[d][j];
          r2 += dx * dx;
        }
        const double reachJ = support * p.h[j];
        if (r2 >= own * own && r2 < reachJ * reachJ) mine.push_back(j);
      }
      std::sort(mine.begin(), mine.end());
    }
  }
  pairStart_.assign(nReal + 1, 0);
  for (std::size_t k = 0; k < active.size(); ++k)
    pairStart_[active[k] + 1] = count_[active[k]] + extra[k].size();
  for (std::size_t i = 0; i < nReal; ++i) pairStart_[i + 1] += pairStart_[i];
  pairs_.resize(pairStart_[nReal]);
#pragma omp parallel for schedule(static)
  for (std::size_t k = 0; k < active.size(); ++k) {
    const std::size_t i = active[k];
    const auto g = gather(i);
    auto at = pairs_.begin() + static_cast<std::ptrdiff_t>(pairStart_[i]);
    at = std::copy(g.begin(), g.end(), at);
    std::copy(extra[k].begin(), extra[k].end(), at);
  }
}

template void NeighbourLists::findGhostGathers<1>(const ParticleSet&, const CellGrid&, double);
template void NeighbourLists::findGhostGathers<2>(const ParticleSet&, const CellGrid&, double);
template void NeighbourLists::findGhostGathers<3>(const ParticleSet&, const CellGrid&, double);
template void NeighbourLists::buildPairs<1>(const ParticleSet&, double);
template void NeighbourLists::buildPairs<2>(const ParticleSet&, double);
template void NeighbourLists::buildPairs<3>(const ParticleSet&, double);
template void NeighbourLists::buildActivePairs<1>(const ParticleSet&, const CellGrid&, double,
                                                  const std::vector<std::size_t>&);
template void NeighbourLists::buildActivePairs<2>(const ParticleSet&, const CellGrid&, double,
                                                  const std::vector<std::size_t>&);
template void NeighbourLists::buildActivePairs<3>(const ParticleSet&, const CellGrid&, double,
                                                  const std::vector<std::size_t>&);

}  // namespace ejecta
