#pragma once
// The crater of a particle state: the target materials splatted onto a lattice in the run's own
// geometry (a 2D lattice for planar and RZ runs, so RZ needs no revolved grid), then measured by
// analyseCrater against the setup's original surface.
#include "fields/crater.hpp"
#include "fields/crater_setup.hpp"
#include "fields/grid_set.hpp"

namespace ejecta::fields {

// resolution [m]: lattice spacing and ray step; 0 = half the median smoothing length. With
// `ranks` (a collective): the crater of every rank's particles, splatted by each rank and
// measured at rank 0 (the other ranks return metrics with found = false).
CraterMetrics measureCrater(const ParticleSet& p, const ParticleContext& ctx,
                            const CraterSetup& setup, double resolution = 0.0,
                            const Communicator* ranks = nullptr);

}  // namespace ejecta::fields
