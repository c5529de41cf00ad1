#pragma once
// The catalog of strength models ([materials.strength] model = "..."): one row per model, each
// defined in its own file in sim/solid/strength_models/ with its parameters, flow stress, scene
// keys and factory. The scene schema and the key reference in docs/scenes.md take the models'
// keys from these rows (sim/solid/model_keys.cpp), and MaterialTable builds a material's
// strength through buildStrength. A new model is one file there, a row in strengthCatalog()
// (strength_catalog.cpp) and a test.
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "core/schema.hpp"
#include "sim/solid/material_spec.hpp"
#include "sim/solid/strength.hpp"

namespace ejecta {

struct StrengthLibraryEntry;

struct StrengthModelRow {
  std::string_view name;  // the table's `model` value, e.g. "johnson_cook"
  std::string_view doc;   // one line for the key reference
  // The model's own parameter keys, with dimension, default and doc (shear_modulus, common to
  // every model, is not among them). A key of another row given to this model is refused.
  config::KeyList keys;
  // The keys a scene must give, unless the library entry is of this model.
  std::vector<std::string_view> required;
  // The yield surface from the table's values; `entry` is the library entry when it is of this
  // model, else null. Throws std::invalid_argument for a bad value ("strength.<key> must ...").
  std::shared_ptr<const YieldSurface> (*make)(const ModelSpec& spec, const StrengthLibraryEntry* entry);
};

// The keys two rows share (collins and drucker_prager), declared once so that the key reference
// (which lists a shared key once) and both rows read the same spec.
config::KeySpec cohesionKey();
config::KeySpec strengthLimitKey();

// The rows in the order of the key reference: elastic, von_mises, johnson_cook, collins,
// drucker_prager.
const std::vector<StrengthModelRow>& strengthCatalog();
const StrengthModelRow* findStrengthModel(const std::vector<StrengthModelRow>& rows, std::string_view name);

// The strength model of a [materials.strength] table `spec` (present) by the row of
// `rows` it names: shear modulus and melting point from the library entry unless given (`melt`
// is set to the entry's), the required keys checked, a key of another row refused. Throws
// std::invalid_argument with a message naming the key ("strength.<key> ...").
StrengthModel buildStrength(const ModelSpec& spec, const std::vector<StrengthModelRow>& rows,
                            std::optional<double>& melt);

}  // namespace ejecta
