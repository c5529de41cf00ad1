#pragma once
// Small 3x3 tensors for the solid-mechanics terms: the velocity gradient (general) and stresses
// (symmetric). Stored symmetric components follow one order everywhere, in the particle arrays,
// snapshots and here: xx, yy, zz, xy, xz, yz. In 1D, 2D planar and RZ only the first four are
// kept (xz = yz = 0); in RZ x is r, y is z and "zz" is the hoop component (theta theta).
#include <array>
#include <cmath>

namespace ejecta {

enum SymComponent : int { kXX = 0, kYY = 1, kZZ = 2, kXY = 3, kXZ = 4, kYZ = 5 };

// Row and column of each stored symmetric component.
inline constexpr int kSymRow[6] = {0, 1, 2, 0, 0, 1};
inline constexpr int kSymCol[6] = {0, 1, 2, 1, 2, 2};

// Number of stored components of the deviatoric stress in a geometry of `dim` coordinates.
constexpr int stressComponentCount(int dim) { return dim == 3 ? 6 : 4; }

using Mat3 = std::array<std::array<double, 3>, 3>;

struct SymTensor {
  std::array<double, 6> c{};  // xx, yy, zz, xy, xz, yz

  double& operator[](int k) { return c[k]; }
  double operator[](int k) const { return c[k]; }
  double at(int row, int col) const {
    if (row == col) return c[row];
    const int s = row + col;  // 1: xy, 2: xz, 3: yz
    return c[2 + s];
  }
  double trace() const { return c[kXX] + c[kYY] + c[kZZ]; }
  // Double contraction with itself, A:A.
  double selfContraction() const {
    return c[kXX] * c[kXX] + c[kYY] * c[kYY] + c[kZZ] * c[kZZ] +
           2.0 * (c[kXY] * c[kXY] + c[kXZ] * c[kXZ] + c[kYZ] * c[kYZ]);
  }
};

// Second invariant of a deviatoric tensor, J2 = S:S / 2; the von Mises stress is sqrt(3 J2).
inline double secondInvariant(const SymTensor& s) { return 0.5 * s.selfContraction(); }

// Eigenvalues (ascending) and unit eigenvectors (columns of `vectors`) of a symmetric tensor, by
// cyclic Jacobi rotations: robust for repeated eigenvalues and deterministic. `vectors` may be
// null when only the eigenvalues are wanted.
void symmetricEigen(const SymTensor& a, std::array<double, 3>& values, Mat3* vectors);

// The same in the x-y plane only (components xx, yy, xy), in closed form: eigenvalues ascending,
// (cos, sin) of the direction of the larger one.
inline void planeEigen(double xx, double yy, double xy, double& lo, double& hi, double& cosT,
                       double& sinT) {
  const double mean = 0.5 * (xx + yy), half = 0.5 * (xx - yy);
  const double radius = std::hypot(half, xy);
  lo = mean - radius;
  hi = mean + radius;
  // Direction of the larger eigenvalue: angle theta with tan(2 theta) = 2 xy / (xx - yy).
  const double theta = 0.5 * std::atan2(xy, half);
  cosT = std::cos(theta);
  sinT = std::sin(theta);
}

}  // namespace ejecta
