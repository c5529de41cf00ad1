#include "sim/parallel/halo_exchange.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "sim/parallel/particle_packing.hpp"

namespace ejecta {

namespace {

struct Box {
  std::array<double, 3> lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
                           std::numeric_limits<double>::max()};
  std::array<double, 3> hi{std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest(),
                           std::numeric_limits<double>::lowest()};
  bool empty() const { return lo[0] > hi[0]; }
  void add(const ParticleSet& p, std::size_t i) {
    for (std::size_t a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], p.x[a][i]);
      hi[a] = std::max(hi[a], p.x[a][i]);
    }
  }
};

double distance(const Box& b, const double* x, int dimension) {
  double d2 = 0.0;
  for (int d = 0; d < dimension; ++d) {
    const std::size_t a = static_cast<std::size_t>(d);
    const double out = x[a] < b.lo[a] ? b.lo[a] - x[a] : x[a] > b.hi[a] ? x[a] - b.hi[a] : 0.0;
    d2 += out * out;
  }
  return std::sqrt(d2);
}

double distance(const Box& a, const Box& b, int dimension) {
  double d2 = 0.0;
  for (int d = 0; d < dimension; ++d) {
    const std::size_t k = static_cast<std::size_t>(d);
    const double gap = std::max({0.0, a.lo[k] - b.hi[k], b.lo[k] - a.hi[k]});
    d2 += gap * gap;
  }
  return std::sqrt(d2);
}

constexpr int kMaxBoxes = 64;

// What each rank tells every other about itself (fixed size, for one all-gather): enough to
// decide who talks to whom. The boxes then go to the partners only.
struct RankExtent {
  Box local;           // around every particle it may send: real ones and its ghosts
  double sendReach;    // the largest k h among those
  Box cover;           // around its real particles
  double reach;        // R: the largest k h among its real particles
};

// The tight boxes of a rank's real particles' occupied cells, a grid of about 64 cells over
// their box.
std::vector<Box> coverBoxes(const ParticleSet& p, int dimension, const RankExtent& e) {
  const int side = dimension == 1 ? 64 : dimension == 2 ? 8 : 4;
  std::array<Box, kMaxBoxes> cells{};
  for (std::size_t i = 0; i < p.numReal; ++i) {
    int cell = 0;
    for (int d = dimension - 1; d >= 0; --d) {
      const std::size_t a = static_cast<std::size_t>(d);
      const double extent = e.cover.hi[a] - e.cover.lo[a];
      const int c = extent > 0.0 ? std::min(side - 1, static_cast<int>((p.x[a][i] - e.cover.lo[a]) / extent * side)) : 0;
      cell = cell * side + c;
    }
    cells[static_cast<std::size_t>(cell)].add(p, i);
  }
  std::vector<Box> occupied;
  for (const Box& b : cells)
    if (!b.empty()) occupied.push_back(b);
  return occupied;
}

// Does rank `from` perhaps hold particles that rank `to` needs? Both ranks evaluate this from
// the gathered extents, so they agree on who talks to whom.
bool mayNeed(const RankExtent& from, const RankExtent& to, int dimension) {
  if (from.local.empty() || to.cover.empty()) return false;
  return distance(from.local, to.cover, dimension) < std::max(to.reach, from.sendReach);
}

// This rank's particles [0, n) binned by a grid of cells at least `cell` wide, to find those
// near a box without visiting the others.
class Buckets {
 public:
  Buckets(const ParticleSet& p, std::size_t n, const Box& box, double cell, int dimension)
      : dimension_(dimension), box_(box) {
    std::size_t cells = 1;
    for (int d = 0; d < 3; ++d) {
      const std::size_t a = static_cast<std::size_t>(d);
      double width = d < dimension ? cell : 1.0;
      const double extent = d < dimension ? box.hi[a] - box.lo[a] : 0.0;
      // No more cells than about twice the particles along all axes together.
      const double most = std::max(1.0, std::floor(std::pow(2.0 * static_cast<double>(n), 1.0 / dimension)));
      width = std::max(width, extent / most);
      width_[a] = width > 0.0 ? width : 1.0;
      count_[a] = d < dimension ? static_cast<long>(extent / width_[a]) + 1 : 1;
      cells *= static_cast<std::size_t>(count_[a]);
    }
    start_.assign(cells + 1, 0);
    std::vector<std::size_t> of(n);
    for (std::size_t i = 0; i < n; ++i) ++start_[(of[i] = cellOf(p, i)) + 1];
    for (std::size_t c = 0; c < cells; ++c) start_[c + 1] += start_[c];
    members_.resize(n);
    std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < n; ++i) members_[fill[of[i]]++] = i;
  }

  // Calls f(i) for every particle in a cell that overlaps `box` widened by `margin`.
  template <typename F>
  void near(const Box& box, double margin, F&& f) const {
    std::array<long, 3> lo{0, 0, 0}, hi{0, 0, 0};
    for (int d = 0; d < dimension_; ++d) {
      const std::size_t a = static_cast<std::size_t>(d);
      lo[a] = coordinate(box.lo[a] - margin, a);
      hi[a] = coordinate(box.hi[a] + margin, a);
    }
    for (long z = lo[2]; z <= hi[2]; ++z)
      for (long y = lo[1]; y <= hi[1]; ++y)
        for (long x = lo[0]; x <= hi[0]; ++x) {
          const std::size_t c = static_cast<std::size_t>((z * count_[1] + y) * count_[0] + x);
          for (std::size_t k = start_[c]; k < start_[c + 1]; ++k) f(members_[k]);
        }
  }

 private:
  long coordinate(double x, std::size_t a) const {
    return std::clamp(static_cast<long>(std::floor((x - box_.lo[a]) / width_[a])), 0L, count_[a] - 1);
  }
  std::size_t cellOf(const ParticleSet& p, std::size_t i) const {
    std::size_t c = 0;
    for (int d = dimension_ - 1; d >= 0; --d) {
      const std::size_t a = static_cast<std::size_t>(d);
      c = c * static_cast<std::size_t>(count_[a]) + static_cast<std::size_t>(coordinate(p.x[a][i], a));
    }
    return c;
  }

  int dimension_;
  Box box_;
  std::array<double, 3> width_{1.0, 1.0, 1.0};
  std::array<long, 3> count_{1, 1, 1};
  std::vector<std::size_t> start_;
  std::vector<std::size_t> members_;
};

}  // namespace

void HaloExchange::build(ParticleSet& p, int dimension, double supportFactor, const Communicator& comm) {
  const std::size_t local = p.size();  // real particles and this rank's boundary ghosts
  RankExtent mine{};
  mine.sendReach = mine.reach = 0.0;
  for (std::size_t i = 0; i < local; ++i) {
    mine.local.add(p, i);
    mine.sendReach = std::max(mine.sendReach, supportFactor * p.h[i]);
    if (i < p.numReal) {
      mine.cover.add(p, i);
      mine.reach = std::max(mine.reach, supportFactor * p.h[i]);
    }
  }
  Bytes bytes;
  appendBytes(bytes, &mine, 1);
  std::vector<RankExtent> extents;
  for (const Bytes& b : comm.allGather(bytes)) extents.push_back(fromBytes<RankExtent>(b).at(0));

  const int me = comm.rank();
  sendRanks_.clear();
  recvRanks_.clear();
  for (int r = 0; r < comm.size(); ++r) {
    if (r == me) continue;
    const RankExtent& them = extents[static_cast<std::size_t>(r)];
    if (mayNeed(mine, them, dimension)) sendRanks_.push_back(r);
    if (mayNeed(them, mine, dimension)) recvRanks_.push_back(r);
  }
  // My boxes to the ranks that send to me (they choose what to send by them); theirs from the
  // ranks I send to.
  const std::vector<Box> myBoxes = coverBoxes(p, dimension, mine);
  Bytes boxBytes;
  appendBytes(boxBytes, myBoxes.data(), myBoxes.size());
  const std::vector<Bytes> theirBoxes =
      comm.exchangeWith(recvRanks_, std::vector<Bytes>(recvRanks_.size(), boxBytes), sendRanks_);
  sendTo_.assign(sendRanks_.size(), {});
  if (!sendRanks_.empty()) {
    const Buckets buckets(p, local, mine.local, mine.sendReach, dimension);
    std::vector<int> marked(local, -1);  // the last send rank a particle was chosen for
    for (std::size_t s = 0; s < sendRanks_.size(); ++s) {
      const RankExtent& them = extents[static_cast<std::size_t>(sendRanks_[s])];
      for (const Box& box : fromBytes<Box>(theirBoxes[s])) {
        buckets.near(box, std::max(them.reach, mine.sendReach), [&](std::size_t j) {
          if (marked[j] == static_cast<int>(s)) return;
          const double x[3] = {p.x[0][j], p.x[1][j], p.x[2][j]};
          if (distance(box, x, dimension) < std::max(them.reach, supportFactor * p.h[j])) {
            marked[j] = static_cast<int>(s);
            sendTo_[s].push_back(j);
          }
        });
      }
      // In index order, whatever order the boxes found them in: the receiver's halo order
      // depends on the ranks only.
      std::sort(sendTo_[s].begin(), sendTo_[s].end());
    }
  }
  const ParticlePacker packer(p, PackedFields::Halo);
  std::vector<Bytes> out(sendRanks_.size());
  for (std::size_t s = 0; s < sendRanks_.size(); ++s) packer.pack(p, sendTo_[s], out[s]);
  const std::vector<Bytes> in = comm.exchangeWith(sendRanks_, out, recvRanks_);
  received_ = 0;
  for (const Bytes& b : in) received_ += packer.count(b);
  p.resize(local + received_);
  p.ghostSource.resize(p.numGhosts(), kRemoteSource);
  firstFrom_.assign(recvRanks_.size(), local);
  countFrom_.assign(recvRanks_.size(), 0);
  std::size_t at = local;
  for (std::size_t k = 0; k < in.size(); ++k) {
    firstFrom_[k] = at;
    countFrom_[k] = packer.count(in[k]);
    packer.unpack(p, in[k], at);
    at += countFrom_[k];
  }
}

void HaloExchange::refresh(ParticleSet& p, const Communicator& comm) const {
  const auto pending = startRefresh(p, comm);
  finishRefresh(p, *pending);
}

std::unique_ptr<Communicator::PendingExchange> HaloExchange::startRefresh(const ParticleSet& p,
                                                                          const Communicator& comm) const {
  const ParticlePacker packer(p, PackedFields::HaloValues);
  std::vector<Bytes> out(sendRanks_.size());
  for (std::size_t s = 0; s < sendRanks_.size(); ++s) packer.pack(p, sendTo_[s], out[s]);
  std::vector<std::size_t> sizes(recvRanks_.size());
  for (std::size_t k = 0; k < sizes.size(); ++k) sizes[k] = countFrom_[k] * packer.recordBytes();
  return comm.startExchangeWith(sendRanks_, std::move(out), recvRanks_, sizes);
}

void HaloExchange::finishRefresh(ParticleSet& p, Communicator::PendingExchange& pending) const {
  const ParticlePacker packer(p, PackedFields::HaloValues);
  const std::vector<Bytes> in = pending.finish();
  for (std::size_t k = 0; k < in.size(); ++k) packer.unpack(p, in[k], firstFrom_[k]);
}

void HaloExchange::refreshArray(std::vector<double>& values, int stride, const Communicator& comm) const {
  const std::size_t s = static_cast<std::size_t>(stride);
  std::vector<Bytes> out(sendRanks_.size());
  for (std::size_t r = 0; r < sendRanks_.size(); ++r)
    for (std::size_t j : sendTo_[r]) appendBytes(out[r], values.data() + s * j, s);
  std::vector<std::size_t> sizes(recvRanks_.size());
  for (std::size_t k = 0; k < sizes.size(); ++k) sizes[k] = countFrom_[k] * s * sizeof(double);
  const std::vector<Bytes> in = comm.startExchangeWith(sendRanks_, std::move(out), recvRanks_, sizes)->finish();
  for (std::size_t k = 0; k < in.size(); ++k) {
    const std::vector<double> theirs = fromBytes<double>(in[k]);
    std::copy(theirs.begin(), theirs.end(), values.begin() + static_cast<std::ptrdiff_t>(s * firstFrom_[k]));
  }
}

std::size_t HaloExchange::sent() const {
  std::size_t n = 0;
  for (const auto& list : sendTo_) n += list.size();
  return n;
}

}  // namespace ejecta
