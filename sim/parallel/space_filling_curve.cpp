#include "sim/parallel/space_filling_curve.hpp"

#include <algorithm>
#include <cmath>

namespace ejecta {

std::uint64_t hilbertKey(std::array<std::uint32_t, 3> cell, int dimension) {
  const int n = dimension, bits = hilbertBits(dimension);
  if (n == 1) return cell[0];
  // Skilling (2004): undo the excess work of the Gray code axis by axis, then Gray-encode; the
  // result is the "transpose" form, whose bits interleaved (most significant first) are the key.
  std::array<std::uint32_t, 3>& x = cell;
  const std::uint32_t top = 1u << (bits - 1);
  for (std::uint32_t q = top; q > 1; q >>= 1) {
    const std::uint32_t lower = q - 1;
    for (int i = 0; i < n; ++i) {
      if (x[static_cast<std::size_t>(i)] & q) {
        x[0] ^= lower;  // invert the lower bits of the first axis
      } else {           // exchange the lower bits of the first axis and axis i
        const std::uint32_t t = (x[0] ^ x[static_cast<std::size_t>(i)]) & lower;
        x[0] ^= t;
        x[static_cast<std::size_t>(i)] ^= t;
      }
    }
  }
  for (int i = 1; i < n; ++i) x[static_cast<std::size_t>(i)] ^= x[static_cast<std::size_t>(i - 1)];
  std::uint32_t t = 0;
  for (std::uint32_t q = top; q > 1; q >>= 1)
    if (x[static_cast<std::size_t>(n - 1)] & q) t ^= q - 1;
  for (int i = 0; i < n; ++i) x[static_cast<std::size_t>(i)] ^= t;
  std::uint64_t key = 0;
  for (int b = bits - 1; b >= 0; --b)
    for (int i = 0; i < n; ++i) key = (key << 1) | ((x[static_cast<std::size_t>(i)] >> b) & 1u);
  return key;
}

std::vector<std::uint64_t> hilbertKeys(const ParticleSet& p, std::size_t count, const KeyBox& box,
                                       int dimension) {
  const int bits = hilbertBits(dimension);
  const double cells = std::ldexp(1.0, bits);
  std::array<double, 3> scale{};
  for (int d = 0; d < dimension; ++d) {
    const double extent = box.hi[static_cast<std::size_t>(d)] - box.lo[static_cast<std::size_t>(d)];
    scale[static_cast<std::size_t>(d)] = extent > 0.0 ? cells / extent : 0.0;
  }
  std::vector<std::uint64_t> keys(count);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < count; ++i) {
    std::array<std::uint32_t, 3> cell{};
    std::uint64_t key1d = 0;
    for (int d = 0; d < dimension; ++d) {
      const std::size_t a = static_cast<std::size_t>(d);
      const double c = std::clamp((p.x[a][i] - box.lo[a]) * scale[a], 0.0, cells - 1.0);
      if (dimension == 1) key1d = static_cast<std::uint64_t>(c);
      else cell[a] = static_cast<std::uint32_t>(c);
    }
    keys[i] = dimension == 1 ? key1d : hilbertKey(cell, dimension);
  }
  return keys;
}

}  // namespace ejecta
