// The scene's schema: [fields], [crater], [fragments], [shield], [images] and [thermal] (read in
// scene_output_sections.cpp and scene_analysis_sections.cpp). Defaults are those of sim/io/output_options.hpp.
#include "sim/setup/scene_schema.hpp"

namespace ejecta::scene_schema_detail {

using namespace config::keys;

std::vector<SceneTable> outputTables() {
  const Dimension m = Dimension::Length;
  return {
      {"fields",
       "`[fields]` (optional: sparse VDB grids during the run, docs/fields.md)",
       "",
       {textList("grids", "[\"density\", \"temperature\", \"pressure\", \"damage\", \"fractions\"]",
                 "particle fields, `\"fractions\"` or `\"fraction_<material>\"`"),
        quantity("voxel", m, "0", "voxel size; 0 = the median smoothing length"),
        choice("normalise", {"auto", "shepard", "none"}, "\"auto\"",
               "`\"auto\"` (Shepard except density and fractions), `\"shepard\"` or `\"none\"`"),
        integer("every", "1", "grids with every Nth snapshot (and the last)"),
        boolean("level_set", "true", "add the `surface` level set"),
        quantity("extrude", m, "0", "2D planar only: slab depth; 0 = one voxel"),
        vector3Of("region_min", m, "none",
                  "clip box, lower corner in grid coordinates (RZ: revolved about y); both or "
                  "neither"),
        vector3Of("region_max", m, "none", "clip box, upper corner; > region_min")}},
      {"crater",
       "`[crater]` (optional: impact scenes are measured without it, docs/crater.md)",
       "",
       {boolean("enabled", "true", "measure the crater at the end of an impact run"),
        textList("materials", "the bodies at rest", "target materials"),
        quantity("resolution", m, "0",
                 "measuring resolution; 0 = half the median smoothing length"),
        text("scaling", "none",
             "set the crater beside pi-group scaling for this class of target: water, dry_sand, "
             "dry_soil, wet_soil, soft_rock, hard_rock, hh2011_sand, hh2011_glass_spheres, "
             "hh2011_sand_fly_ash, hh2011_perlite_sand (Holsapple 1993; the hh2011_ classes: "
             "Housen & Holsapple 2011's porous targets; docs/crater.md)"),
        quantity("gravity", Dimension::Acceleration, "a uniform sphere's",
                 "surface gravity for the scaling; default on a sphere (4/3) pi G rho R, on a "
                 "plane 0"),
        quantity("strength", Dimension::Pressure, "the class's",
                 "the target's effective strength Y in the scaling, in place of the class's (its "
                 "laboratory target's)")}},
      {"fragments",
       "`[fragments]` (optional: fragment identification, docs/fragments.md)",
       "",
       {number("link_factor", "2",
               "friends when closer than link_factor (h_i + h_j) / 2; 2 = the kernel's support"),
        number("damage_threshold", "0.99", "particles with damage at or above it link to nobody"),
        number("resolved_spacings", "4",
               "a size is measured when it spans at least this many particle spacings"),
        integer("every", "0", "also with every Nth snapshot; 0 = at the end only")}},
      {"shield",
       "`[shield]` (optional: a Whipple shield's perforation verdict, docs/whipple.md)",
       "",
       {text("wall", "required", "the rear wall's body: a box whose material no other body uses"),
        text("bumper", "none", "the bumper's body (a box): the debris cloud is measured behind it"),
        number("damage_threshold", "0.99", "wall particles at or above it have failed")}},
      {"images",
       "`[images]` (optional: pictures during the run, docs/render.md)",
       "",
       {textList("fields", "[\"density\"]",
                 "particle fields drawn, each to `images/<field>_NNNN.png`; may be `[]` when "
                 "`grids` or `surface` is given"),
        textList("log", "[]",
                 "of those, the ones on a log scale (also applies to a grid of the same name, "
                 "and `\"temperature\"` to the surface's colours)"),
        integer("every", "1", "with every Nth snapshot (and the last)"),
        integer("size", "1024", "pixels (square), 64 to 8192"),
        choice("cut", {"none", "x", "y", "z"}, "\"z\"",
               "3D: keep the half x, y or z ≤ `cut_at` (also cuts the `surface` picture)"),
        quantity("cut_at", m, "0; surface: 0 when it spans 0, else its middle",
                 "3D: where the cut's plane crosses its axis, e.g. `\"30 m\"`"),
        table("camera", "automatic", "3D: `[images.camera]`, below"),
        textList("grids", "[]",
                 "grids of the run's grid files sliced through the plane z = 0, each to "
                 "`images/grid_<name>_NNNN.png`; needs `[fields]`, and each name must be a grid "
                 "it writes (its `grids` with `\"fractions\"` spelled out as "
                 "`fraction_<material>`, and `surface`, `surface_<material>` with its level set)"),
        boolean("surface", "false",
                "the `surface` level set as a 3D iso-surface coloured by temperature (when the "
                "file has it), cut open by `cut`, to `images/surface_NNNN.png`; needs `[fields]` "
                "with `level_set = true` (2D planar: with `extrude`)")}},
      {"images.camera",
       "`[images.camera]`",
       "The 3D pictures' perspective camera (particles and the `surface` picture alike); 2D and "
       "RZ pictures are orthographic sections and take none.",
       {vector3Of("position", m, "required", "where the camera is, e.g. `[\"60 m\", \"-60 m\", \"50 m\"]`"),
        vector3Of("target", m, "required", "the point at the centre of the picture"),
        vector3Of("up", Dimension::None, "[0, 0, 1]",
                  "the direction that is up in the picture; not along the line of sight"),
        number("fov_degrees", "30", "vertical field of view in degrees, between 0 and 180")}},
      {"thermal",
       "`[thermal]` (optional: the radiation chain in-situ, docs/thermal.md)",
       "RZ and 3D scenes only.",
       {text("study", "required",
             "a study file beside the scene (`\"follower.toml\"`), or one compiled in "
             "(`\"thermal/follower\"`)"),
        quantityList("times", Dimension::Time, "[]",
                     "increasing; snapshot: a pass at the first output at or after each (empty: "
                     "at the last output); evolving: a pass starting at each (empty: at 0)"),
        choice("hot_material", {"snapshot", "evolving"}, "\"snapshot\"",
               "the material of one output, frozen during the pass, or at each sample time of "
               "the pass the material of that moment while the run goes on")}},
  };
}

}  // namespace ejecta::scene_schema_detail
