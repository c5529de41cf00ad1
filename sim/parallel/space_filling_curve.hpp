#pragma once
// Hilbert keys: positions in a box mapped to one 64-bit number so that particles close on the
// curve are close in space (the curve never jumps, unlike Morton order), which keeps a rank's
// contiguous key range compact and its halo small. Skilling's transpose construction
// (J. Skilling, "Programming the Hilbert curve", AIP Conf. Proc. 707, 381 (2004)) in 1, 2 or
// 3 dimensions: 63, 31 and 21 bits per axis.
#include <array>
#include <cstdint>
#include <vector>

#include "sim/state/particles.hpp"

namespace ejecta {

struct KeyBox {
  std::array<double, 3> lo{};
  std::array<double, 3> hi{};
};

// Bits per axis of a dimension's keys.
constexpr int hilbertBits(int dimension) { return dimension == 1 ? 63 : dimension == 2 ? 31 : 21; }

// The key of integer cell coordinates (each below 2^hilbertBits(D)).
std::uint64_t hilbertKey(std::array<std::uint32_t, 3> cell, int dimension);

// Keys of particles [0, count) in `box` (positions outside it are clamped to its faces).
std::vector<std::uint64_t> hilbertKeys(const ParticleSet& p, std::size_t count, const KeyBox& box,
                                       int dimension);

}  // namespace ejecta
