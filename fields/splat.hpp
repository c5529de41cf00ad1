#pragma once
// SPH interpolation of particle fields onto a sparse lattice, with the run's own kernel:
//   channel 0:      S(x)   = sum_j V_j W(|x - x_j|, h_j)        (the filled volume fraction)
//   channel c >= 1: F_c(x) = sum_j V_j f_c,j W(|x - x_j|, h_j)
// where V_j = m_j / rho_j (2D planar: area, mass being per metre depth; RZ: the 2D kernel with
// V_j = m_j / (2 pi r_j rho_j), ring mass over circumference). F_c is the plain SPH estimate of
// f_c, F_c / S its Shepard-normalised form. Only voxels inside some particle's support exist.
// Deterministic for any thread count: every block sums its particles in index order.
#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "fields/sparse_lattice.hpp"
#include "sim/setup/scene.hpp"

namespace ejecta::fields {

struct SplatSource {
  int dims = 3;                       // 2 or 3: the kernel's dimension and the lattice's
  KernelKind kernel = KernelKind::CubicSpline;
  std::size_t count = 0;
  std::array<const double*, 3> x{};   // positions [m] (2D: x[0], x[1])
  const double* h = nullptr;          // smoothing lengths [m]
  const double* volume = nullptr;     // V_j [m^3] (2D: [m^2])
  // RZ: add each particle's mirror image across the axis (x[0] -> -x[0]) where its support
  // crosses it, so that sums near the axis are complete.
  bool mirrorAxis = false;
};

// A box of voxel indices, inclusive at both ends; voxels outside are not produced.
struct VoxelBox {
  Index3 lo{}, hi{};
  bool contains(int i, int j, int k) const {
    return i >= lo[0] && i <= hi[0] && j >= lo[1] && j <= hi[1] && k >= lo[2] && k <= hi[2];
  }
};

// Splats `values` (each `source.count` long) onto a lattice of spacing `voxel`; the result has
// values.size() + 1 channels as above. Blocks where no voxel centre is inside any support are
// dropped. Throws std::invalid_argument for a non-positive voxel or h.
SparseLattice splat(const SplatSource& source, const std::vector<const double*>& values,
                    double voxel, const std::optional<VoxelBox>& clip = std::nullopt);

}  // namespace ejecta::fields
