#include "sim/sph/kernel.hpp"

namespace ejecta {

const char* kernelName(KernelKind kind) {
  switch (kind) {
    case KernelKind::CubicSpline: return "cubic_spline";
    case KernelKind::WendlandC2: return "wendland_c2";
    case KernelKind::WendlandC4: return "wendland_c4";
  }
  return "cubic_spline";
}

}  // namespace ejecta
