#pragma once
// The memory a scene's run will need, estimated from its bodies before any particle is built
// (core/machine_memory.hpp refuses what cannot fit).
#include "sim/setup/scene.hpp"

namespace ejecta {

struct RunMemoryEstimate {
  double particles = 0.0;  // upper estimate: each body's lattice over its shape, voids not cut
  double bytes = 0.0;
};

// Bytes per particle of a run, measured as the slope of peak resident memory against particle
// count (bench/memory.cpp, `ejecta_bench_memory`, two spacings each): 1.16 kB for the 3D Sedov
// (hydro), 1.28 kB for the 3D oblique impact over 20 us (strength, damage, three materials;
// 1.62 kB by hand over longer runs). 2 kB covers both with the ghosts of walls and mirrors.
inline constexpr double kBytesPerParticle = 2048.0;
// Godunov SPH (sph.dissipation = "riemann") adds the star states of the pairs that both sides sum
// (sim/sph/shared_pair_stars.hpp, 36 bytes a pair and half the neighbours a particle), measured
// the same way against the viscosity's run: +1,160 bytes per particle for the 3D Sedov (2,485
// against 1,325) and +412 for the 2D one (1,163 against 751; `ejecta_bench_memory --scene
// verification/sedov_2d --spacings 0.01,0.005 --set sph.dissipation=riemann`). By dimension:
inline constexpr double kRiemannBytesPerParticle[4] = {0.0, 100.0, 450.0, 1200.0};

// A run's bytes per particle: kBytesPerParticle and what its options add.
double bytesPerParticle(const Scene& scene);

RunMemoryEstimate estimateRunMemory(const Scene& scene);

// Throws InputError naming the scene file when the run would not fit in this machine's memory
// (split over `ranks` ranks, which may share a machine: the estimate is per rank).
void requireRunMemory(const Scene& scene, int ranks = 1);

}  // namespace ejecta
