#pragma once
// The domain box per axis and what bounds it (open, periodic, wall); RZ: axis 0 is r and its
// lower bound the symmetry axis.
#include <array>

namespace ejecta {

enum class BoundaryKind { Open, Periodic, Wall };

struct AxisBounds {
  double min = 0.0, max = 0.0;
  BoundaryKind lower = BoundaryKind::Open;   // boundary at min
  BoundaryKind upper = BoundaryKind::Open;   // boundary at max
  bool bounded = false;  // false: open in both directions with no box (min/max unused)
};

// Per axis; RZ: axis 0 is r (lower bound = the axis).
using DomainBounds = std::array<AxisBounds, 3>;

}  // namespace ejecta
