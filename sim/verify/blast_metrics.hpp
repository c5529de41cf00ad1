#pragma once
// A blast's particles measured against the Sedov-Taylor solution: the shock's radius and peak
// from a binned radial profile, and the pressure of the hot centre. Shared by `ejecta verify`'s
// Sedov problems and ejecta_bench_sedov, so the README's table and the benchmark read the same
// numbers.
#include <array>
#include <cstddef>

#include "sim/exact/sedov.hpp"
#include "sim/state/particles.hpp"

namespace ejecta::verify {

// Distance of particle i from the blast centre `c` in the first `dim` coordinates.
double blastDistance(const ParticleSet& p, std::size_t i, const std::array<double, 3>& c, int dim);

// The shock: the centre of the radial bin (width `binWidth`, out to `rMax`) with the highest
// mass-weighted mean density, and that density; and the shell's peak pressure, the highest
// mass-weighted mean pressure of the bins from half to one and a half times that radius (not the
// densest bin's: in a smeared shell the pressure peaks a little behind the density; and not the
// centre's, whose own measure is centrePressureRatio: a hot 3D centre reads 1.5x the jump).
struct BlastShock {
  double radius = 0.0;
  double density = 0.0;
  double pressure = 0.0;
};
BlastShock blastShock(const ParticleSet& p, const std::array<double, 3>& centre, int dim,
                      double binWidth, double rMax);

// The hot centre (issue 19): the median of P / P_exact(r) over the `count` particles nearest the
// blast centre. The exact pressure there is nearly flat (a fraction of the jump) while the
// density falls to zero, so a scheme that heats the centre's walls or keeps too much mass there
// reads above 1. The innermost particles, not a fixed radius: the centre empties as the blast
// runs (none is left within a quarter of the shock radius in sedov_3d at 46k), and the median
// because a few particles left in the near-vacuum carry extreme ratios. 0 without particles.
double centrePressureRatio(const ParticleSet& p, const std::array<double, 3>& centre, int dim,
                           const exact::SedovSolution& sedov, double time, std::size_t count = 32);

}  // namespace ejecta::verify
