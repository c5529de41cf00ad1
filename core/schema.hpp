#pragma once
// A declarative description of the keys of a TOML input: name, kind, dimension (SI), default,
// allowed values and a one-line doc string. A reader's schema (core/table_reader.hpp
// SchemaTables) is a list of these per table, so its unknown-key errors and its generated key
// reference (a scene's: `ejecta keys --markdown`, docs/scenes.md) come from one place.
// A KeySpec converts from a bare name ("shape"): readers that only check names list names.
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/units.hpp"

namespace ejecta::config {

enum class KeyKind {
  Unspecified,    // a name only
  Number,         // a plain dimensionless number (read as a quantity of Dimension::None)
  Quantity,       // a number in SI or a quantity string ("10 km/s") of `dimension`
  Integer,
  Bool,
  String,
  Enum,           // a string, one of `allowed`
  StringArray,
  QuantityArray,  // an array of quantities of `dimension`
  Vector,         // one quantity of `dimension` per coordinate of the input's geometry
  Vector3,        // exactly three quantities of `dimension`
  Table,
  TableArray,     // [[name]]
  AnyKey,         // "*": any key; the reader checks them itself
};

struct KeySpec {
  std::string_view name;
  KeyKind kind = KeyKind::Unspecified;
  Dimension dimension{};
  std::string_view defaultText;           // as a user would write it; "required"; "" = none
  std::vector<std::string_view> allowed;  // Enum: the values
  std::string_view doc;                   // one line of Markdown

  KeySpec(const char* n) : name(n) {}  // NOLINT: implicit, so {"a", "b"} is a KeyList
  KeySpec(std::string_view n) : name(n) {}  // NOLINT
  KeySpec(std::string_view n, KeyKind k, Dimension d, std::string_view def, std::string_view description,
          std::vector<std::string_view> values = {})
      : name(n), kind(k), dimension(d), defaultText(def), allowed(std::move(values)), doc(description) {}
  // So `for (std::string_view k : keys)` keeps working over a KeyList.
  operator std::string_view() const { return name; }  // NOLINT
  bool required() const { return defaultText == "required"; }
};

using KeyList = std::vector<KeySpec>;

// The spec of `name` in `keys`, or nullptr (a "*" entry matches nothing here).
inline const KeySpec* findKey(const KeyList& keys, std::string_view name) {
  for (const KeySpec& k : keys)
    if (k.name == name) return &k;
  return nullptr;
}

// Builders, so a schema reads as a table: key, (dimension,) default, doc. In their own namespace:
// their short names would otherwise clash with the readers' locals.
namespace keys {

inline KeySpec number(std::string_view n, std::string_view def, std::string_view doc) {
  return {n, KeyKind::Number, Dimension::None, def, doc};
}
inline KeySpec quantity(std::string_view n, Dimension d, std::string_view def,
                        std::string_view doc) {
  return {n, KeyKind::Quantity, d, def, doc};
}
inline KeySpec integer(std::string_view n, std::string_view def, std::string_view doc) {
  return {n, KeyKind::Integer, Dimension::None, def, doc};
}
inline KeySpec boolean(std::string_view n, std::string_view def, std::string_view doc) {
  return {n, KeyKind::Bool, Dimension::None, def, doc};
}
inline KeySpec text(std::string_view n, std::string_view def, std::string_view doc) {
  return {n, KeyKind::String, Dimension::None, def, doc};
}
inline KeySpec choice(std::string_view n, std::vector<std::string_view> values,
                      std::string_view def, std::string_view doc) {
  return {n, KeyKind::Enum, Dimension::None, def, doc, std::move(values)};
}
inline KeySpec textList(std::string_view n, std::string_view def, std::string_view doc) {
  return {n, KeyKind::StringArray, Dimension::None, def, doc};
}
inline KeySpec quantityList(std::string_view n, Dimension d, std::string_view def,
                            std::string_view doc) {
  return {n, KeyKind::QuantityArray, d, def, doc};
}
inline KeySpec vectorOf(std::string_view n, Dimension d, std::string_view def,
                      std::string_view doc) {
  return {n, KeyKind::Vector, d, def, doc};
}
inline KeySpec vector3Of(std::string_view n, Dimension d, std::string_view def,
                       std::string_view doc) {
  return {n, KeyKind::Vector3, d, def, doc};
}
inline KeySpec table(std::string_view n, std::string_view def, std::string_view doc) {
  return {n, KeyKind::Table, Dimension::None, def, doc};
}
inline KeySpec tableArray(std::string_view n, std::string_view def, std::string_view doc) {
  return {n, KeyKind::TableArray, Dimension::None, def, doc};
}
inline KeySpec anyKey(std::string_view doc) {
  return {"*", KeyKind::AnyKey, Dimension::None, "", doc};
}

}  // namespace keys

// How a key is written, for a key reference: "Q [m]", "vector of Q [m/s]", "string", ...
inline std::string kindText(const KeySpec& k) {
  const std::string unit = siUnit(k.dimension);
  const std::string q = unit.empty() ? "number" : "Q [" + unit + "]";
  switch (k.kind) {
    case KeyKind::Unspecified: return "";
    case KeyKind::Number: return "number";
    case KeyKind::Quantity: return q;
    case KeyKind::Integer: return "integer";
    case KeyKind::Bool: return "bool";
    case KeyKind::String: return "string";
    case KeyKind::Enum: return "string";
    case KeyKind::StringArray: return "array of strings";
    case KeyKind::QuantityArray: return "array of " + q;
    case KeyKind::Vector: return "vector of " + q;
    case KeyKind::Vector3: return "3 × " + q;
    case KeyKind::Table: return "table";
    case KeyKind::TableArray: return "array of tables";
    case KeyKind::AnyKey: return "any";
  }
  return "";
}

}  // namespace ejecta::config
