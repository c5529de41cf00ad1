// The scene's [fields], [crater], [images] and [thermal] tables.
#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <string>

#include "core/join.hpp"
#include "sim/state/particle_fields.hpp"
#include "sim/setup/scene_sections.hpp"

namespace ejecta::scene_detail {

namespace {

// A grid name of [fields]: a particle field, "fractions", or "fraction_<material>".
void checkGridName(const TableReader& r, const Scene& scene, const std::string& name) {
  if (findParticleScalarField(name) || name == "fractions") return;
  const std::string prefix = "fraction_";
  if (name.rfind(prefix, 0) == 0) {
    for (const MaterialSpec& m : scene.materials)
      if (m.name == name.substr(prefix.size())) return;
    r.fail("grids", "'" + name + "': no material named '" + name.substr(prefix.size()) + "'");
  }
  r.fail("grids", "unknown grid '" + name + "'; allowed: " + particleScalarFieldList() +
                      ", 'fractions', 'fraction_<material>'");
}

}  // namespace

// [fields] and [crater] come after the materials: their names are checked against them.
void readFields(const TableReader& root, Scene& scene) {
  const toml::table* t = root.optTable("fields");
  if (!t) return;
  const TableReader r(root.context(), *t, "fields", "fields");
  FieldsOutputOptions& f = scene.fields;
  f.enabled = true;
  if (auto grids = r.optStringArray("grids")) {
    r.check(!grids->empty(), "grids", "must name at least one grid");
    for (const std::string& g : *grids) checkGridName(r, scene, g);
    f.grids = *grids;
  }
  const Dimension m = Dimension::Length;
  f.voxel = r.optQuantity("voxel", m).value_or(0.0);
  r.check(f.voxel >= 0.0, "voxel", nonNegativeMessage(f.voxel, m) + "; 0 = the median h");
  static const EnumNames<FieldNormalisation> kNorm{{"auto", FieldNormalisation::Auto},
                                                   {"shepard", FieldNormalisation::Shepard},
                                                   {"none", FieldNormalisation::None}};
  f.normalise = r.optEnum("normalise", kNorm).value_or(f.normalise);
  f.every = static_cast<int>(r.optInteger("every").value_or(1));
  r.check(f.every >= 1, "every", "must be at least 1 (every Nth snapshot)");
  f.levelSet = r.optBool("level_set").value_or(true);
  f.extrude = r.optQuantity("extrude", m).value_or(0.0);
  r.check(f.extrude >= 0.0, "extrude", nonNegativeMessage(f.extrude, m));
  r.check(f.extrude == 0.0 || scene.geometry == Geometry::Planar, "extrude",
          "only 2D planar runs are extruded");
  const auto lo = r.optVector("region_min", m, 3, "[x, y, z] (RZ grids: revolved about y)");
  const auto hi = r.optVector("region_max", m, 3, "[x, y, z] (RZ grids: revolved about y)");
  r.check(lo.has_value() == hi.has_value(), lo ? "region_max" : "region_min",
          "give both region_min and region_max");
  if (lo) {
    f.clip = true;
    f.regionMin = *lo;
    f.regionMax = *hi;
    for (int d = 0; d < 3; ++d)
      r.check(f.regionMax[d] > f.regionMin[d], "region_max", "must exceed region_min in every component");
  }
}

void readCrater(const TableReader& root, Scene& scene) {
  const toml::table* t = root.optTable("crater");
  if (!t) return;
  const TableReader r(root.context(), *t, "crater", "crater");
  CraterAnalysisOptions& c = scene.crater;
  c.enabled = r.optBool("enabled").value_or(true);
  if (auto names = r.optStringArray("materials")) {
    for (const std::string& n : *names) {
      bool known = false;
      for (const MaterialSpec& m : scene.materials) known = known || m.name == n;
      r.check(known, "materials", "no material named '" + n + "'");
    }
    c.materials = *names;
  }
  c.resolution = r.optQuantity("resolution", Dimension::Length).value_or(0.0);
  r.check(c.resolution >= 0.0, "resolution",
          nonNegativeMessage(c.resolution, Dimension::Length) + "; 0 = half the median h");
  // The class name is checked where the classes live (fields/crater_setup.cpp), before the run.
  c.scaling = r.optString("scaling").value_or("");
  c.gravity = r.optQuantity("gravity", Dimension::Acceleration);
  if (c.gravity)
    r.check(*c.gravity >= 0.0, "gravity", nonNegativeMessage(*c.gravity, Dimension::Acceleration));
  r.check(!c.gravity || !c.scaling.empty(), "gravity", "is for the crater scaling: give `scaling` too");
  c.strength = r.optQuantity("strength", Dimension::Pressure);
  if (c.strength)
    r.check(*c.strength >= 0.0, "strength", nonNegativeMessage(*c.strength, Dimension::Pressure));
  r.check(!c.strength || !c.scaling.empty(), "strength", "is for the crater scaling: give `scaling` too");
  r.check(c.enabled || c.scaling.empty(), "scaling", "sets the measured crater beside the scaled "
                                                     "one: it needs enabled = true");
}

namespace {

// [images] grids and surface: pictures of the grid files [fields] writes, so the names must be
// grids it writes (docs/fields.md): its grids with "fractions" spelled out, and with the level
// set, "surface" and "surface_<material>".
void readGridImages(const TableReader& r, Scene& scene) {
  ImageOutputOptions& im = scene.images;
  const FieldsOutputOptions& f = scene.fields;
  const bool grids = f.enabled && scene.geometry != Geometry::Line;
  if (auto names = r.optStringArray("grids")) {
    r.check(grids, "grids", scene.geometry == Geometry::Line
                                ? "1D runs write no grids"
                                : "needs a [fields] table: the pictures are of the grid files it writes");
    std::vector<std::string> written;
    for (const std::string& g : f.grids) {
      if (g != "fractions") written.push_back(g);
      else
        for (const MaterialSpec& m : scene.materials) written.push_back("fraction_" + m.name);
    }
    if (f.levelSet) {
      written.push_back("surface");
      for (const MaterialSpec& m : scene.materials) written.push_back("surface_" + m.name);
    }
    for (const std::string& n : *names) {
      bool known = false;
      for (const std::string& w : written) known = known || w == n;
      r.check(known, "grids", "'" + n + "' is not a grid the run writes (" + joinList(written) + ")");
    }
    im.grids = *names;
  }
  im.surface = r.optBool("surface").value_or(false);
  if (im.surface) {
    r.check(grids && f.levelSet, "surface",
            "needs a [fields] table with level_set = true: the picture is of its surface level set");
    r.check(scene.geometry != Geometry::Planar || f.extrude > 0.0, "surface",
            "a 2D planar run has a surface level set only when [fields] extrude is set");
  }
}

// [images.camera]: a camera the renderer can use (render/view_transform.hpp would reject the
// same, later and without the key's name).
void readImageCamera(const TableReader& r, ImageOutputOptions& im) {
  ImageCamera c;
  const char* layout = "[x, y, z]";
  auto point = [&](const char* k) {
    r.require(k);
    return *r.optVector(k, Dimension::Length, 3, layout);
  };
  c.position = point("position");
  c.target = point("target");
  c.up = r.optVector("up", Dimension::None, 3, layout).value_or(c.up);
  c.fovDegrees = r.optQuantity("fov_degrees", Dimension::None).value_or(c.fovDegrees);
  r.check(c.fovDegrees > 0.0 && c.fovDegrees < 180.0, "fov_degrees", "must be between 0 and 180");
  const std::array<double, 3> sight{c.target[0] - c.position[0], c.target[1] - c.position[1],
                                    c.target[2] - c.position[2]};
  const double distance = std::hypot(sight[0], sight[1], sight[2]);
  r.check(distance > 0.0, "target", "is the camera's position: the camera must look somewhere");
  const double upLength = std::hypot(c.up[0], c.up[1], c.up[2]);
  const std::array<double, 3> side{sight[1] * c.up[2] - sight[2] * c.up[1],
                                   sight[2] * c.up[0] - sight[0] * c.up[2],
                                   sight[0] * c.up[1] - sight[1] * c.up[0]};
  r.check(upLength > 0.0 && std::hypot(side[0], side[1], side[2]) > 1e-6 * distance * upLength,
          "up", "must not be zero or along the line of sight (position -> target)");
  im.camera = c;
}

}  // namespace

void readImages(const TableReader& root, Scene& scene) {
  const toml::table* t = root.optTable("images");
  if (!t) return;
  const TableReader r(root.context(), *t, "images", "images");
  ImageOutputOptions& im = scene.images;
  im.enabled = true;
  auto checkFields = [&](const char* key, const std::vector<std::string>& names) {
    for (const std::string& n : names)
      r.check(findParticleScalarField(n) != nullptr, key,
              "no particle field '" + n + "' (known: " + particleScalarFieldList() + ")");
  };
  if (auto f = r.optStringArray("fields")) {
    checkFields("fields", *f);
    // No particle pictures is fine when the table asks for pictures of the grids.
    r.check(!f->empty() || t->contains("grids") || t->contains("surface"), "fields", "give at least one field");
    im.fields = *f;
  }
  if (auto l = r.optStringArray("log")) {
    checkFields("log", *l);
    im.log = *l;
  }
  im.every = static_cast<int>(r.optInteger("every").value_or(1));
  r.check(im.every >= 1, "every", "must be at least 1");
  im.size = static_cast<int>(r.optInteger("size").value_or(1024));
  r.check(im.size >= 64 && im.size <= 8192, "size", "must be 64 to 8192 pixels");
  im.cut = r.optString("cut").value_or("z");
  r.check(im.cut == "none" || im.cut == "x" || im.cut == "y" || im.cut == "z", "cut",
          "expected \"none\", \"x\", \"y\" or \"z\"");
  if (auto at = r.optQuantity("cut_at", Dimension::Length)) {
    r.check(spatialDimension(scene.geometry) == 3 && im.cut != "none", "cut_at",
            "moves the cut of a 3D picture; this scene has none (cut = \"" + im.cut + "\", " +
                std::to_string(spatialDimension(scene.geometry)) + "D)");
    im.cutAt = *at;
  }
  if (const toml::table* c = r.optTable("camera")) {
    r.check(spatialDimension(scene.geometry) == 3, "camera",
            "only 3D pictures have a camera; 2D and RZ pictures are orthographic sections");
    readImageCamera(TableReader(root.context(), *c, "images.camera", "images.camera"), im);
  }
  readGridImages(r, scene);
}

void readThermal(const TableReader& root, Scene& scene) {
  const toml::table* t = root.optTable("thermal");
  if (!t) return;
  const TableReader r(root.context(), *t, "thermal", "thermal");
  ThermalOutputOptions& th = scene.thermal;
  th.enabled = true;
  th.line = lineOf(*t);
  th.study = r.requireString("study");
  const std::string material = r.optString("hot_material").value_or("snapshot");
  r.check(material == "snapshot" || material == "evolving", "hot_material",
          "expected \"snapshot\" (the material of one output, frozen during the pass) or "
          "\"evolving\" (the material of each moment of the pass)");
  th.evolving = material == "evolving";
  r.check(!th.study.empty(), "study", "must name a study file");
  if (const toml::node* n = t->get("times")) {
    const toml::array* arr = n->as_array();
    r.check(arr != nullptr, "times", "expected an array of times, e.g. [\"1 ms\", \"3 ms\"]");
    for (std::size_t i = 0; i < arr->size(); ++i) {
      const double time = r.quantityOf(*arr->get(i), "thermal.times[" + std::to_string(i) + "]",
                                       Dimension::Time);
      r.check(time >= 0.0, "times", "times must not be negative");
      r.check(th.times.empty() || time > th.times.back(), "times", "times must increase");
      th.times.push_back(time);
    }
  }
}

}  // namespace ejecta::scene_detail
