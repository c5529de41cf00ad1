#pragma once
// The one TOML input reader: typed, checked reading of a document against a schema of allowed
// keys. Every value comes out in SI (numbers, or quantity strings read by core/units.hpp); every
// message reads "FILE:LINE: key 'a.b': reason" and is thrown as the reader's InputError kind
// (a scene's SceneError, a geometry file's GeometryFileError, ...). Scenes (sim/setup/scene_*.cpp),
// geometry files, thermal studies and shield files are all read with it.
#include <toml++/toml.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/input_error.hpp"
#include "core/join.hpp"
#include "core/schema.hpp"
#include "core/units.hpp"

namespace ejecta::config {

// Allowed keys by schema path ("bodies[]" = any element of [[bodies]]); each a KeySpec
// (core/schema.hpp), which may be a bare name.
using SchemaTables = std::map<std::string_view, KeyList>;

inline bool contains(const KeyList& keys, std::string_view k) {
  for (const KeySpec& a : keys)
    if (a.name == k || a.name == "*") return true;
  return false;
}

inline std::string joinKeys(const KeyList& keys) { return joinList(keys, &KeySpec::name); }

inline std::string typeName(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a floating-point number";
    case toml::node_type::boolean: return "a boolean";
    default: return "a date/time";
  }
}

// Enum spellings in input files.
template <typename E>
using EnumNames = std::vector<std::pair<std::string_view, E>>;

template <typename E>
inline std::string enumList(const EnumNames<E>& names) {
  std::string out;
  for (const auto& [name, value] : names)
    out += (out.empty() ? "'" : ", '") + std::string(name) + "'";
  return out;
}

template <typename Error>
[[noreturn]] void raiseInputError(const std::string& message) {
  throw Error(message);
}

// Where messages point. Values set by --set carry their own source name (see applyOverride).
class Context {
 public:
  // How a reader reports bad input: throws the reader's own InputError kind.
  using Raise = void (*)(const std::string& message);

  Context(std::string sourceName, const toml::table& root, const SchemaTables& schema,
          Raise raise = &raiseInputError<SceneError>)
      : source_(std::move(sourceName)), root_(&root), schema_(&schema), raise_(raise) {}
  const std::string& source() const { return source_; }
  // The keys allowed in the table at `schemaPath` ("bodies[]" = any element), or nullptr.
  const KeyList* allowedKeys(std::string_view schemaPath) const {
    const auto it = schema_->find(schemaPath);
    return it == schema_->end() ? nullptr : &it->second;
  }

  std::string where(const toml::node* n) const {
    if (n && n != root_) {
      const auto& src = n->source();
      if (src.path && *src.path != source_) return source_ + ": " + *src.path;
      if (src.begin.line > 0) return source_ + ":" + std::to_string(src.begin.line);
    }
    return source_ + ":1";  // the document itself (e.g. a missing top-level table)
  }

  [[noreturn]] void fail(const toml::node* at, std::string_view key,
                         const std::string& reason) const {
    raise_(where(at) + ": key '" + std::string(key) + "': " + reason);
    throw InputError("unreachable: Context::Raise returned");  // Raise must throw
  }

 private:
  std::string source_;
  const toml::table* root_;
  const SchemaTables* schema_;
  Raise raise_;
};

// Typed, checked access to one table of a TOML input. Unknown keys are rejected on construction.
class TableReader {
 public:
  TableReader(const Context& ctx, const toml::table& tbl, std::string path, std::string schema)
      : ctx_(ctx), tbl_(tbl), path_(std::move(path)), allowed_(ctx_.allowedKeys(schema)) {
    for (auto&& [k, v] : tbl_) {
      if (!allowed_ || !contains(*allowed_, k.str()))
        ctx_.fail(&v, key(k.str()),
                  "unknown key; allowed keys here: " + (allowed_ ? joinKeys(*allowed_) : "none"));
    }
  }

  // The key's spec in this table's schema, or nullptr.
  const KeySpec* spec(std::string_view k) const {
    return allowed_ ? findKey(*allowed_, k) : nullptr;
  }

  const toml::table& table() const { return tbl_; }
  std::string key(std::string_view k) const {
    return path_.empty() ? std::string(k) : path_ + "." + std::string(k);
  }
  const toml::node* find(std::string_view k) const { return tbl_.get(k); }
  bool has(std::string_view k) const { return find(k) != nullptr; }

  [[noreturn]] void fail(std::string_view k, const std::string& reason) const {
    const toml::node* n = find(k);
    ctx_.fail(n ? n : &tbl_, key(k), reason);
  }
  void check(bool ok, std::string_view k, const std::string& reason) const {
    if (!ok) fail(k, reason);
  }
  const toml::node& require(std::string_view k) const {
    const toml::node* n = find(k);
    if (!n) ctx_.fail(&tbl_, key(k), "required key is missing");
    return *n;
  }

  std::optional<std::string> optString(std::string_view k) const {
    const toml::node* n = find(k);
    if (!n) return std::nullopt;
    if (!n->is_string()) fail(k, "expected a string, got " + typeName(*n));
    return n->value<std::string>();
  }
  std::string requireString(std::string_view k) const {
    require(k);
    return *optString(k);
  }

  std::optional<bool> optBool(std::string_view k) const {
    const toml::node* n = find(k);
    if (!n) return std::nullopt;
    if (!n->is_boolean()) fail(k, "expected true or false, got " + typeName(*n));
    return n->value<bool>();
  }

  std::optional<long> optInteger(std::string_view k) const {
    const toml::node* n = find(k);
    if (!n) return std::nullopt;
    if (!n->is_integer()) fail(k, "expected an integer, got " + typeName(*n));
    return static_cast<long>(*n->value<std::int64_t>());
  }

  // A number (SI) or a quantity string ("10 km/s") of dimension `dim`.
  double quantityOf(const toml::node& n, const std::string& fullKey, Dimension dim) const {
    if (n.is_integer() || n.is_floating_point()) {
      const double x = *n.value<double>();
      if (!std::isfinite(x)) ctx_.fail(&n, fullKey, "must be finite");
      return x;
    }
    if (n.is_string()) {
      try {
        return parseQuantity(*n.value<std::string>(), dim);
      } catch (const UnitError& e) {
        ctx_.fail(&n, fullKey, e.what());
      }
    }
    const std::string unit = siUnit(dim);
    ctx_.fail(&n, fullKey,
              "expected " + describeDimension(dim) + " as a number" +
                  (unit.empty() ? "" : " (SI) or a string such as \"1 " + unit + "\"") + ", got " +
                  typeName(n));
  }
  std::optional<double> optQuantity(std::string_view k, Dimension dim) const {
    const toml::node* n = find(k);
    if (!n) return std::nullopt;
    return quantityOf(*n, key(k), dim);
  }
  double requireQuantity(std::string_view k, Dimension dim) const {
    return quantityOf(require(k), key(k), dim);
  }
  // The same, of the dimension the schema gives the key (a Quantity or Number KeySpec).
  std::optional<double> optQuantity(std::string_view k) const {
    return optQuantity(k, schemaDimension(k));
  }
  double requireQuantity(std::string_view k) const {
    return requireQuantity(k, schemaDimension(k));
  }

  // A vector with exactly `n` components (the scene's dimension); unused components are 0.
  std::optional<std::array<double, 3>> optVector(std::string_view k, Dimension dim, int n,
                                                 std::string_view layout) const {
    const toml::node* node = find(k);
    if (!node) return std::nullopt;
    const toml::array* arr = node->as_array();
    if (!arr) fail(k, "expected an array " + std::string(layout) + ", got " + typeName(*node));
    if (static_cast<int>(arr->size()) != n)
      fail(k, "expected " + std::to_string(n) + " component" + (n == 1 ? "" : "s") + " " +
                  std::string(layout) + ", got " + std::to_string(arr->size()));
    std::array<double, 3> out{};
    for (int i = 0; i < n; ++i)
      out[i] = quantityOf(*arr->get(static_cast<std::size_t>(i)),
                          key(k) + "[" + std::to_string(i) + "]", dim);
    return out;
  }

  std::optional<std::vector<std::string>> optStringArray(std::string_view k) const {
    const toml::node* node = find(k);
    if (!node) return std::nullopt;
    const toml::array* arr = node->as_array();
    if (!arr) fail(k, "expected an array of strings, got " + typeName(*node));
    std::vector<std::string> out;
    for (std::size_t i = 0; i < arr->size(); ++i) {
      const toml::node* e = arr->get(i);
      if (!e->is_string())
        ctx_.fail(e, key(k) + "[" + std::to_string(i) + "]", "expected a string, got " + typeName(*e));
      out.push_back(*e->value<std::string>());
    }
    return out;
  }

  template <typename E>
  std::optional<E> optEnum(std::string_view k, const EnumNames<E>& names) const {
    const std::optional<std::string> text = optString(k);
    if (!text) return std::nullopt;
    for (const auto& [name, value] : names)
      if (name == *text) return value;
    fail(k, "unknown value '" + *text + "'; allowed: " + enumList(names));
  }

  const toml::table* optTable(std::string_view k) const {
    const toml::node* n = find(k);
    if (!n) return nullptr;
    if (!n->is_table()) fail(k, "expected a table, got " + typeName(*n));
    return n->as_table();
  }

  // An array of tables ([[k]]); each element is returned with its index.
  std::vector<const toml::table*> tableArray(std::string_view k) const {
    std::vector<const toml::table*> out;
    const toml::node* n = find(k);
    if (!n) return out;
    const toml::array* arr = n->as_array();
    if (!arr)
      fail(k, "expected an array of tables ([[" + std::string(k) + "]]), got " + typeName(*n));
    for (std::size_t i = 0; i < arr->size(); ++i) {
      const toml::node* e = arr->get(i);
      if (!e->is_table())
        ctx_.fail(e, key(k) + "[" + std::to_string(i) + "]",
                  "expected a table, got " + typeName(*e));
      out.push_back(e->as_table());
    }
    return out;
  }

  const Context& context() const { return ctx_; }

 private:
  // A reader asking for a key its schema does not give a dimension is a bug, not bad input.
  Dimension schemaDimension(std::string_view k) const {
    const KeySpec* s = spec(k);
    if (!s || (s->kind != KeyKind::Quantity && s->kind != KeyKind::Number)) {
      std::string what = "schema: key '";
      what += key(k);
      throw std::logic_error(what + "' is not a quantity in its schema");
    }
    return s->dimension;
  }

  const Context& ctx_;
  const toml::table& tbl_;
  std::string path_;
  const KeyList* allowed_;
};

// The line a node starts on in its file.
inline int lineOf(const toml::node& n) { return static_cast<int>(n.source().begin.line); }

inline std::string positiveMessage(double v, Dimension d) {
  return "must be positive (got " + formatQuantity(v, d) + ")";
}
inline std::string nonNegativeMessage(double v, Dimension d) {
  return "must not be negative (got " + formatQuantity(v, d) + ")";
}

}  // namespace ejecta::config
