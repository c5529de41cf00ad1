#pragma once
// Initial particles: each body of the scene filled on its lattice, less the space of the voids
// listed before it, then the energy deposits.
#include <array>

#include "sim/materials.hpp"
#include "sim/particles.hpp"
#include "sim/scene.hpp"

namespace ejecta {

// Generates the particles of every body (clipped to its shape and the domain; earlier bodies and
// voids win where shapes overlap), sets mass, density, internal energy, velocity, h and material, then
// adds the energy deposits. Ids run 0..n-1; numReal = n. Throws SceneError for a body without
// particles or a deposit that covers none.
ParticleSet buildParticles(const Scene& scene, const MaterialTable& materials);

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
