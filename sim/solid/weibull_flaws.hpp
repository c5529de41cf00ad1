#pragma once
// Flaw population of the Grady-Kipp fracture model as set up by Benz & Asphaug (1994, Icarus
// 107, 98; 1995, Comput. Phys. Commun. 87, 253).
//
// Weibull: the number of flaws per unit volume that activate at a tensile strain <= eps is
//   n(eps) = k eps^m.
// Benz & Asphaug realise this on N particles of total volume V deterministically in threshold and
// randomly in place: for j = 1, 2, 3, ... the j-th weakest flaw of the whole body has activation
// strain
//   eps_j = (j / (k V))^(1/m)          (so exactly floor(k V eps^m) flaws have eps_j <= eps)
// and is given to a particle drawn uniformly at random; flaws are assigned until every particle
// holds at least one. That is the coupon collector: about N (ln N + 0.577) flaws, ~ln N a particle.
//
// Equal volumes. A uniform draw gives particle i an expected k (V/N) eps^m flaws below eps, which
// is the Weibull k V_i eps^m only where V_i = V/N. Benz & Asphaug, miluphcuda's weibullit.c and
// Spheral's Benz-Asphaug seeding all draw uniformly, which suits near-equal volumes; where volumes
// differ strongly, small particles get too many flaws for their size (Spheral's Owen and
// probabilistic damage models exist for that case).
//
// Two-dimensional (planar) runs. No peer code we found has a separate 2D Weibull law: they keep
// k as a number per unit volume and put the 2D "volume" (the area) into k V:
//   - miluphcuda, test_cases/tensile_rod/input/create_2D_rod.py (2D tensile rod; Schaefer 2005,
//     Schaefer et al. 2016, Sect. 4.1): eps = (i / (k * area))^(1/m), area = length x width in
//     the run's units, k unchanged. Its 3D tool test_cases/nakamura/input/weibullit.c uses
//     V = sum m/rho the same way.
//   - Spheral, src/Damage/weibullFlawDistributionBenzAsphaug.cc: V = sum m/rho, which is an area
//     in 2D, times an optional `volumeStretchFactor` (default 1), documented in
//     src/Damage/GradyKippTensorDamage.py as "useful for reduced dimensional (1D or 2D) problems".
//     Its 2D tensile rod (tests/functional/Damage/TensileRod/TensileRod-2d.py) keeps it at 1.
// So the de facto rule is a slab one length unit deep. Here volumes are per metre of depth (area
// x 1 m), the same rule in SI. The choice is not neutral: thresholds scale as depth^(-1/m), so a
// depth of 1 cm instead of 1 m raises every threshold by 100^(1/m) (x1.7 for m = 8.5). A caller
// who wants another depth scales the volumes; no 2D special case is made here.
//
// Random numbers. Portable and exact: xoshiro256** (Blackman & Vigna 2021, ACM TOMS 47, 36)
// seeded through splitmix64 as its authors recommend, and particle indices drawn with Lemire's
// unbiased multiply-and-reject (Lemire 2019, ACM TOMACS 29, 3). No <random> distribution is used,
// because their algorithms are implementation-defined. Which flaws go to which particle is thus
// bit-identical on every platform and thread count. The threshold values come from std::pow; one
// libm gives the same bits for every thread count, but two libms may differ in the last place,
// because IEEE 754 does not require pow to be correctly rounded.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace ejecta {

struct WeibullParameters {
  double k = 0.0;  // flaw number density coefficient [m^-3]
  double m = 0.0;  // Weibull modulus [-]
};

// Expected number of flaws with activation strain <= strain in a volume: k V strain^m.
inline double weibullExpectedCount(WeibullParameters w, double volume, double strain) {
  return w.k * volume * std::pow(strain, w.m);
}

// The strain at which that expected number reaches `count`: (count / (k V))^(1/m). With
// count = j and V the total volume this is the Benz-Asphaug threshold eps_j.
inline double weibullStrainForCount(WeibullParameters w, double volume, double count) {
  return std::pow(count / (w.k * volume), 1.0 / w.m);
}

// Activation strains of every particle's flaws, compressed-row: particle i owns
// threshold[offset[i] .. offset[i+1]), ascending.
//
// Thresholds are double, not float: they are compared with strains held in double, and with
// ~N ln N flaws consecutive global thresholds differ by only ~1 / (m N ln N) relatively (1e-8 at
// N = 1e6), below float resolution, so float would merge neighbouring flaws. The cost is
// 8 (ln N + 0.58) bytes a particle, ~115 MB for 1e6 particles; float would halve it.
class FlawTable {
 public:
  FlawTable() = default;
  // From stored rows (e.g. a restart). Throws std::invalid_argument unless offset has N + 1 >= 1
  // entries, starts at 0, ends at threshold.size(), never decreases, and every row is ascending.
  FlawTable(std::vector<std::size_t> offset, std::vector<double> threshold);

  std::size_t numParticles() const { return offset_.empty() ? 0 : offset_.size() - 1; }
  std::size_t numFlaws() const { return threshold_.size(); }

  std::span<const double> thresholds(std::size_t i) const {
    return {threshold_.data() + offset_[i], threshold_.data() + offset_[i + 1]};
  }
  std::uint32_t count(std::size_t i) const {
    return static_cast<std::uint32_t>(offset_[i + 1] - offset_[i]);
  }
  // Number of flaws of particle i with threshold <= strain (binary search). A NaN strain
  // activates none: every comparison with it is false.
  std::uint32_t activeCount(std::size_t i, double strain) const;

  // The raw rows, for output and restarts.
  std::span<const std::size_t> offsets() const { return offset_; }
  std::span<const double> allThresholds() const { return threshold_; }

  bool operator==(const FlawTable&) const = default;

 private:
  std::vector<std::size_t> offset_;  // numParticles() + 1 entries
  std::vector<double> threshold_;    // numFlaws() entries
};

// Flaws beyond this abort distributeFlaws: 2^31 doubles are 16 GiB, far past any run this code
// makes (N ln N reaches it near N = 1e8), so hitting it means the input is wrong.
inline constexpr std::uint32_t kDefaultMaxFlaws = std::uint32_t{1} << 31;

// Benz & Asphaug flaws for the particles of one flawed region, V = sum of volumes.
// volumes: the volume of each particle (2D: area x 1 m, see above), in the order the caller
// indexes by. seed: the same volumes, parameters and seed give the same table.
// Throws std::invalid_argument for k or m not positive and finite, no particles, a volume not
// positive and finite, or k V not finite and positive; std::length_error when the expected
// N (ln N + 0.577) flaws exceed maxFlaws, or the draw actually reaches maxFlaws.
FlawTable distributeFlaws(std::span<const double> volumes, WeibullParameters w,
                          std::uint64_t seed, std::uint32_t maxFlaws = kDefaultMaxFlaws);

}  // namespace ejecta
