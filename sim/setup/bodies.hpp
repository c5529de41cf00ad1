#pragma once
// Initial particles: each body of the scene filled on its lattice, less the space of the voids
// listed before it, then the energy deposits due at t = 0.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "sim/solid/materials.hpp"
#include "sim/parallel/communicator.hpp"
#include "sim/state/particles.hpp"
#include "sim/setup/scene.hpp"

namespace ejecta {

// Generates the particles of every body (clipped to its shape and the domain; earlier bodies and
// voids win where shapes overlap), sets mass, density, internal energy, velocity, h and material, then
// adds the energy deposits with time 0 (the delayed ones are Simulation's to fire). Ids run
// 0..n-1; numReal = n. Throws SceneError for a body without particles or a deposit that covers
// none.
// With `ranks` of more than one rank (a collective), each rank builds only its slice of the
// build order, about n / ranks particles with their ids, so no rank ever holds the whole set; the
// deposits are summed over the ranks. Scenes whose flaws are drawn from the whole body
// (needsWholeBody) are built whole on every rank instead.
ParticleSet buildParticles(const Scene& scene, const MaterialTable& materials,
                           const Communicator* ranks = nullptr);
// Grady-Kipp flaws are distributed over every particle of a material at t = 0 (sim/solid/
// solid_state.hpp): such scenes are built whole.
bool needsWholeBody(const MaterialTable& materials);

// The particle ids of each body as buildParticles assigns them: body b holds the ids
// [first[b], first[b + 1]). Ids travel with the particles, so a body is found again after any
// reordering (for a delayed body deposit).
std::vector<std::int64_t> bodyFirstIds(const Scene& scene, const MaterialTable& materials);

// Adds deposit `index` of the scene to the real particles now: sum_i m_i du_i = E exactly, over
// the particles in its region (and of its body, by the ids of bodyFirstIds, if it names one) at
// this moment. `time` is the time it fires, for the message. Returns the centroid of the energy
// (the mass- and weight-averaged position), the burst's point. Throws SceneError naming the file,
// key, scene, time and region when the region holds no particles. In a distributed run
// (`ranks` given) the region's mass and centroid are summed over every rank's particles.
std::array<double, 3> applyDeposit(const Scene& scene, std::size_t index,
                                   const std::vector<std::int64_t>& firstIdOfBody, ParticleSet& p,
                                   double time, const Communicator* ranks = nullptr);

// Whether body `index` makes a particle at x, a point of its lattice (or holds x, a point in
// space): inside its shape and the domain, and not claimed by an earlier body (other than
// `ignoring`; scene.bodies.size(): none) or an earlier void.
bool bodyOwnsPoint(const Scene& scene, std::size_t index, const std::array<double, 3>& x,
                   std::size_t ignoring);

// The lattice points body `index` makes, positions only, as buildParticles places them (inside
// its shape and the domain, not claimed by an earlier body or void), within [lo, hi] on every
// axis. `ignoring`: a body whose claim is left out (scene.bodies.size(): none). More than about
// 2 maxPoints lattice points to look at is a SceneError naming the body (a bound on the work of
// a scene reader given any text).
std::vector<std::array<double, 3>> bodyLatticePoints(const Scene& scene, std::size_t index,
                                                     const std::array<double, 3>& lo,
                                                     const std::array<double, 3>& hi,
                                                     std::size_t ignoring, std::size_t maxPoints);

// "FILE:LINE: key 'bodies[i]': body 'NAME'" (with `key`, 'bodies[i].KEY'), i as the scene file
// numbers its [[bodies]] entries: how an error about body `index` begins.
std::string bodyContext(const Scene& scene, std::size_t index, const std::string& key = "");

// Volume (area in 2D and RZ, length in 1D) of one lattice cell: cubic s^d, 2D hexagonal
// s^2 sqrt(3)/2, 3D close packed (face-centred cubic, nearest neighbour s) s^3/sqrt(2).
double latticeCellVolume(LatticeKind lattice, int dimension, double spacing);

// Whether x lies in the shape (closed), using the first `dimension` coordinates.
bool insideShape(const ShapeSpec& shape, const std::array<double, 3>& x, int dimension);

// Whether x lies in a crater's bowl (closed): at a height s >= 0 above the floor along the axis
// and within radius * sqrt(s / depth) of the axis.
bool insideBowl(const BowlSpec& bowl, const std::array<double, 3>& x, int dimension);

// Whether x lies in the space a void body claims (its bowl or its shape).
bool insideVoid(const VoidSpec& v, const std::array<double, 3>& x, int dimension);

}  // namespace ejecta
