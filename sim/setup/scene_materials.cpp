// The scene's [[materials]] and their model tables.
#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <string>

#include "sim/eos/eos_catalog.hpp"
#include "sim/setup/scene_sections.hpp"

namespace ejecta::scene_detail {

// Names within one list must be unique: bodies and deposits are reported by name.
void checkUniqueName(const TableReader& r, std::set<std::string>& seen, const std::string& name) {
  r.check(!name.empty(), "name", "must not be empty");
  r.check(seen.insert(name).second, "name", "'" + name + "' is already used by an earlier entry");
}

namespace {

// Keys of a material's model tables and what each must measure; string keys are handled apart.
struct ModelKey {
  std::string_view key;
  Dimension dimension;
};
const Dimension kPerVolume{0, -3, 0, 0};
const Dimension kPerTime{0, 0, -1, 0};
const Dimension kSpecificHeat{0, 2, -2, -1};

void readModelTable(const TableReader& material, std::string_view name,
                    const std::vector<ModelKey>& keys, const std::vector<std::string_view>& models,
                    ModelSpec& out) {
  const toml::table* t = material.optTable(name);
  if (!t) return;
  const TableReader r(material.context(), *t, material.key(name),
                      "materials[]." + std::string(name));
  out.present = true;
  out.line = lineOf(*t);
  if (!models.empty()) {
    EnumNames<std::string> names;
    for (std::string_view m : models) names.push_back({m, std::string(m)});
    const std::optional<std::string> model = r.optEnum<std::string>("model", names);
    if (!model) r.fail("model", "required key is missing; one of " + enumList(names));
    out.model = *model;
  }
  out.library = r.optString("library").value_or("");
  for (const ModelKey& k : keys) {
    if (k.key == "seed") {
      if (const std::optional<long> seed = r.optInteger("seed")) {
        r.check(*seed >= 0, "seed", "must not be negative");
        out.values.emplace_back("seed", static_cast<double>(*seed));
      }
      continue;
    }
    if (const std::optional<double> v = r.optQuantity(k.key, k.dimension)) {
      r.check(*v >= 0.0, k.key, nonNegativeMessage(*v, k.dimension));
      out.values.emplace_back(std::string(k.key), *v);
    }
  }
}

void readMaterialModels(const TableReader& r, MaterialSpec& m) {
  readModelTable(r, "thermal",
                 {{"specific_heat", kSpecificHeat},
                  {"mean_atomic_mass", Dimension::None},
                  {"molar_mass", Dimension::None},
                  {"initial_temperature", Dimension::Temperature},
                  {"melt_temperature", Dimension::Temperature}},
                 {}, m.thermal);
  readModelTable(r, "strength",
                 {{"shear_modulus", Dimension::Pressure},
                  {"yield_stress", Dimension::Pressure},
                  {"A", Dimension::Pressure},
                  {"B", Dimension::Pressure},
                  {"n", Dimension::None},
                  {"C", Dimension::None},
                  {"m", Dimension::None},
                  {"reference_strain_rate", kPerTime},
                  {"room_temperature", Dimension::Temperature},
                  {"cohesion", Dimension::Pressure},
                  {"friction_intact", Dimension::None},
                  {"strength_limit", Dimension::Pressure},
                  {"friction_damaged", Dimension::None},
                  {"cohesion_damaged", Dimension::Pressure}},
                 {"elastic", "von_mises", "johnson_cook", "collins"}, m.strength);
  readModelTable(r, "fracture",
                 {{"weibull_k", kPerVolume},
                  {"weibull_m", Dimension::None},
                  {"tensile_strength", Dimension::Pressure},
                  {"erosion_strain", Dimension::None},
                  {"crack_speed_factor", Dimension::None},
                  {"max_crack_increment", Dimension::None},
                  {"seed", Dimension::None}},
                 {"none", "grady_kipp", "principal_stress"}, m.fracture);
}

}  // namespace

void readMaterials(const TableReader& root, Scene& scene) {
  const std::vector<const toml::table*> list = root.tableArray("materials");
  if (list.empty()) root.fail("materials", "at least one [[materials]] entry is required");
  std::set<std::string> names;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const TableReader r(root.context(), *list[i], "materials[" + std::to_string(i) + "]",
                        "materials[]");
    MaterialSpec m;
    m.line = lineOf(*list[i]);
    m.name = r.requireString("name");
    checkUniqueName(r, names, m.name);
    EnumNames<std::string> eosNames;
    for (const EosKind& k : eosKinds()) eosNames.push_back({k.name, std::string(k.name)});
    m.eos = r.optEnum<std::string>("eos", eosNames).value_or("ideal_gas");
    const EosKind& kind = *findEosKind(m.eos);
    if (r.has("gamma")) {
      r.check(m.eos == "ideal_gas", "gamma", "applies to eos = \"ideal_gas\" only");
      m.gamma = *r.optQuantity("gamma", Dimension::None);
      r.check(m.gamma > 1.0, "gamma", "must exceed 1 (got " + formatQuantity(m.gamma, {}) + ")");
    }
    if (const std::optional<std::string> library = r.optString("library")) {
      std::string known;
      bool found = false;
      for (const std::string& n : kind.libraryNames) {
        known += (known.empty() ? "" : ", ") + n;
        found = found || n == *library;
      }
      r.check(found, "library",
              "no " + m.eos + " library entry '" + *library + "'" +
                  (known.empty() ? std::string(" (this eos has no library)") : "; known: " + known));
      m.library = *library;
    }
    if (const toml::table* params = r.optTable("parameters")) {
      const TableReader pr(root.context(), *params, r.key("parameters"), "materials[].parameters");
      for (auto&& [k, node] : *params) {
        const EosParameter* found = nullptr;
        for (const EosParameter& p : kind.parameters)
          if (p.key == k.str()) found = &p;
        if (!found) {
          std::string known;
          for (const EosParameter& p : kind.parameters)
            known += (known.empty() ? "" : ", ") + std::string(p.key);
          pr.fail(k.str(), "not a parameter of eos '" + m.eos + "'; its parameters: " + known);
        }
        m.parameters.emplace_back(std::string(k.str()),
                                  pr.quantityOf(node, pr.key(k.str()), found->dimension));
      }
    }
    readMaterialModels(r, m);
    scene.materials.push_back(std::move(m));
  }
}

}  // namespace ejecta::scene_detail
