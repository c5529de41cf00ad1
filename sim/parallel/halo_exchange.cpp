#include "sim/parallel/halo_exchange.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "sim/parallel/particle_packing.hpp"

namespace ejecta {

namespace {

// What each rank tells the others about itself: the box around its real particles and their
// largest reach (a rank without particles sends an empty box, which no particle is near).
struct RankExtent {
  std::array<double, 3> lo;
  std::array<double, 3> hi;
  double reach;
};

double distanceToBox(const ParticleSet& p, std::size_t j, const RankExtent& e, int dimension) {
  double d2 = 0.0;
  for (int d = 0; d < dimension; ++d) {
    const std::size_t a = static_cast<std::size_t>(d);
    const double x = p.x[a][j];
    const double out = x < e.lo[a] ? e.lo[a] - x : x > e.hi[a] ? x - e.hi[a] : 0.0;
    d2 += out * out;
  }
  return std::sqrt(d2);
}

}  // namespace

void HaloExchange::build(ParticleSet& p, int dimension, double supportFactor, const Communicator& comm) {
  const std::size_t ranks = static_cast<std::size_t>(comm.size());
  RankExtent mine{};
  mine.lo.fill(std::numeric_limits<double>::max());
  mine.hi.fill(std::numeric_limits<double>::lowest());
  mine.reach = 0.0;
  for (std::size_t i = 0; i < p.numReal; ++i) {
    for (std::size_t a = 0; a < 3; ++a) {
      mine.lo[a] = std::min(mine.lo[a], p.x[a][i]);
      mine.hi[a] = std::max(mine.hi[a], p.x[a][i]);
    }
    mine.reach = std::max(mine.reach, supportFactor * p.h[i]);
  }
  Bytes bytes;
  appendBytes(bytes, &mine, 1);
  std::vector<RankExtent> extents;
  for (const Bytes& b : comm.allGather(bytes)) extents.push_back(fromBytes<RankExtent>(b).at(0));

  sendTo_.assign(ranks, {});
  const int me = comm.rank();
  const std::size_t local = p.size();  // real particles and this rank's boundary ghosts
  for (std::size_t r = 0; r < ranks; ++r) {
    if (static_cast<int>(r) == me || extents[r].lo[0] > extents[r].hi[0]) continue;
    for (std::size_t j = 0; j < local; ++j)
      if (distanceToBox(p, j, extents[r], dimension) < std::max(extents[r].reach, supportFactor * p.h[j]))
        sendTo_[r].push_back(j);
  }
  const ParticlePacker packer(p, PackedFields::Halo);
  std::vector<Bytes> out(ranks);
  for (std::size_t r = 0; r < ranks; ++r) packer.pack(p, sendTo_[r], out[r]);
  const std::vector<Bytes> in = comm.exchange(out);
  received_ = 0;
  for (const Bytes& b : in) received_ += packer.count(b);
  firstFrom_.assign(ranks, local);
  p.resize(local + received_);
  p.ghostSource.resize(p.numGhosts(), kRemoteSource);
  std::size_t at = local;
  for (std::size_t r = 0; r < ranks; ++r) {
    firstFrom_[r] = at;
    packer.unpack(p, in[r], at);
    at += packer.count(in[r]);
  }
}

void HaloExchange::refresh(ParticleSet& p, const Communicator& comm) const {
  if (sendTo_.empty()) return;
  const ParticlePacker packer(p, PackedFields::HaloValues);
  std::vector<Bytes> out(sendTo_.size());
  for (std::size_t r = 0; r < sendTo_.size(); ++r) packer.pack(p, sendTo_[r], out[r]);
  const std::vector<Bytes> in = comm.exchange(out);
  for (std::size_t r = 0; r < in.size(); ++r) packer.unpack(p, in[r], firstFrom_[r]);
}

void HaloExchange::refreshArray(std::vector<double>& values, int stride, const Communicator& comm) const {
  if (sendTo_.empty()) return;
  const std::size_t s = static_cast<std::size_t>(stride);
  std::vector<Bytes> out(sendTo_.size());
  for (std::size_t r = 0; r < sendTo_.size(); ++r)
    for (std::size_t j : sendTo_[r]) appendBytes(out[r], values.data() + s * j, s);
  const std::vector<Bytes> in = comm.exchange(out);
  for (std::size_t r = 0; r < in.size(); ++r) {
    const std::vector<double> theirs = fromBytes<double>(in[r]);
    std::copy(theirs.begin(), theirs.end(), values.begin() + static_cast<std::ptrdiff_t>(s * firstFrom_[r]));
  }
}

std::size_t HaloExchange::sent() const {
  std::size_t n = 0;
  for (const auto& list : sendTo_) n += list.size();
  return n;
}

}  // namespace ejecta
