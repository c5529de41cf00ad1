// The scene's schema: [[materials]] and their model tables (scene_materials.cpp), [[bodies]]
// (scene_bodies.cpp), [[energy_deposits]], [[detonations]] and [[gauges]] (scene_sources.cpp).
// The eos names come from sim/eos/eos_catalog.hpp and the model tables' keys from
// sim/solid/model_keys.hpp; defaults are those of MaterialSpec, BodySpec and the source specs.
#include <stdexcept>

#include "sim/eos/eos_catalog.hpp"
#include "sim/setup/scene_schema.hpp"
#include "sim/solid/model_keys.hpp"

namespace ejecta::scene_schema_detail {

using namespace config::keys;

std::vector<SceneTable> materialTables() {
  std::vector<std::string_view> eosNames;
  for (const EosKind& k : eosKinds()) eosNames.push_back(k.name);
  return {
      {"materials[]",
       "`[[materials]]` (at least one)",
       "",
       {text("name", "required", "unique; bodies refer to it"),
        choice("eos", eosNames, "\"ideal_gas\"", "the equation of state (below)"),
        number("gamma", "1.4", "ideal gas only: adiabatic index, > 1"),
        text("library", "none", "a published parameter set of that eos (below)"),
        table("parameters", "none",
              "parameters of the eos (below), numbers (SI) or quantities with units; they "
              "override the library entry; without a library every parameter is required"),
        table("thermal", "none", "`[materials.thermal]`: specific heat, temperatures (below)"),
        table("strength", "none", "`[materials.strength]`: a yield model (below)"),
        table("fracture", "none", "`[materials.fracture]`: a fracture model (below)"),
        table("porosity", "none", "`[materials.porosity]`: pores below the resolution (below)")}},
      // Keys depend on the eos: checked against sim/eos/eos_catalog.hpp in readMaterials.
      {"materials[].parameters", "", "", {anyKey("a parameter of the material's eos")}},
      {"materials[].thermal", "`[materials.thermal]`", "", thermalModelFamily().keys},
      {"materials[].strength", "`[materials.strength]`", "", strengthModelFamily().keys},
      {"materials[].fracture", "`[materials.fracture]`", "", fractureModelFamily().keys},
      {"materials[].porosity", "`[materials.porosity]`", "", porosityModelFamily().keys},
  };
}

std::vector<SceneTable> bodyTables() {
  std::vector<std::string_view> shapeNames;
  for (const SceneShape& shape : sceneShapes()) shapeNames.push_back(shape.name);
  const Dimension m = Dimension::Length;
  const Dimension s = Dimension::Time;
  return {
      {"bodies[]",
       "`[[bodies]]` (at least one)",
       "Bodies are filled in order; earlier bodies win where shapes overlap. A shape takes its "
       "own keys only (the table after the keys); a shape entirely outside the domain is an "
       "error.",
       {text("name", "required", "unique"),
        text("material", "required", "a `[[materials]]` name"),
        choice("shape", shapeNames, "required",
               "`\"box\"`, `\"sphere\"`, `\"shell\"`, `\"half_space\"`; `\"paraboloid\"` for "
               "void bodies only (the shapes' keys: below)"),
        vectorOf("min", m, "box: required", "box: the lower corner"),
        vectorOf("max", m, "box: required", "box: the upper corner, > min per component"),
        vectorOf("center", m, "sphere, shell: required", "sphere, shell: the centre"),
        quantity("radius", m, "sphere, paraboloid: required",
                 "sphere: radius, > 0; paraboloid: the radius at `depth`"),
        quantity("inner_radius", m, "shell: required", "shell: inner radius, ≥ 0"),
        quantity("outer_radius", m, "shell: required", "shell: outer radius, > inner_radius"),
        vectorOf("point", m, "half_space, paraboloid: required",
                 "half_space: a point of the plane; paraboloid: the floor"),
        vectorOf("normal", Dimension::None, "half_space, paraboloid: required",
                 "half_space: outward normal, any length ≠ 0; paraboloid: the direction it "
                 "opens"),
        choice("lattice", {"cubic", "hexagonal"}, "\"cubic\"", "the lattice of the particles"),
        quantity("spacing", m, "required", "lattice spacing s > 0"),
        quantity("density", Dimension::Density, "required", "initial density, > 0"),
        quantity("pressure", Dimension::Pressure, "—",
                 "≥ 0; internal energy from the material's EOS. Exactly one of pressure / "
                 "internal_energy (neither: an explosive with a `[[detonations]]` entry)"),
        quantity("internal_energy", Dimension::SpecificEnergy, "—", "≥ 0"),
        vectorOf("velocity", Dimension::Velocity, "zero", "initial velocity"),
        number("damage", "0", "initial damage D in [0, 1] (1: rubble, no tension, no shear)"),
        text("rest_on", "—",
             "the name of a body listed after it (one that does not rest itself, and on which no other body rests): this body (a box, sphere or shell) is moved "
             "along `rest_direction` until its nearest particle pair with that body is "
             "`rest_gap` spacings apart, so the contact is the same at every spacing (a device "
             "on a crater floor; `sim/setup/resting_bodies.hpp`, docs/asteroid_studies.md)"),
        vectorOf("rest_direction", Dimension::None, "down",
                 "with rest_on: the direction it moves in, any length ≠ 0 (down: −x in 1D, −y "
                 "in 2D and RZ, −z in 3D; in RZ along the axis only)"),
        number("rest_gap", "1", "with rest_on: the nearest pair's distance in this body's "
               "spacings, in [1, 2]"),
        boolean("void", "false",
                "a body with no particles that claims its shape, so the bodies listed after it "
                "are carved there (a crater, a cavity); it takes `name`, `shape` and the shape's "
                "keys only, and must precede a body (`sim/setup/bodies.hpp`, "
                "docs/asteroid_studies.md)"),
        quantity("depth", m, "paraboloid: required", "paraboloid: depth, > 0")}},
      {"energy_deposits[]",
       "`[[energy_deposits]]`",
       "Exactly `energy` is deposited: Σ mᵢ Δuᵢ = E.",
       {text("name", "required", "unique"),
        quantity("energy", Dimension::Energy, "required",
                 "> 0: `\"1e5 J\"`, `\"100 kt\"` (2D planar: per metre depth)"),
        text("body", "every body",
             "only this body's particles; without `center`, all of them (du = E / M_body, the "
             "seed's DED device)"),
        vectorOf("center", m, "required without a body",
                 "centre of the deposit; in RZ on the axis: `[0, z]`"),
        quantity("radius", m, "top_hat: required",
                 "Δuᵢ = E / M for the particles with |xᵢ − c| ≤ radius (M: their mass)"),
        choice("profile", {"top_hat", "gaussian"}, "\"top_hat\"", "how the energy is spread"),
        quantity("width", m, "gaussian: required",
                 "Δuᵢ = E gᵢ / Σⱼ mⱼ gⱼ, g = exp(−r²/width²)"),
        quantity("time", s, "0",
                 "≥ 0 and < `time.t_end`: when the deposit fires (a delayed deposit, below)")}},
      {"detonations[]",
       "`[[detonations]]`",
       "Programmed burn of a JWL explosive: docs/sources.md.",
       {text("name", "required", "unique"),
        text("material", "required", "a material with `eos = \"jwl\"`"),
        vectorOf("point", m, "required", "the initiation point (RZ: on the axis)"),
        vectorOf("line_to", m, "—", "initiation along the segment from `point` to it (RZ: on the axis)"),
        quantity("time", s, "0", "when it lights, ≥ 0"),
        quantity("velocity", Dimension::Velocity, "the explosive's D_cj",
                 "detonation velocity, ≥ 0 (0: D_cj); one per explosive")}},
      {"gauges[]",
       "`[[gauges]]`",
       "Pressure, density and velocity every step into `gauges.csv`: docs/undex.md.",
       {text("name", "required", "unique; a CSV column prefix: letters, digits, `_` and `-`"),
        vectorOf("position", m, "required", "where it records (RZ: r ≥ 0)")}},
  };
}

}  // namespace ejecta::scene_schema_detail

namespace ejecta {

const std::vector<SceneShape>& sceneShapes() {
  static const std::vector<SceneShape> shapes{
      {"box", {"min", "max"}, "axis-aligned box, min < max per component"},
      {"sphere", {"center", "radius"},
       "ball; a disc in 2D and RZ (in RZ a sphere), a segment in 1D"},
      {"shell", {"center", "inner_radius", "outer_radius"}, "inner ≤ |x − c| ≤ outer"},
      {"half_space", {"point", "normal"},
       "{x : (x − point)·normal ≤ 0}, clipped to the domain box; every domain axis must then be "
       "bounded"},
      {"paraboloid", {"point", "normal", "radius", "depth"},
       "void bodies only: a crater's bowl, {x : s ≥ 0, ρ² ≤ radius²·s/depth} with s the height "
       "above the floor along `normal` and ρ the distance from that axis; open above (a parabola "
       "in 2D; in RZ the floor on the axis, `normal` = [0, ±1])"},
  };
  return shapes;
}

const SceneShape& sceneShape(std::string_view name) {
  for (const SceneShape& s : sceneShapes())
    if (s.name == name) return s;
  std::string what = "no shape '";
  what += name;
  throw std::out_of_range(what + "' in the scene schema");
}

}  // namespace ejecta
