#pragma once
// Per-step scratch shared by the density and force passes: neighbour structures and the
// per-particle quantities that are not part of the particle state.
#include <optional>
#include <vector>

#include "sim/sph/axis_correction.hpp"
#include "sim/sph/cell_grid.hpp"
#include "sim/sph/neighbour_lists.hpp"
#include "sim/sph/shared_pair_stars.hpp"
#include "sim/sph/sph_options.hpp"
#include "sim/state/geometry.hpp"

namespace ejecta {

struct HydroWorkspace {
  HydroWorkspace(const SphOptions& options, Geometry g)
      : sph(options), geometry(g), dim(spatialDimension(g)) {
    if (g == Geometry::Axisymmetric) axis.emplace(options.kernel);
  }
  SphOptions sph;
  Geometry geometry;
  int dim;
  std::optional<AxisCorrection> axis;  // RZ only
  CellGrid grid;
  NeighbourLists lists;
  int numThreads = 1;
  // RZ: smoothed radius rt and d rt / d r of each particle (real and ghost).
  std::vector<double> smoothedR, dSmoothedR;
  // Shear modulus of each material [Pa]; 0 for a material without strength. Empty when no
  // material has strength (the hydro-only pair loops).
  std::vector<double> shearModulus;
  // Per material: 1 when its yield surface carries the damage (Collins), so the force uses the
  // stored S rather than (1 - D) S. Same length as shearModulus.
  std::vector<unsigned char> yieldCarriesDamage;
  // Artificial stress epsilon in effect (0 = off).
  double artificialStress = 0.0;
  // Velocity gradient dv_a/dx_b of every particle (real and ghost), 9 values per particle with
  // dv_a/dx_b at 9 i + 3 a + b (the pair loop reads a neighbour's whole tensor at once), linearly
  // corrected so that it is exact for a linear field; filled only when the viscosity
  // reconstructs velocities (SphOptions::viscosityReconstruction), empty otherwise.
  std::vector<double> velocityGradient;
  // Integral-approach matrix C of every particle (real and ghost), 9 values per particle at
  // 9 i + 3 a + b (symmetric), the inverse of tau_i = sum_j V_j W_ij(h_i) (x_j - x_i)(x)(x_j - x_i)
  // over i's gather list; all zero where tau cannot be inverted (the pair terms then take the
  // kernel gradient). Filled only with SphOptions::gradients = IntegralApproach.
  std::vector<double> iadMatrix;
  // Generalised volume elements (SphOptions::volumeElements): each particle's X_i / m_i, real
  // and ghost, fixed from the densities before the density pass; the pair terms take only the
  // ratios of two particles' values. Empty with the standard (mass) volumes.
  std::vector<double> volumeWeight;
  // Largest h of each real particle (SphOptions::hMaxFactor), or nullptr: h is not capped. The
  // run points it at the particles' column before each pass that sets h.
  const double* hCap = nullptr;
  // Artificial conductivity: the fastest signal speed v_sig^u of the pairs that heat each
  // evaluated real particle [m/s] (sim/sph/terms/artificial_conductivity.hpp), for the
  // individual steps' diffusion limit (sim/run/timestep_criteria.hpp). Written by the force
  // pass only with conductivity on, and read right after it: a reorder of the particles does not
  // carry it along.
  std::vector<double> conductionSignal;
  // The Riemann-solver dissipation's pairs that the force pass sums from both sides, solved once
  // (sim/sph/shared_pair_stars.hpp); kept here for its buffers.
  SharedPairStars sharedStars;
  // Number of neighbours in each real particle's gather list, the particle itself included
  // (diagnostics, the neighbour check and the decomposition's costs).
  std::vector<std::uint32_t> neighbourCount;
};

// Runs `f.template operator()<K, D, RZ>()` for the workspace's kernel and geometry.
template <typename F>
decltype(auto) dispatchHydro(const HydroWorkspace& ws, F&& f);

}  // namespace ejecta

#include "sim/sph/kernel.hpp"

namespace ejecta {

template <typename F>
decltype(auto) dispatchHydro(const HydroWorkspace& ws, F&& f) {
  return withKernel(ws.sph.kernel, [&]<template <int> class K>() {
    switch (ws.geometry) {
      case Geometry::Line: return f.template operator()<K, 1, false>();
      case Geometry::Planar: return f.template operator()<K, 2, false>();
      case Geometry::Axisymmetric: return f.template operator()<K, 2, true>();
      case Geometry::Spatial: break;
    }
    return f.template operator()<K, 3, false>();
  });
}

}  // namespace ejecta
