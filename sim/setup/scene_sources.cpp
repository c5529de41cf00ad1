// The scene's [[energy_deposits]], [[detonations]] and [[gauges]].
#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <string>

#include "sim/setup/scene_sections.hpp"

namespace ejecta::scene_detail {

void readDeposits(const TableReader& root, Scene& scene) {
  static const EnumNames<DepositProfile> kProfiles{{"top_hat", DepositProfile::TopHat},
                                                   {"gaussian", DepositProfile::Gaussian}};
  const std::vector<const toml::table*> list = root.tableArray("energy_deposits");
  const int dim = spatialDimension(scene.geometry);
  const Dimension m = Dimension::Length;
  std::set<std::string> names;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const TableReader r(root.context(), *list[i], "energy_deposits[" + std::to_string(i) + "]",
                        "energy_deposits[]");
    EnergyDepositSpec e;
    e.line = lineOf(*list[i]);
    e.name = r.requireString("name");
    checkUniqueName(r, names, e.name);
    e.energy = r.requireQuantity("energy", Dimension::Energy);
    r.check(e.energy > 0.0, "energy", positiveMessage(e.energy, Dimension::Energy));
    // A delayed deposit (the follower's burst after the impact) must fire before the run ends.
    e.time = r.optQuantity("time", Dimension::Time).value_or(0.0);
    r.check(e.time >= 0.0, "time", nonNegativeMessage(e.time, Dimension::Time));
    r.check(e.time < scene.time.tEnd, "time",
            "the deposit at " + formatQuantity(e.time, Dimension::Time) +
                " would never fire: the run ends at t_end = " +
                formatQuantity(scene.time.tEnd, Dimension::Time));
    if (const std::optional<std::string> body = r.optString("body")) {
      for (std::size_t b = 0; b < scene.bodies.size(); ++b)
        if (scene.bodies[b].name == *body) e.body = static_cast<int>(b);
      for (const VoidSpec& v : scene.voids)
        r.check(v.name != *body, "body", "'" + *body + "' is a void body: it has no particles");
      r.check(e.body >= 0, "body", "no body named '" + *body + "'");
    }
    // A body deposit without a centre covers the whole body (the seed's device particles).
    e.hasCenter = e.body < 0 || r.has("center");
    if (e.hasCenter) {
      r.require("center");
      e.center = *r.optVector("center", m, dim, vectorLayout(scene.geometry));
      if (scene.geometry == Geometry::Axisymmetric)
        r.check(e.center[0] == 0.0, "center",
                "in rz the deposit must be centred on the axis (r = 0)");
    } else {
      r.check(!r.has("radius") && !r.has("width") && !r.has("profile"), "radius",
              "a deposit over a whole body takes no radius, width or profile (give a 'center' "
              "to deposit in part of it)");
      scene.deposits.push_back(std::move(e));
      continue;
    }
    e.profile = r.optEnum("profile", kProfiles).value_or(e.profile);
    if (e.profile == DepositProfile::TopHat) {
      r.check(!r.has("width"), "width", "only a 'gaussian' profile takes a width");
      e.radius = r.requireQuantity("radius", m);
      r.check(e.radius > 0.0, "radius", positiveMessage(e.radius, m));
    } else {
      r.check(!r.has("radius"), "radius", "a 'gaussian' profile takes a width, not a radius");
      e.width = r.requireQuantity("width", m);
      r.check(e.width > 0.0, "width", positiveMessage(e.width, m));
    }
    scene.deposits.push_back(std::move(e));
  }
}

void readDetonations(const TableReader& root, Scene& scene) {
  const std::vector<const toml::table*> list = root.tableArray("detonations");
  const int dim = spatialDimension(scene.geometry);
  const Dimension m = Dimension::Length;
  std::set<std::string> names;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const TableReader r(root.context(), *list[i], "detonations[" + std::to_string(i) + "]",
                        "detonations[]");
    DetonationSpec d;
    d.line = lineOf(*list[i]);
    d.name = r.requireString("name");
    checkUniqueName(r, names, d.name);
    const std::string material = r.requireString("material");
    d.material = -1;
    for (std::size_t k = 0; k < scene.materials.size(); ++k)
      if (scene.materials[k].name == material) d.material = static_cast<int>(k);
    r.check(d.material >= 0, "material", "no material named '" + material + "'");
    r.check(scene.materials[static_cast<std::size_t>(d.material)].eos == "jwl", "material",
            "material '" + material + "' is not a JWL explosive (eos = \"jwl\"); programmed "
            "burn lights detonation products");
    r.require("point");
    d.point = *r.optVector("point", m, dim, vectorLayout(scene.geometry));
    if (const auto end = r.optVector("line_to", m, dim, vectorLayout(scene.geometry))) {
      d.alongLine = true;
      d.lineEnd = *end;
    }
    if (scene.geometry == Geometry::Axisymmetric) {
      r.check(d.point[0] == 0.0, "point", "in rz the initiation point must be on the axis (r = 0)");
      r.check(!d.alongLine || d.lineEnd[0] == 0.0, "line_to",
              "in rz an initiation line must lie on the axis (r = 0)");
    }
    d.time = r.optQuantity("time", Dimension::Time).value_or(0.0);
    r.check(d.time >= 0.0, "time", nonNegativeMessage(d.time, Dimension::Time));
    d.velocity = r.optQuantity("velocity", Dimension::Velocity).value_or(0.0);
    r.check(d.velocity >= 0.0, "velocity", nonNegativeMessage(d.velocity, Dimension::Velocity));
    for (const DetonationSpec& other : scene.detonations)
      r.check(other.material != d.material || other.velocity == d.velocity, "velocity",
              "detonations of one explosive must share one detonation velocity");
    scene.detonations.push_back(std::move(d));
  }
  // A body with neither pressure nor internal energy must be an explosive lit here: it starts at
  // its detonation energy (sim/setup/bodies.cpp).
  const std::vector<const toml::table*> bodies = root.tableArray("bodies");
  for (std::size_t b = 0; b < scene.bodies.size(); ++b) {
    const BodySpec& body = scene.bodies[b];
    if (body.pressure || body.internalEnergy) continue;
    bool lit = false;
    for (const DetonationSpec& d : scene.detonations) lit = lit || d.material == body.material;
    if (!lit) {
      const std::size_t entry = body.entry >= 0 ? static_cast<std::size_t>(body.entry) : b;
      const TableReader r(root.context(), *bodies[entry], "bodies[" + std::to_string(entry) + "]",
                          "bodies[]");
      r.fail("pressure", "give exactly one of 'pressure' and 'internal_energy' (only a body of "
                         "an explosive with a [[detonations]] entry may give neither)");
    }
  }
}

void readGauges(const TableReader& root, Scene& scene) {
  const std::vector<const toml::table*> list = root.tableArray("gauges");
  const int dim = spatialDimension(scene.geometry);
  std::set<std::string> names;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const TableReader r(root.context(), *list[i], "gauges[" + std::to_string(i) + "]", "gauges[]");
    GaugeSpec g;
    g.line = lineOf(*list[i]);
    g.name = r.requireString("name");
    checkUniqueName(r, names, g.name);
    for (char c : g.name)
      r.check(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-', "name",
              "a gauge name is a CSV column prefix: letters, digits, '_' and '-' only");
    r.require("position");
    g.position = *r.optVector("position", Dimension::Length, dim, vectorLayout(scene.geometry));
    if (scene.geometry == Geometry::Axisymmetric)
      r.check(g.position[0] >= 0.0, "position", "in rz a gauge's r must be >= 0");
    scene.gauges.push_back(std::move(g));
  }
}

}  // namespace ejecta::scene_detail
