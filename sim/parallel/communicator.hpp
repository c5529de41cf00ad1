#pragma once
// Communicator: the ranks of one distributed run, and the few collective operations ejecta's
// decomposition, halo exchange and reductions are built from. sim/ depends on this interface
// only; MPI lives behind it (sim/parallel/mpi_communicator.cpp, built when CMake finds MPI), and
// a run without MPI uses the one-rank SerialCommunicator. Every call is collective: all ranks of
// the communicator make it, in the same order, from their OpenMP master thread.
//
// Reductions that feed results (energies, deposits, totals) are summed in rank order from an
// all-gather rather than by MPI_Allreduce, whose order of summation MPI leaves open: a run on a
// fixed number of ranks is then bit-for-bit reproducible.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace ejecta {

using Bytes = std::vector<std::byte>;

class Communicator {
 public:
  virtual ~Communicator() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;

  // Every rank's bytes, indexed by rank.
  virtual std::vector<Bytes> allGather(std::span<const std::byte> mine) const = 0;
  // Personalised all-to-all: toRank[r] goes to rank r (toRank.size() == size()); returns what
  // each rank sent here, indexed by the sender.
  virtual std::vector<Bytes> exchange(const std::vector<Bytes>& toRank) const = 0;
  // Point to point with known partners: sends payloads[k] to rank to[k] and returns what each
  // rank of `from` sent here, in from's order. Every rank this one lists in `to` must list this
  // one in its `from`, and the other way round (a message may be empty). Costs a latency per
  // partner rather than per rank: the halo exchange, whose partners are a rank's neighbours.
  virtual std::vector<Bytes> exchangeWith(std::span<const int> to, const std::vector<Bytes>& payloads,
                                          std::span<const int> from) const = 0;
  // A point-to-point exchange under way (startExchangeWith).
  class PendingExchange {
   public:
    virtual ~PendingExchange() = default;
    // Waits until every message has arrived and gone; what each rank of `from` sent, in from's
    // order. Call once.
    virtual std::vector<Bytes> finish() = 0;
    // Lets the messages advance without waiting (MPI moves a large message only inside its
    // calls); a computation that overlaps them calls it now and then.
    virtual void progress() {}
  };
  // exchangeWith for messages whose sizes the receiver knows (sizes[k] bytes from from[k], as
  // in a halo refresh), without waiting: one message each way, and this rank computes until
  // finish(). The same pairing rules as exchangeWith; one pending exchange at a time.
  virtual std::unique_ptr<PendingExchange> startExchangeWith(std::span<const int> to,
                                                             std::vector<Bytes> payloads,
                                                             std::span<const int> from,
                                                             std::span<const std::size_t> sizes) const = 0;
  // Every rank's bytes at rank 0 (indexed by rank there; empty on the other ranks).
  virtual std::vector<Bytes> gatherToRoot(std::span<const std::byte> mine) const = 0;
  // Element-wise over ranks, in place (exact: integer sums and extrema do not depend on order).
  virtual void sumInPlace(std::span<std::uint64_t> values) const = 0;
  virtual void minInPlace(std::span<double> values) const = 0;
  virtual void maxInPlace(std::span<double> values) const = 0;
  // The ranks that pass the same `color` form a new communicator (ranked in this one's order):
  // sweeps run variants on such groups, and tests run a smaller run beside a larger one.
  virtual std::shared_ptr<const Communicator> split(int color) const = 0;

  bool isRoot() const { return rank() == 0; }
  double minimum(double x) const { minInPlace({&x, 1}); return x; }
  double maximum(double x) const { maxInPlace({&x, 1}); return x; }
  std::uint64_t sum(std::uint64_t x) const { sumInPlace({&x, 1}); return x; }
  // True on every rank when `mine` is true on every rank.
  bool allTrue(bool mine) const { return minimum(mine ? 1.0 : 0.0) > 0.5; }
  // The element-wise sum of every rank's `values`, added in rank order (reproducible).
  void sumInRankOrder(std::span<double> values) const;
  // The message of the lowest rank that has one, on every rank (nothing when none has): how a
  // failure found on one rank stops all of them with the same diagnosis.
  std::string firstMessage(const std::string& mine) const;
};

// One rank: every collective is the identity.
class SerialCommunicator final : public Communicator {
 public:
  int rank() const override { return 0; }
  int size() const override { return 1; }
  std::vector<Bytes> allGather(std::span<const std::byte> mine) const override {
    return {Bytes(mine.begin(), mine.end())};
  }
  std::vector<Bytes> exchange(const std::vector<Bytes>& toRank) const override { return toRank; }
  std::vector<Bytes> exchangeWith(std::span<const int> to, const std::vector<Bytes>& payloads,
                                  std::span<const int> from) const override {
    return !to.empty() && !from.empty() ? payloads : std::vector<Bytes>(from.size());
  }
  std::unique_ptr<PendingExchange> startExchangeWith(std::span<const int> to, std::vector<Bytes> payloads,
                                                     std::span<const int> from,
                                                     std::span<const std::size_t>) const override;
  std::vector<Bytes> gatherToRoot(std::span<const std::byte> mine) const override {
    return allGather(mine);
  }
  void sumInPlace(std::span<std::uint64_t>) const override {}
  void minInPlace(std::span<double>) const override {}
  void maxInPlace(std::span<double>) const override {}
  std::shared_ptr<const Communicator> split(int) const override {
    return std::make_shared<SerialCommunicator>();
  }
};

// The communicator a run uses when none is given: all of MPI_COMM_WORLD when this build has MPI
// and MPI is initialised (MpiSession), one serial rank otherwise.
std::shared_ptr<const Communicator> worldCommunicator();
// True when this build was made with MPI (EJECTA_HAVE_MPI).
bool builtWithMpi();

// Initialises MPI for the life of the object (funnelled threads: MPI is called from the OpenMP
// master thread only) and finalises it after. Without MPI it does nothing. One per process,
// made by main().
class MpiSession {
 public:
  MpiSession(int* argc, char*** argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  // Ends every rank at once with `code` (an error on one rank that the others cannot see would
  // leave them waiting in a collective). Returns only without MPI.
  static void abortAll(int code);
};

// Plain-data (de)serialisation for collective payloads.
template <typename T>
void appendBytes(Bytes& out, const T* values, std::size_t count) {
  const auto* b = reinterpret_cast<const std::byte*>(values);
  out.insert(out.end(), b, b + count * sizeof(T));
}
template <typename T>
std::vector<T> fromBytes(const Bytes& in) {
  std::vector<T> out(in.size() / sizeof(T));
  if (!out.empty()) std::copy(in.begin(), in.begin() + static_cast<std::ptrdiff_t>(out.size() * sizeof(T)),
                              reinterpret_cast<std::byte*>(out.data()));
  return out;
}

}  // namespace ejecta
