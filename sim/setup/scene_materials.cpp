// The scene's [[materials]] and their model tables.
#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <string>

#include "core/join.hpp"
#include "sim/eos/eos_catalog.hpp"
#include "sim/solid/model_keys.hpp"
#include "sim/setup/scene_sections.hpp"

namespace ejecta::scene_detail {

// Names within one list must be unique: bodies and deposits are reported by name.
void checkUniqueName(const TableReader& r, std::set<std::string>& seen, const std::string& name) {
  r.check(!name.empty(), "name", "must not be empty");
  r.check(seen.insert(name).second, "name", "'" + name + "' is already used by an earlier entry");
}

namespace {

// A material's model table, read by its family's key specs (sim/solid/model_keys.hpp): the model
// name, the library entry, and every number in SI by key.
void readModelTable(const TableReader& material, const ModelFamily& family, ModelSpec& out) {
  const std::string_view name = family.table;
  const toml::table* t = material.optTable(name);
  if (!t) return;
  const TableReader r(material.context(), *t, material.key(name),
                      "materials[]." + std::string(name));
  out.present = true;
  out.line = lineOf(*t);
  if (!family.models.empty()) {
    EnumNames<std::string> names;
    for (const ModelKind& m : family.models) names.push_back({m.name, std::string(m.name)});
    const std::optional<std::string> model = r.optEnum<std::string>("model", names);
    if (!model) r.fail("model", "required key is missing; one of " + enumList(names));
    out.model = *model;
  }
  out.library = r.optString("library").value_or("");
  for (const KeySpec& k : family.keys) {
    if (k.kind == KeyKind::Integer) {
      if (const std::optional<long> v = r.optInteger(k.name)) {
        r.check(*v >= 0, k.name, "must not be negative");
        out.values.emplace_back(std::string(k.name), static_cast<double>(*v));
      }
    } else if (k.kind == KeyKind::Bool) {
      if (const std::optional<bool> v = r.optBool(k.name))
        out.values.emplace_back(std::string(k.name), *v ? 1.0 : 0.0);
    } else if (k.kind == KeyKind::Quantity || k.kind == KeyKind::Number) {
      if (const std::optional<double> v = r.optQuantity(k.name, k.dimension)) {
        r.check(*v >= 0.0, k.name, nonNegativeMessage(*v, k.dimension));
        out.values.emplace_back(std::string(k.name), *v);
      }
    }
  }
}

void readMaterialModels(const TableReader& r, MaterialSpec& m) {
  readModelTable(r, thermalModelFamily(), m.thermal);
  readModelTable(r, strengthModelFamily(), m.strength);
  readModelTable(r, fractureModelFamily(), m.fracture);
  readModelTable(r, porosityModelFamily(), m.porosity);
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
      const auto& entries = kind.libraryNames;
      r.check(std::find(entries.begin(), entries.end(), *library) != entries.end(), "library",
              "no " + m.eos + " library entry '" + *library + "'" +
                  (entries.empty() ? std::string(" (this eos has no library)") : "; known: " + joinList(entries)));
      m.library = *library;
    }
    if (const toml::table* params = r.optTable("parameters")) {
      const TableReader pr(root.context(), *params, r.key("parameters"), "materials[].parameters");
      for (auto&& [k, node] : *params) {
        const EosParameter* found = nullptr;
        for (const EosParameter& p : kind.parameters)
          if (p.key == k.str()) found = &p;
        if (!found) {
          if (kind.parameters.empty())
            pr.fail(k.str(), "eos '" + m.eos + "' takes no parameters" +
                                 (kind.constantsElsewhere.empty()
                                      ? std::string()
                                      : ": " + std::string(kind.constantsElsewhere)));
          pr.fail(k.str(), "not a parameter of eos '" + m.eos + "'; its parameters: " +
                                 joinList(kind.parameters, &EosParameter::key));
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
