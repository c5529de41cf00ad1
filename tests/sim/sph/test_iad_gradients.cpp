// Integral-approach gradients (sph.gradients = "iad", sim/sph/iad_matrix.hpp): the matrix
// inverse, the exactness for linear fields on any arrangement of neighbours that is the method's
// point, and the scenes it is refused for. Its runs against exact solutions are in
// tests/sim/verify/test_verify_iad.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "sim/run/run.hpp"
#include "sim/run/simulation.hpp"
#include "sim/setup/bodies.hpp"
#include "sim/setup/scene.hpp"
#include "sim/solid/materials.hpp"
#include "sim/sph/iad_matrix.hpp"
#include "sim/sph/kernel.hpp"
#include "support/fluid_option_checks.hpp"
#include "support/quarter_blast.hpp"

namespace ejecta {
namespace {

// A random symmetric positive-definite D x D matrix (a sum of outer products).
template <int D>
void randomTau(std::mt19937& rng, double tau[9]) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int k = 0; k < 9; ++k) tau[k] = 0.0;
  for (int n = 0; n < 2 * D + 3; ++n) {
    double v[3] = {0.0, 0.0, 0.0};
    for (int d = 0; d < D; ++d) v[d] = unit(rng);
    for (int a = 0; a < D; ++a)
      for (int b = 0; b < D; ++b) tau[3 * a + b] += v[a] * v[b];
  }
}

template <int D>
double inverseError(unsigned seed) {
  std::mt19937 rng(seed);
  double tau[9], C[9];
  randomTau<D>(rng, tau);
  EXPECT_TRUE(invertSymmetric<D>(tau, C));
  double worst = 0.0;
  for (int a = 0; a < D; ++a)
    for (int b = 0; b < D; ++b) {
      double product = 0.0;
      for (int k = 0; k < D; ++k) product += C[3 * a + k] * tau[3 * k + b];
      worst = std::max(worst, std::abs(product - (a == b ? 1.0 : 0.0)));
    }
  return worst;
}

TEST(IadGradients, TheMatrixIsTheInverseOfTau) {
  // Round-off of a 3 x 3 cofactor inverse of a well-conditioned matrix: 1e-12.
  for (unsigned seed = 1; seed <= 10; ++seed) {
    EXPECT_LT(inverseError<1>(seed), 1e-12);
    EXPECT_LT(inverseError<2>(seed), 1e-12);
    EXPECT_LT(inverseError<3>(seed), 1e-12);
  }
}

TEST(IadGradients, ASingularTauGivesNoMatrix) {
  // Neighbours on a line in 2D and in a plane in 3D: tau has rank 1 and 2.
  double line[9] = {1.0, 2.0, 0.0, 2.0, 4.0, 0.0, 0.0, 0.0, 0.0}, C[9];
  EXPECT_FALSE(invertSymmetric<2>(line, C));
  for (double c : C) EXPECT_EQ(c, 0.0);
  double plane[9] = {1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0};
  EXPECT_FALSE(invertSymmetric<3>(plane, C));
  double none[9] = {};
  EXPECT_FALSE(invertSymmetric<1>(none, C));
}

// The IAD gradient of a linear field f = f0 + g . x at a particle among 40 random neighbours
// (any volumes V_j, every neighbour on one side when oneSided, as at a free surface): with
// A_ij = C_i (x_j - x_i) W_ij, sum_j V_j (f_j - f_i) A_ij = g exactly; the kernel gradient's
// sum_j V_j (f_j - f_i) grad W_ij is off by tens of percent on such an arrangement.
template <int D>
void linearFieldErrors(unsigned seed, bool oneSided, double& iad, double& kernel) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), volume(0.5e-6, 2e-6);
  const double h = 0.01;
  double g[3] = {0.0, 0.0, 0.0};
  for (int d = 0; d < D; ++d) g[d] = 100.0 * unit(rng);
  double x[40][3] = {}, V[40];
  double tau[9] = {};
  for (int k = 0; k < 40; ++k) {
    for (int d = 0; d < D; ++d) x[k][d] = 1.9 * h * unit(rng) / std::sqrt(double(D));  // x_j - x_i
    if (oneSided) x[k][0] = std::abs(x[k][0]);
    V[k] = volume(rng);
    double r2 = 0.0;
    for (int d = 0; d < D; ++d) r2 += x[k][d] * x[k][d];
    const double w = V[k] * kernelValue<CubicSplineKernel, D>(std::sqrt(r2), h);
    for (int a = 0; a < D; ++a)
      for (int b = 0; b < D; ++b) tau[3 * a + b] += w * x[k][a] * x[k][b];
  }
  double C[9];
  ASSERT_TRUE(invertSymmetric<D>(tau, C));
  double gIad[3] = {}, gKernel[3] = {};
  for (int k = 0; k < 40; ++k) {
    double r2 = 0.0, df = 0.0;
    for (int d = 0; d < D; ++d) {
      r2 += x[k][d] * x[k][d];
      df += g[d] * x[k][d];
    }
    const double r = std::sqrt(r2);
    const double W = kernelValue<CubicSplineKernel, D>(r, h);
    const double dW = kernelDerivative<CubicSplineKernel, D>(r, h);
    for (int a = 0; a < D; ++a) {
      double Cx = 0.0;
      for (int b = 0; b < D; ++b) Cx += C[3 * a + b] * x[k][b];
      gIad[a] += V[k] * df * Cx * W;
      gKernel[a] += V[k] * df * dW * (-x[k][a]) / r;  // grad_i W = W'(r) (x_i - x_j) / r
    }
  }
  double scale = 0.0;
  iad = kernel = 0.0;
  for (int d = 0; d < D; ++d) {
    scale = std::max(scale, std::abs(g[d]));
    iad = std::max(iad, std::abs(gIad[d] - g[d]));
    kernel = std::max(kernel, std::abs(gKernel[d] - g[d]));
  }
  iad /= scale;
  kernel /= scale;
}

TEST(IadGradients, ExactForALinearFieldOnAnyArrangement) {
  // Round-off of sums of 40 terms and a 3 x 3 inverse: 1e-11 of the largest component.
  double worstKernel = 0.0;
  for (unsigned seed = 1; seed <= 5; ++seed)
    for (bool oneSided : {false, true}) {
      double iad, kernel;
      linearFieldErrors<1>(seed, oneSided, iad, kernel);
      EXPECT_LT(iad, 1e-11);
      worstKernel = std::max(worstKernel, kernel);
      linearFieldErrors<2>(seed, oneSided, iad, kernel);
      EXPECT_LT(iad, 1e-11);
      worstKernel = std::max(worstKernel, kernel);
      linearFieldErrors<3>(seed, oneSided, iad, kernel);
      EXPECT_LT(iad, 1e-11);
      worstKernel = std::max(worstKernel, kernel);
    }
  // The point of the method: the kernel gradient is not exact there (the test would not tell the
  // two apart otherwise).
  EXPECT_GT(worstKernel, 0.1);
}

// --- Through the solver: conservation, threads, mirror walls -----------------------------------


// The periodic 2D blast off the lattice's centre of symmetry (a centred blast has no net momentum
// whether or not the pair force conserves it): tests/support/fluid_option_checks.hpp.
TEST(IadGradients, StrongBlastConservesEnergyAndMomentum) {
  test::expectBlastConserves({"sph.gradients=iad"});
}

TEST(IadGradients, IsIndependentOfThreadCount) { test::expectThreadIndependent({"sph.gradients=iad"}); }

// A blast in a walled box and its quarter with walls on the symmetry axes: the mirror ghosts must
// carry C with the signs a reflection gives (C_xy reverses), or the particles beside the axes feel
// other forces than in the full box.
TEST(IadGradients, QuarterDomainWithMirrorWallsMatchesTheFullBox) {
  const test::QuarterMismatch m = test::quarterAgainstFullBox("[sph]\ngradients = \"iad\"\n");
  const double worstPosition = m.position, worstPressure = m.pressure;
  std::printf("  quarter against full box: position %.2e m, pressure %.2e of the peak\n",
              worstPosition, worstPressure);
  // The same particles and arithmetic with sums in another order: round-off, as the
  // reconstructed viscosity's same test allows (tests/sim/sph/test_viscosity_reconstruction.cpp).
  EXPECT_LT(worstPosition, 1e-12);
  EXPECT_LT(worstPressure, 1e-10);
}

// --- Where it is refused, with the key named ------------------------------------------------

constexpr const char* kOn = "gradients = \"iad\"";

TEST(IadGradients, RefusedWhereItIsNotBuilt) {
  using test::expectReaderRefuses, test::optionGasScene;
  EXPECT_NO_THROW(parseScene(optionGasScene(kOn, "2d"), "iad.toml"));
  const std::string key = "sph.gradients";
  expectReaderRefuses(optionGasScene(kOn, "rz"), key, "RZ");
  test::expectRefusedWhereNoOptionIsBuilt(kOn, key);
  expectReaderRefuses(optionGasScene(kOn, "2d", "", "stepping = \"individual\"\n"), key,
                      "global time steps");
}

// A scene built in code (a bench) passes no reader: the simulation refuses it itself.
TEST(IadGradients, TheSimulationRefusesWhatTheReaderWouldHave) {
  test::expectSimulationRefusesIndividualSteps(kOn, "sph.gradients");
}

}  // namespace
}  // namespace ejecta
