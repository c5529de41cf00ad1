#pragma once
// The equations of state a scene can name: their parameters (with physical dimensions, so scene
// files may give them with units), their libraries of published materials, and a factory that
// builds one from a MaterialSpec (a library entry, then the scene's overrides).
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/units.hpp"
#include "sim/eos/eos.hpp"

namespace ejecta {

struct MaterialSpec;

struct EosParameter {
  std::string_view key;   // as written in [materials.parameters]
  Dimension dimension;    // what a quantity string must reduce to
  std::string_view doc;   // one line, for the key reference (docs/scenes.md)
};

struct EosKind {
  std::string_view name;                // "ideal_gas", "tillotson", "mie_gruneisen", "jwl", ...
  std::vector<EosParameter> parameters; // every key [materials.parameters] may hold
  std::vector<std::string> libraryNames;
  std::string_view doc;                 // one line: what it models, where it is documented
  // An EOS without parameters: where its constants are given instead (read in the reader's
  // error for a stray parameter and in the key reference).
  std::string_view constantsElsewhere = {};
};

const std::vector<EosKind>& eosKinds();
// The kind of that name, or nullptr.
const EosKind* findEosKind(std::string_view name);

// Builds the EOS of a material: its library entry (if named), overridden by its parameters.
// Without a library every parameter is required. Throws std::invalid_argument naming the
// parameter and the reason.
std::shared_ptr<const EquationOfState> makeEquationOfState(const MaterialSpec& spec);

}  // namespace ejecta
