// Benz & Asphaug flaw seeding: two passes over one replayable random stream (count, then fill),
// so the only memory beyond the flaws themselves is O(N).
#include "sim/solid/weibull_flaws.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace ejecta {
namespace {

// splitmix64 (Steele, Lea & Flood 2014): turns the 64-bit seed into xoshiro's 256-bit state. It
// is a bijection of a counter, so four consecutive outputs are never all zero (xoshiro's one bad
// state).
std::uint64_t splitmix64(std::uint64_t& x) {
  std::uint64_t z = (x += 0x9e3779b97f4a7c15);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9;
  z = (z ^ (z >> 27)) * 0x94d049bb133111eb;
  return z ^ (z >> 31);
}

// xoshiro256** 1.0 (Blackman & Vigna): fixed integer arithmetic, hence the same stream everywhere.
class Xoshiro256StarStar {
 public:
  explicit Xoshiro256StarStar(std::uint64_t seed) {
    for (auto& word : s_) word = splitmix64(seed);
  }
  std::uint64_t operator()() {
    const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = rotl(s_[3], 45);
    return result;
  }

 private:
  static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  std::array<std::uint64_t, 4> s_{};
};

// Uniform particle index in [0, n), n >= 1, without bias (Lemire 2019): the high half of
// r * n for 32 random bits r is the index; products whose low half is below 2^32 mod n are the
// surplus that would favour some indices, and are drawn again.
class UniformIndex {
 public:
  UniformIndex(std::uint64_t seed, std::uint32_t n)
      : rng_(seed), n_(n), reject_((std::uint32_t{0} - n) % n) {}
  std::uint32_t operator()() {
    std::uint64_t product;
    do {
      product = (rng_() >> 32) * n_;  // the high bits are xoshiro's best
    } while (static_cast<std::uint32_t>(product) < reject_);
    return static_cast<std::uint32_t>(product >> 32);
  }

 private:
  Xoshiro256StarStar rng_;
  std::uint64_t n_;
  std::uint32_t reject_;
};

template <typename... Parts>
std::string message(const Parts&... parts) {
  std::ostringstream s;
  s.precision(17);
  (s << ... << parts);
  return s.str();
}

void requirePositiveFinite(double value, const char* what) {
  if (!(std::isfinite(value) && value > 0.0))
    throw std::invalid_argument(message("distributeFlaws: ", what, " = ", value,
                                        " must be positive and finite"));
}

}  // namespace

FlawTable::FlawTable(std::vector<std::size_t> offset, std::vector<double> threshold)
    : offset_(std::move(offset)), threshold_(std::move(threshold)) {
  if (offset_.empty() || offset_.front() != 0 || offset_.back() != threshold_.size())
    throw std::invalid_argument(
        message("FlawTable: offset must have numParticles + 1 entries running from 0 to the ",
                "number of thresholds (", threshold_.size(), ")"));
  for (std::size_t i = 0; i + 1 < offset_.size(); ++i) {
    if (offset_[i + 1] < offset_[i])
      throw std::invalid_argument(message("FlawTable: offset decreases at particle ", i));
    const auto row = thresholds(i);
    if (std::any_of(row.begin(), row.end(), [](double t) { return std::isnan(t); }) ||
        !std::is_sorted(row.begin(), row.end()))
      throw std::invalid_argument(
          message("FlawTable: thresholds of particle ", i, " are not ascending numbers"));
  }
}

std::uint32_t FlawTable::activeCount(std::size_t i, double strain) const {
  const auto row = thresholds(i);
  const auto end =
      std::partition_point(row.begin(), row.end(), [strain](double t) { return t <= strain; });
  return static_cast<std::uint32_t>(end - row.begin());
}

FlawTable distributeFlaws(std::span<const double> volumes, WeibullParameters w,
                          std::uint64_t seed, std::uint32_t maxFlaws) {
  requirePositiveFinite(w.k, "Weibull k [m^-3]");
  requirePositiveFinite(w.m, "Weibull m");
  if (volumes.empty())
    throw std::invalid_argument("distributeFlaws: volumes is empty; a flawed region needs at "
                                "least one particle");

  // V = sum of volumes, compensated (Neumaier) so that millions of similar terms lose nothing;
  // a fixed serial order keeps it reproducible.
  double total = 0.0, compensation = 0.0;
  for (std::size_t i = 0; i < volumes.size(); ++i) {
    const double v = volumes[i];
    if (!(std::isfinite(v) && v > 0.0))
      throw std::invalid_argument(message("distributeFlaws: volumes[", i, "] = ", v,
                                          " must be positive and finite"));
    const double sum = total + v;
    compensation += std::abs(total) >= v ? (total - sum) + v : (v - sum) + total;
    total = sum;
  }
  total += compensation;
  const double kV = w.k * total;
  if (!(std::isfinite(kV) && kV > 0.0))
    throw std::invalid_argument(message("distributeFlaws: Weibull k times the total volume = ",
                                        w.k, " * ", total, " must be positive and finite"));

  // The coupon collector needs N H_N ~ N (ln N + gamma) + 1/2 draws on average; refuse before
  // allocating when that is past the limit.
  const std::size_t n = volumes.size();
  const double expected =
      static_cast<double>(n) * (std::log(static_cast<double>(n)) + 0.5772156649015329) + 0.5;
  if (n > maxFlaws || expected > static_cast<double>(maxFlaws))
    throw std::length_error(message("distributeFlaws: ", n, " particles need about ", expected,
                                    " flaws (N ln N), more than maxFlaws = ", maxFlaws));

  // Pass 1: draw the particle of flaw j = 1, 2, ... until every particle has one, counting flaws
  // per particle in offset[i + 1].
  std::vector<std::size_t> offset(n + 1, 0);
  std::size_t numFlaws = 0, covered = 0;
  UniformIndex draw(seed, static_cast<std::uint32_t>(n));
  while (covered < n) {
    if (numFlaws == maxFlaws)
      throw std::length_error(message("distributeFlaws: ", n, " particles still lack flaws after ",
                                      "maxFlaws = ", maxFlaws, " draws"));
    ++numFlaws;
    if (offset[draw() + 1]++ == 0) ++covered;
  }
  std::partial_sum(offset.begin(), offset.end(), offset.begin());  // row starts and ends

  // Pass 2: replay the same stream and drop j into the next free slot of its particle. Rows fill
  // in increasing j, so each comes out ascending without a sort.
  std::vector<double> threshold(numFlaws);
  std::vector<std::size_t> next(offset.begin(), offset.end() - 1);
  UniformIndex replay(seed, static_cast<std::uint32_t>(n));
  for (std::size_t j = 1; j <= numFlaws; ++j) threshold[next[replay()]++] = static_cast<double>(j);

  // j -> eps_j, element by element, so the result does not depend on the number of threads.
  const auto count = static_cast<std::ptrdiff_t>(numFlaws);
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t f = 0; f < count; ++f)
    threshold[f] = weibullStrainForCount(w, total, threshold[f]);

  return FlawTable(std::move(offset), std::move(threshold));
}

}  // namespace ejecta
