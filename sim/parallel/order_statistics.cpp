#include "sim/parallel/order_statistics.hpp"

#include <array>
#include <bit>
#include <stdexcept>
#include <string>
#include <vector>

namespace ejecta {

namespace {

// A key whose unsigned order is the order of the doubles (negative ones reversed below the
// positive ones; -0 just below +0).
std::uint64_t orderKey(double x) {
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(x);
  return bits >> 63 ? ~bits : bits | (std::uint64_t{1} << 63);
}

double fromOrderKey(std::uint64_t key) {
  return std::bit_cast<double>(key >> 63 ? key & ~(std::uint64_t{1} << 63) : ~key);
}

}  // namespace

double kthSmallest(std::span<const double> values, std::uint64_t k, const Communicator& ranks) {
  const std::uint64_t total = ranks.sum(values.size());
  if (k >= total)
    throw std::out_of_range("kthSmallest: index " + std::to_string(k) + " of " +
                            std::to_string(total) + " values");
  std::vector<std::uint64_t> keys(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) keys[i] = orderKey(values[i]);
  // Invariant: the answer's key starts with `prefix` (its top `known` bits), and k counts from
  // the first value with that prefix.
  std::uint64_t prefix = 0;
  for (int known = 0; known < 64; known += 8) {
    const int shift = 56 - known;
    std::array<std::uint64_t, 256> bins{};
    for (const std::uint64_t key : keys)
      if (known == 0 || key >> (64 - known) == prefix >> (64 - known)) ++bins[(key >> shift) & 0xff];
    ranks.sumInPlace(bins);
    std::uint64_t bin = 0;
    while (k >= bins[bin]) k -= bins[bin++];
    prefix |= bin << shift;
  }
  return fromOrderKey(prefix);
}

double upperMedian(std::span<const double> values, const Communicator& ranks) {
  return kthSmallest(values, ranks.sum(values.size()) / 2, ranks);
}

}  // namespace ejecta
