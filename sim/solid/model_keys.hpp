#pragma once
// The keys of a material's model tables ([materials.thermal], [materials.strength],
// [materials.fracture], [materials.porosity]): each key's kind, dimension (SI), default and doc, and which model uses
// which. The scene reader reads the tables by these specs (sim/setup/scene_materials.cpp),
// sim/solid/materials.cpp applies the values, and the key reference in docs/scenes.md is
// generated from them (`ejecta keys --markdown`). The strength models and their keys are the
// rows of sim/solid/strength_catalog.hpp.
#include <string_view>
#include <vector>

#include "core/schema.hpp"

namespace ejecta {

struct ModelKind {
  std::string_view name;               // the table's `model` value, e.g. "johnson_cook"
  std::string_view doc;
  std::vector<std::string_view> keys;  // the parameter keys of this model alone
};

struct ModelFamily {
  std::string_view table;         // "strength": [materials.strength]
  std::vector<ModelKind> models;  // empty: the table has no `model` key (thermal)
  config::KeyList keys;           // every key of the table, `model` and `library` included
};

const ModelFamily& thermalModelFamily();
const ModelFamily& strengthModelFamily();
const ModelFamily& fractureModelFamily();
const ModelFamily& porosityModelFamily();

}  // namespace ejecta
