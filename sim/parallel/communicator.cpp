#include "sim/parallel/communicator.hpp"

namespace ejecta {

void Communicator::sumInRankOrder(std::span<double> values) const {
  if (size() == 1) return;
  Bytes mine;
  appendBytes(mine, values.data(), values.size());
  const std::vector<Bytes> all = allGather(mine);
  for (double& v : values) v = 0.0;
  for (const Bytes& rankBytes : all) {
    const std::vector<double> theirs = fromBytes<double>(rankBytes);
    for (std::size_t k = 0; k < values.size() && k < theirs.size(); ++k) values[k] += theirs[k];
  }
}

std::string Communicator::firstMessage(const std::string& mine) const {
  if (size() == 1) return mine;
  // Only ranks with a message send one; the common case (none) costs one small reduction.
  const std::uint64_t count = sum(mine.empty() ? 0 : 1);
  if (count == 0) return {};
  Bytes bytes;
  appendBytes(bytes, mine.data(), mine.size());
  for (const Bytes& b : allGather(bytes))
    if (!b.empty()) return std::string(reinterpret_cast<const char*>(b.data()), b.size());
  return {};
}

}  // namespace ejecta

namespace ejecta {

namespace {

// One rank sends to itself only: the payloads are what arrives, already.
class ImmediateExchange final : public Communicator::PendingExchange {
 public:
  explicit ImmediateExchange(std::vector<Bytes> arrived) : arrived_(std::move(arrived)) {}
  std::vector<Bytes> finish() override { return std::move(arrived_); }

 private:
  std::vector<Bytes> arrived_;
};

}  // namespace

std::unique_ptr<Communicator::PendingExchange> SerialCommunicator::startExchangeWith(
    std::span<const int> to, std::vector<Bytes> payloads, std::span<const int> from,
    std::span<const std::size_t>) const {
  return std::make_unique<ImmediateExchange>(!to.empty() && !from.empty() ? std::move(payloads)
                                                                          : std::vector<Bytes>(from.size()));
}

}  // namespace ejecta
