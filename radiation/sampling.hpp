#pragma once
// Sample points for the ray casting: 4 coordinates in (0, 1) per ray (2 place the ray on the
// receiver, 2 choose its direction), either
//   - Sobol' points (I. M. Sobol', USSR Comput. Math. Math. Phys. 7, 86 (1967)) with the
//     direction numbers of S. Joe and F. Y. Kuo, SIAM J. Sci. Comput. 30, 2635 (2008) (file
//     new-joe-kuo-6.21201, dimensions 1-4), each replicate randomised by a nested uniform
//     (Owen) scramble in the hash-based form of B. Burley, "Practical Hash-based Owen
//     Scrambling", JCGT 9(4), 2020 (itself after Laine and Karras 2011). A scrambled Sobol'
//     replicate is an unbiased estimate, and independent replicates give an honest standard
//     error while keeping the quasi-random stratification; or
//   - independent uniform random numbers from a counter-based hash (for comparison).
// Both are pure functions of (seed, stream, replicate, index): no state, so any thread can
// produce any point and results do not depend on the thread count.
//
// Maps from the unit square: area-uniform points on a triangle, cosine-weighted directions
// (Shirley-Chiu concentric disc lifted to the hemisphere, "Malley's method"), uniform directions
// on the sphere.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace ejecta::radiation::sampling {

// SplitMix64's finaliser (Steele, Lea and Flood, OOPSLA 2014): a bijective 64-bit mixer.
inline std::uint64_t mix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

// A key for stream `b` under key `a`: distinct (a, b) give unrelated keys.
inline std::uint64_t combine(std::uint64_t a, std::uint64_t b) { return mix64(a ^ mix64(b)); }

inline std::uint32_t reverseBits(std::uint32_t x) {
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
  x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
  return (x >> 16) | (x << 16);
}

// Nested uniform scramble of a 32-bit fraction: bit k (from the most significant) is flipped by
// a hash of the bits above it and the seed. With the bits reversed, "above" becomes "below", and
// adding the seed or xoring with x times an even constant only lets low bits change high ones.
// Constants: Burley 2020, section 4.
inline std::uint32_t owenScramble(std::uint32_t x, std::uint32_t seed) {
  x = reverseBits(x);
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return reverseBits(x);
}

inline constexpr int kDimensions = 4;

// Direction numbers v_k = m_k 2^(32-k), k = 1..32, of the first four Sobol' dimensions.
// Dimension 1: all m_k = 1 (van der Corput). Then (degree s, coefficients a, initial m):
// (1, 0, {1}), (2, 1, {1, 3}), (3, 1, {1, 3, 1}) (Joe and Kuo 2008).
inline constexpr std::array<std::array<std::uint32_t, 32>, kDimensions> sobolDirections() {
  std::array<std::array<std::uint32_t, 32>, kDimensions> v{};
  struct Poly {
    int s;
    unsigned a;
    std::array<std::uint32_t, 3> m;
  };
  constexpr std::array<Poly, 3> polys{{{1, 0u, {1, 0, 0}}, {2, 1u, {1, 3, 0}}, {3, 1u, {1, 3, 1}}}};
  for (int k = 0; k < 32; ++k) v[0][k] = 1u << (31 - k);
  for (int d = 1; d < kDimensions; ++d) {
    const Poly& p = polys[d - 1];
    for (int k = 0; k < p.s; ++k) v[d][k] = p.m[k] << (31 - k);
    for (int k = p.s; k < 32; ++k) {
      std::uint32_t x = v[d][k - p.s] ^ (v[d][k - p.s] >> p.s);
      for (int l = 1; l < p.s; ++l)
        if ((p.a >> (p.s - 1 - l)) & 1u) x ^= v[d][k - l];
      v[d][k] = x;
    }
  }
  return v;
}

inline constexpr std::array<std::array<std::uint32_t, 32>, kDimensions> kSobolV = sobolDirections();

// The unscrambled Sobol' point `index` in dimension d, as a 32-bit fraction.
inline std::uint32_t sobol(std::uint32_t index, int d) {
  std::uint32_t x = 0;
  for (int k = 0; index != 0; ++k, index >>= 1)
    if (index & 1u) x ^= kSobolV[d][k];
  return x;
}

// A 32-bit fraction to a double strictly inside (0, 1).
inline double toUnit(std::uint32_t x) { return (static_cast<double>(x) + 0.5) * 0x1p-32; }

enum class Sampler { Sobol, Random };

// Points of one replicate: `key` identifies (seed, receiver, replicate). Sobol: the scrambled
// Sobol' sequence (its first 2^m points form a (t, m, 4)-net); Random: independent uniforms.
struct PointSet {
  Sampler sampler = Sampler::Sobol;
  std::array<std::uint32_t, kDimensions> scramble{};
  std::uint64_t key = 0;

  PointSet(Sampler s, std::uint64_t replicateKey) : sampler(s), key(replicateKey) {
    for (int d = 0; d < kDimensions; ++d)
      scramble[d] = static_cast<std::uint32_t>(combine(replicateKey, 0x5eedull + d));
  }

  // Points first .. first + count - 1 of the replicate into u. Sobol: in Gray-code order
  // (Antonov and Saleev 1979): consecutive points differ by one direction number, 4 xors a
  // point instead of a loop over the index's bits. The order differs from point(), the set does
  // not: for `first` a multiple of a power of two >= count, or any range [2^j, 2^(j+1)), Gray
  // code permutes the range onto itself.
  void block(std::uint32_t first, int count, double (*u)[kDimensions]) const {
    if (sampler != Sampler::Sobol) {
      for (int i = 0; i < count; ++i) point(first + static_cast<std::uint32_t>(i), u[i]);
      return;
    }
    std::uint32_t x[kDimensions];
    const std::uint32_t g = first ^ (first >> 1);
    for (int d = 0; d < kDimensions; ++d) x[d] = sobol(g, d);
    for (int i = 0; i < count; ++i) {
      if (i > 0) {
        const int bit = std::countr_zero(first + static_cast<std::uint32_t>(i));
        for (int d = 0; d < kDimensions; ++d) x[d] ^= kSobolV[d][bit];
      }
      for (int d = 0; d < kDimensions; ++d) u[i][d] = toUnit(owenScramble(x[d], scramble[d]));
    }
  }

  // Fills u[0..3] for point `index`.
  void point(std::uint32_t index, double (&u)[kDimensions]) const {
    if (sampler == Sampler::Sobol) {
      for (int d = 0; d < kDimensions; ++d) u[d] = toUnit(owenScramble(sobol(index, d), scramble[d]));
    } else {
      const std::uint64_t a = combine(key, 2ull * index), b = combine(key, 2ull * index + 1);
      u[0] = toUnit(static_cast<std::uint32_t>(a));
      u[1] = toUnit(static_cast<std::uint32_t>(a >> 32));
      u[2] = toUnit(static_cast<std::uint32_t>(b));
      u[3] = toUnit(static_cast<std::uint32_t>(b >> 32));
    }
  }
};

// Barycentric weights (w0, w1, w2) of an area-uniform point of a triangle.
inline std::array<double, 3> squareToTriangle(double u, double v) {
  const double s = std::sqrt(u);
  return {1.0 - s, s * (1.0 - v), s * v};
}

// Shirley-Chiu concentric map of the unit square onto the unit disc (area preserving, low
// distortion, so stratification survives).
inline std::array<double, 2> squareToDisc(double u, double v) {
  const double a = 2.0 * u - 1.0, b = 2.0 * v - 1.0;
  if (a == 0.0 && b == 0.0) return {0.0, 0.0};
  constexpr double q = 0.25 * std::numbers::pi;
  double r, phi;
  if (std::abs(a) > std::abs(b)) {
    r = a;
    phi = q * (b / a);
  } else {
    r = b;
    phi = 2.0 * q - q * (a / b);
  }
  return {r * std::cos(phi), r * std::sin(phi)};
}

// Cosine-weighted direction about +z in local coordinates (x, y, z), z > 0.
inline std::array<double, 3> squareToCosineHemisphere(double u, double v) {
  const auto d = squareToDisc(u, v);
  const double z = std::sqrt(std::max(0.0, 1.0 - d[0] * d[0] - d[1] * d[1]));
  return {d[0], d[1], z};
}

// Uniform direction on the unit sphere.
inline std::array<double, 3> squareToSphere(double u, double v) {
  const double z = 1.0 - 2.0 * u;
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  const double phi = 2.0 * std::numbers::pi * v;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

}  // namespace ejecta::radiation::sampling
