// The command line's --set: "dotted.key=value" applied to the scene document before validation.
#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <string>

#include "core/json.hpp"
#include "sim/setup/scene_sections.hpp"

namespace ejecta::scene_detail {

// ---------------------------------------------------------------------------------------------
// --set overrides

namespace {

struct PathPart {
  std::string key;                   // empty for an index
  std::optional<std::size_t> index;  // "[i]"
};

std::vector<PathPart> splitKeyPath(std::string_view path) {
  std::vector<PathPart> parts;
  std::size_t pos = 0;
  while (pos < path.size()) {
    if (path[pos] == '[') {
      const std::size_t close = path.find(']', pos);
      if (close == std::string_view::npos || close == pos + 1 || close > pos + 9 || parts.empty())
        return {};
      std::size_t idx = 0;
      for (std::size_t i = pos + 1; i < close; ++i) {
        if (path[i] < '0' || path[i] > '9') return {};
        idx = idx * 10 + static_cast<std::size_t>(path[i] - '0');
      }
      parts.push_back({"", idx});
      pos = close + 1;
      if (pos < path.size() && path[pos] == '.') ++pos;
      continue;
    }
    std::size_t end = pos;
    while (end < path.size() && path[end] != '.' && path[end] != '[') ++end;
    if (end == pos) return {};
    parts.push_back({std::string(path.substr(pos, end - pos)), std::nullopt});
    pos = end;
    if (pos < path.size() && path[pos] == '.') {
      ++pos;
      if (pos == path.size()) return {};
    }
  }
  return parts;
}

std::string trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return std::string(s);
}

// The override's value as a TOML node if the text is a TOML value, else as a string. Parsing
// with `label` as the source path makes every message about this value name the --set.
toml::table parseOverrideValue(const std::string& text, const std::string& label) {
  try {
    toml::table doc = toml::parse("v = " + text, label);
    if (doc.size() == 1 && doc.contains("v")) return doc;
  } catch (const toml::parse_error&) {
    // not a TOML value: fall through to a string
  }
  // A JSON string literal is a TOML basic string too (the same escapes: \" \\ \n \uXXXX).
  return toml::parse("v = " + jsonString(text), label);
}

}  // namespace

void applyOverride(toml::table& root, const std::string& text, const std::string& sourceName) {
  const std::string label = "--set '" + text + "'";
  auto bad = [&](const std::string& reason) -> SceneError {
    return SceneError(sourceName + ": " + label + ": " + reason);
  };
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos) throw bad("expected KEY=VALUE");
  const std::string keyPath = trimmed(std::string_view(text).substr(0, eq));
  const std::vector<PathPart> parts = splitKeyPath(keyPath);
  if (parts.empty())
    throw bad("malformed key '" + keyPath + "' (use e.g. sph.kernel or bodies[0].spacing)");
  toml::table valueDoc = parseOverrideValue(trimmed(std::string_view(text).substr(eq + 1)), label);
  toml::node& value = *valueDoc.get("v");

  toml::node* cur = &root;
  std::string schema;  // schema path of `cur`
  std::string dotted;  // key path of `cur`, for messages
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const PathPart& part = parts[i];
    const bool last = (i + 1 == parts.size());
    if (part.index) {
      toml::array* arr = cur->as_array();
      if (!arr) throw bad("key '" + dotted + "' is not an array");
      if (*part.index >= arr->size())
        throw bad("key '" + dotted + "' has " + std::to_string(arr->size()) +
                  " element(s); no index " + std::to_string(*part.index));
      dotted += '[';
      dotted += std::to_string(*part.index);
      dotted += ']';
      if (allowedKeys(schema + "[]")) schema += "[]";
      if (last) {
        arr->replace(arr->cbegin() + static_cast<std::ptrdiff_t>(*part.index), std::move(value));
        return;
      }
      cur = arr->get(*part.index);
      continue;
    }
    const KeyList* allowed = allowedKeys(schema);
    const std::string childKey = dotted.empty() ? part.key : dotted + "." + part.key;
    if (!allowed) throw bad("key '" + dotted + "' has no sub-keys");
    if (!contains(*allowed, part.key))
      throw bad("unknown key '" + childKey + "'; allowed keys " +
                (dotted.empty() ? std::string("at the top level") : "in '" + dotted + "'") + ": " +
                joinKeys(*allowed));
    toml::table* tbl = cur->as_table();
    if (!tbl) throw bad("key '" + dotted + "' is not a table");
    const std::string childSchema = schema.empty() ? part.key : schema + "." + part.key;
    if (last) {
      tbl->insert_or_assign(part.key, std::move(value));
      return;
    }
    if (!tbl->contains(part.key)) {
      if (!allowedKeys(childSchema)) throw bad("key '" + childKey + "' does not exist");
      // Parsed rather than constructed so that the new table's source names this --set.
      toml::table empty = toml::parse("t = {}", label);
      tbl->insert_or_assign(part.key, std::move(*empty.get("t")));
    }
    cur = tbl->get(part.key);
    schema = childSchema;
    dotted = childKey;
  }
}

}  // namespace ejecta::scene_detail
