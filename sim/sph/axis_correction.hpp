#pragma once
// RZ near-axis correction. With mirror ghosts across the axis, the 2D kernel sum of ring masses
//   eta*_i = sum_j m_j W(x_i - x_j, h_i)
// estimates 2 pi rho times the kernel-smoothed |r| at particle i, not 2 pi rho r_i. Dividing by
// the smoothed radius instead of r,
//   rho_i = eta*_i / (2 pi rt_i),   rt_i = h_i I(r_i / h_i),   I(xi) = integral |xi - s| Wp(s) ds
// (Wp: the kernel projected onto the r axis) gives the right density for uniform matter at every
// distance from the axis, and rt -> r beyond one kernel support (I(xi) = xi for xi >= 2). This is
// the correction of Garcia-Senz et al. (2009, MNRAS 392, 346) in a kernel-independent form: I is
// tabulated at start-up by quadrature for whichever kernel the scene uses. The Lagrangian
// derivation with rt in place of r keeps energy conservation exact (see docs/rz.md).
#include <vector>

#include "sim/sph/sph_options.hpp"
#include "sim/state/geometry.hpp"

namespace ejecta {

class AxisCorrection {
 public:
  explicit AxisCorrection(KernelKind kernel);
  // Smoothed radius rt(r, h) [m] and its derivative d rt / d r (dimensionless, in [0, 1]).
  void smoothedRadius(double r, double h, double& rt, double& drt_dr) const;

 private:
  static constexpr int kTableSize = 401;  // xi in [0, 2]
  std::vector<double> I_, dI_;            // I(xi) and I'(xi) on the table
};

}  // namespace ejecta
