// The scene's analysis tables: [fragments] (fields/fragments.hpp) and [shield]
// (fields/shield_analysis.hpp). Read after the bodies, whose names [shield] refers to.
#include <cmath>
#include <string>

#include "core/join.hpp"
#include "sim/setup/scene_sections.hpp"

namespace ejecta::scene_detail {

namespace {

// A [shield] body by name: a box of particles. Returns its index in Scene::bodies.
std::size_t shieldBody(const TableReader& r, const Scene& scene, std::string_view key,
                       const std::string& name) {
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    if (scene.bodies[b].name != name) continue;
    r.check(scene.bodies[b].shape.kind == ShapeKind::Box, key,
            "body '" + name + "' must be a box (a plate), not another shape");
    return b;
  }
  r.fail(key, "no body named '" + name + "'; the bodies are: " + joinList(scene.bodies, &BodySpec::name));
}

}  // namespace

void readFragments(const TableReader& root, Scene& scene) {
  const toml::table* t = root.optTable("fragments");
  if (!t) return;
  const TableReader r(root.context(), *t, "fragments", "fragments");
  FragmentAnalysisOptions& f = scene.fragments;
  f.enabled = true;
  r.check(scene.geometry != Geometry::Line, "fragments", "a 1D run has no fragments (slabs only)");
  f.linkFactor = r.optQuantity("link_factor").value_or(f.linkFactor);
  r.check(f.linkFactor > 0.0 && std::isfinite(f.linkFactor), "link_factor", "must be positive");
  f.damageThreshold = r.optQuantity("damage_threshold").value_or(f.damageThreshold);
  r.check(f.damageThreshold > 0.0, "damage_threshold",
          "must be positive (above 1: damage never separates fragments)");
  f.resolvedSpacings = r.optQuantity("resolved_spacings").value_or(f.resolvedSpacings);
  r.check(f.resolvedSpacings > 0.0 && std::isfinite(f.resolvedSpacings), "resolved_spacings",
          "must be positive");
  f.every = static_cast<int>(r.optInteger("every").value_or(0));
  r.check(f.every >= 0, "every", "must be 0 (the end only) or a positive count of snapshots");
}

void readShield(const TableReader& root, Scene& scene) {
  const toml::table* t = root.optTable("shield");
  if (!t) return;
  const TableReader r(root.context(), *t, "shield", "shield");
  ShieldAnalysisOptions& s = scene.shield;
  s.enabled = true;
  r.check(scene.geometry != Geometry::Line, "wall", "1D runs have no shield analysis (no lateral extent)");
  s.wall = r.requireString("wall");
  const BodySpec& wall = scene.bodies[shieldBody(r, scene, "wall", s.wall)];
  // The wall is told apart by its material: no other body may share it.
  for (const BodySpec& b : scene.bodies)
    r.check(&b == &wall || b.material != wall.material, "wall",
            "body '" + b.name + "' shares the wall's material '" + scene.materials[wall.material].name +
                "': give the wall a material of its own (the same constants under another name)");
  if (auto bumper = r.optString("bumper")) {
    s.bumper = *bumper;
    r.check(s.bumper != s.wall, "bumper", "the bumper and the wall must be different bodies");
    shieldBody(r, scene, "bumper", s.bumper);
  }
  s.damageThreshold = r.optQuantity("damage_threshold").value_or(s.damageThreshold);
  r.check(s.damageThreshold > 0.0, "damage_threshold", "must be positive");
  bool moving = false;
  for (const BodySpec& b : scene.bodies)
    moving = moving || b.velocity[0] != 0.0 || b.velocity[1] != 0.0 || b.velocity[2] != 0.0;
  r.check(moving, "wall", "no body moves: a shield analysis needs a projectile");
}

}  // namespace ejecta::scene_detail
