// MPI behind the Communicator interface (sim/parallel/communicator.hpp). Built when CMake finds
// MPI (EJECTA_HAVE_MPI); the same functions without MPI are in serial_session.cpp.
#include <mpi.h>

#include <cstdlib>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "sim/parallel/communicator.hpp"

namespace ejecta {

namespace {

// MPI counts are int: payloads beyond 2 GiB per rank would need a chunked protocol.
int checkedCount(std::size_t n) {
  if (n > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw std::length_error("an MPI message of " + std::to_string(n) +
                            " bytes exceeds MPI's int count");
  return static_cast<int>(n);
}

std::vector<int> displacements(const std::vector<int>& counts) {
  std::vector<int> displ(counts.size(), 0);
  std::size_t total = 0;
  for (std::size_t r = 0; r < counts.size(); ++r) {
    displ[r] = checkedCount(total);
    total += static_cast<std::size_t>(counts[r]);
  }
  checkedCount(total);
  return displ;
}

std::vector<Bytes> splitBytes(const Bytes& all, const std::vector<int>& counts, const std::vector<int>& displ) {
  std::vector<Bytes> out(counts.size());
  for (std::size_t r = 0; r < counts.size(); ++r)
    out[r].assign(all.begin() + displ[r], all.begin() + displ[r] + counts[r]);
  return out;
}

// The requests of a startExchangeWith and the buffers they read and fill, kept alive until
// they complete (a destructor that finds them pending waits, so no buffer outlives its use).
class MpiPendingExchange final : public Communicator::PendingExchange {
 public:
  MpiPendingExchange(MPI_Comm comm, std::span<const int> to, std::vector<Bytes> payloads,
                     std::span<const int> from, std::span<const std::size_t> sizes)
      : sent_(std::move(payloads)), received_(from.size()) {
    // A tag of its own: its messages cannot pair with a blocking exchange's.
    constexpr int kPendingTag = 7103;
    for (std::size_t k = 0; k < from.size(); ++k) {
      received_[k].resize(sizes[k]);
      if (sizes[k] == 0) continue;
      requests_.emplace_back();
      MPI_Irecv(received_[k].data(), checkedCount(sizes[k]), MPI_BYTE, from[k], kPendingTag, comm,
                &requests_.back());
    }
    for (std::size_t k = 0; k < to.size(); ++k) {
      if (sent_[k].empty()) continue;
      requests_.emplace_back();
      MPI_Isend(sent_[k].data(), checkedCount(sent_[k].size()), MPI_BYTE, to[k], kPendingTag, comm,
                &requests_.back());
    }
  }
  ~MpiPendingExchange() override { wait(); }
  MpiPendingExchange(const MpiPendingExchange&) = delete;
  MpiPendingExchange& operator=(const MpiPendingExchange&) = delete;

  std::vector<Bytes> finish() override {
    wait();
    return std::move(received_);
  }
  void progress() override {
    if (requests_.empty()) return;
    int done = 0;
    MPI_Testall(static_cast<int>(requests_.size()), requests_.data(), &done, MPI_STATUSES_IGNORE);
    if (done) requests_.clear();
  }

 private:
  void wait() {
    if (requests_.empty()) return;
    MPI_Waitall(static_cast<int>(requests_.size()), requests_.data(), MPI_STATUSES_IGNORE);
    requests_.clear();
  }
  std::vector<Bytes> sent_, received_;
  std::vector<MPI_Request> requests_;
};

class MpiCommunicator final : public Communicator {
 public:
  // `owned`: the communicator was made by split() and is freed with this object.
  MpiCommunicator(MPI_Comm comm, bool owned) : comm_(comm), owned_(owned) {
    MPI_Comm_rank(comm_, &rank_);
    MPI_Comm_size(comm_, &size_);
  }
  ~MpiCommunicator() override {
    int finalised = 0;
    MPI_Finalized(&finalised);
    if (owned_ && !finalised) MPI_Comm_free(&comm_);
  }
  MpiCommunicator(const MpiCommunicator&) = delete;
  MpiCommunicator& operator=(const MpiCommunicator&) = delete;

  std::shared_ptr<const Communicator> split(int color) const override {
    MPI_Comm part = MPI_COMM_NULL;
    MPI_Comm_split(comm_, color, rank_, &part);
    return std::make_shared<MpiCommunicator>(part, true);
  }
  int rank() const override { return rank_; }
  int size() const override { return size_; }

  std::vector<Bytes> allGather(std::span<const std::byte> mine) const override {
    int count = checkedCount(mine.size());
    std::vector<int> counts(static_cast<std::size_t>(size_));
    MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, comm_);
    const std::vector<int> displ = displacements(counts);
    Bytes all(static_cast<std::size_t>(displ.back()) + static_cast<std::size_t>(counts.back()));
    MPI_Allgatherv(mine.data(), count, MPI_BYTE, all.data(), counts.data(), displ.data(), MPI_BYTE, comm_);
    return splitBytes(all, counts, displ);
  }

  std::vector<Bytes> exchange(const std::vector<Bytes>& toRank) const override {
    const std::size_t n = static_cast<std::size_t>(size_);
    std::vector<int> sendCounts(n), recvCounts(n);
    Bytes send;
    for (std::size_t r = 0; r < n; ++r) {
      sendCounts[r] = checkedCount(toRank[r].size());
      send.insert(send.end(), toRank[r].begin(), toRank[r].end());
    }
    MPI_Alltoall(sendCounts.data(), 1, MPI_INT, recvCounts.data(), 1, MPI_INT, comm_);
    const std::vector<int> sendDispl = displacements(sendCounts);
    const std::vector<int> recvDispl = displacements(recvCounts);
    Bytes recv(static_cast<std::size_t>(recvDispl.back()) + static_cast<std::size_t>(recvCounts.back()));
    MPI_Alltoallv(send.data(), sendCounts.data(), sendDispl.data(), MPI_BYTE, recv.data(),
                  recvCounts.data(), recvDispl.data(), MPI_BYTE, comm_);
    return splitBytes(recv, recvCounts, recvDispl);
  }

  std::vector<Bytes> exchangeWith(std::span<const int> to, const std::vector<Bytes>& payloads,
                                  std::span<const int> from) const override {
    // Sizes first, then the payloads; every receive is posted before the sends it waits on.
    constexpr int kSizeTag = 7101, kDataTag = 7102;
    std::vector<std::uint64_t> sendSizes(to.size()), recvSizes(from.size());
    std::vector<MPI_Request> requests;
    requests.reserve(2 * (to.size() + from.size()));
    for (std::size_t k = 0; k < from.size(); ++k) {
      requests.emplace_back();
      MPI_Irecv(&recvSizes[k], 1, MPI_UINT64_T, from[k], kSizeTag, comm_, &requests.back());
    }
    for (std::size_t k = 0; k < to.size(); ++k) {
      sendSizes[k] = payloads[k].size();
      requests.emplace_back();
      MPI_Isend(&sendSizes[k], 1, MPI_UINT64_T, to[k], kSizeTag, comm_, &requests.back());
    }
    MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
    requests.clear();
    std::vector<Bytes> received(from.size());
    for (std::size_t k = 0; k < from.size(); ++k) {
      received[k].resize(recvSizes[k]);
      if (recvSizes[k] == 0) continue;
      requests.emplace_back();
      MPI_Irecv(received[k].data(), checkedCount(recvSizes[k]), MPI_BYTE, from[k], kDataTag, comm_,
                &requests.back());
    }
    for (std::size_t k = 0; k < to.size(); ++k) {
      if (payloads[k].empty()) continue;
      requests.emplace_back();
      MPI_Isend(payloads[k].data(), checkedCount(payloads[k].size()), MPI_BYTE, to[k], kDataTag,
                comm_, &requests.back());
    }
    MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
    return received;
  }

  std::unique_ptr<PendingExchange> startExchangeWith(std::span<const int> to, std::vector<Bytes> payloads,
                                                     std::span<const int> from,
                                                     std::span<const std::size_t> sizes) const override {
    return std::make_unique<MpiPendingExchange>(comm_, to, std::move(payloads), from, sizes);
  }

  std::vector<Bytes> gatherToRoot(std::span<const std::byte> mine) const override {
    int count = checkedCount(mine.size());
    std::vector<int> counts(static_cast<std::size_t>(size_));
    MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm_);
    std::vector<int> displ(counts.size(), 0);
    Bytes all;
    if (rank_ == 0) {
      displ = displacements(counts);
      all.resize(static_cast<std::size_t>(displ.back()) + static_cast<std::size_t>(counts.back()));
    }
    MPI_Gatherv(mine.data(), count, MPI_BYTE, all.data(), counts.data(), displ.data(), MPI_BYTE, 0, comm_);
    if (rank_ != 0) return {};
    return splitBytes(all, counts, displ);
  }

  void sumInPlace(std::span<std::uint64_t> values) const override {
    MPI_Allreduce(MPI_IN_PLACE, values.data(), checkedCount(values.size()), MPI_UINT64_T, MPI_SUM, comm_);
  }
  void minInPlace(std::span<double> values) const override {
    MPI_Allreduce(MPI_IN_PLACE, values.data(), checkedCount(values.size()), MPI_DOUBLE, MPI_MIN, comm_);
  }
  void maxInPlace(std::span<double> values) const override {
    MPI_Allreduce(MPI_IN_PLACE, values.data(), checkedCount(values.size()), MPI_DOUBLE, MPI_MAX, comm_);
  }

 private:
  MPI_Comm comm_;
  bool owned_ = false;
  int rank_ = 0;
  int size_ = 1;
};

}  // namespace

bool builtWithMpi() { return true; }

std::shared_ptr<const Communicator> worldCommunicator() {
  int initialised = 0, finalised = 0;
  MPI_Initialized(&initialised);
  MPI_Finalized(&finalised);
  if (!initialised || finalised) return std::make_shared<SerialCommunicator>();
  return std::make_shared<MpiCommunicator>(MPI_COMM_WORLD, false);
}

MpiSession::MpiSession(int* argc, char*** argv) {
  int provided = 0;
  MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
}

MpiSession::~MpiSession() {
  int finalised = 0;
  MPI_Finalized(&finalised);
  if (!finalised) MPI_Finalize();
}

void MpiSession::abortAll(int code) {
  int initialised = 0;
  MPI_Initialized(&initialised);
  if (initialised) MPI_Abort(MPI_COMM_WORLD, code);
}

}  // namespace ejecta
