#pragma once
// Bodies and voids as a scene gives them ([[bodies]]): shapes, lattices, initial state.
#include <array>
#include <cstddef>
#include <optional>
#include <string>

namespace ejecta {

enum class LatticeKind { Cubic, Hexagonal };
enum class ShapeKind { Box, Sphere, Shell, HalfSpace };

struct ShapeSpec {
  ShapeKind kind = ShapeKind::Box;
  std::array<double, 3> min{}, max{};       // Box
  std::array<double, 3> center{};           // Sphere, Shell (a disc in 2D, a segment in 1D)
  double radius = 0.0;                      // Sphere; Shell outer radius
  double innerRadius = 0.0;                 // Shell
  std::array<double, 3> point{};            // HalfSpace: a point on the plane
  std::array<double, 3> normal{};           // HalfSpace: outward normal; inside is behind it
};

struct BodySpec {
  std::string name;
  int material = 0;                         // index into Scene::materials
  ShapeSpec shape;
  LatticeKind lattice = LatticeKind::Cubic;
  double spacing = 0.0;                     // [m]
  double density = 0.0;                     // [kg/m^3]
  // [Pa] or [J/kg]: exactly one, except for a body of a detonated JWL explosive, which may give
  // neither and then starts at the explosive's detonation energy e0 = E0 / rho0.
  std::optional<double> pressure;
  std::optional<double> internalEnergy;
  std::array<double, 3> velocity{};         // [m/s]
  double damage = 0.0;                      // initial damage D in [0, 1] (1: rubble)
  // Resting on another body (`rest_on`): the body is moved along `restDirection` (unit) until the
  // nearest pair of its particles and that body's is `restGap` of its spacing apart, whatever the
  // spacing (sim/setup/resting_bodies.hpp). `restMove`: how far it was moved [m], set then.
  std::string restOn;
  std::array<double, 3> restDirection{};
  double restGap = 1.0;
  double restMove = 0.0;
  int line = 0;
  // Its index among the file's [[bodies]] entries, voids included, for messages; -1: the same
  // as its index in Scene::bodies (a body built in code).
  int entry = -1;
};

// A crater's bowl: a paraboloid of revolution about `axis` (a parabola in 2D planar) with its
// vertex at `floor`, opening along `axis` (unit), `radius` wide at `depth` above the floor and
// open beyond, as a crater opens to space.
struct BowlSpec {
  std::array<double, 3> floor{};
  std::array<double, 3> axis{};
  double depth = 0.0;
  double radius = 0.0;
};

// A void: a [[bodies]] entry with `void = true`. It makes no particles but claims its space as a
// body does, so the bodies listed after it lose their particles there (earlier bodies win): the
// crater an impactor left, a cavity. Kept apart from Scene::bodies, the bodies with particles,
// so that the energy ledger, the crater analysis and the restarts never see it.
struct VoidSpec {
  std::string name;
  bool isBowl = false;          // shape = "paraboloid": `bowl`; otherwise `shape`
  ShapeSpec shape;
  BowlSpec bowl;
  std::size_t firstCarved = 0;  // index in Scene::bodies of the first body it carves
  int line = 0;
};

}  // namespace ejecta
