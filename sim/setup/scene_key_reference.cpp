// The key reference of docs/scenes.md, generated from the scene's schema (scene_schema.hpp), the
// eos catalog and the material model families: `ejecta keys --markdown` prints it, and
// tests/sim/setup/test_scene_key_reference.cpp checks that the doc holds exactly this text.
#include <sstream>
#include <stdexcept>
#include <string>

#include <toml++/toml.h>

#include "sim/eos/eos_catalog.hpp"
#include "sim/setup/scene_schema.hpp"
#include "sim/solid/model_keys.hpp"
#include "sim/solid/strength_library.hpp"
#include "sim/solid/thermal.hpp"

namespace ejecta {

namespace {

using config::KeyKind;
using config::KeySpec;

// A Markdown table cell: '|' would end the cell.
std::string cell(std::string_view text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '|' && (i == 0 || text[i - 1] != '\\')) out += '\\';
    out += text[i];
  }
  return out;
}

// A default written as a TOML value is shown as code; prose ("required", "the bodies at rest")
// as it is.
bool isTomlValue(std::string_view text) {
  if (text.empty() || text == "required") return false;
  try {
    std::string doc = "v = ";
    doc += text;
    const toml::table t = toml::parse(doc);
    return t.size() == 1;
  } catch (const toml::parse_error&) {
    return false;
  }
}

std::string defaultCell(const KeySpec& k) {
  if (k.defaultText.empty()) return "—";
  if (isTomlValue(k.defaultText)) {
    std::string code = "`";
    code += cell(k.defaultText);
    return code + "`";
  }
  return cell(k.defaultText);
}

std::string quoted(std::string_view v) {
  std::string out = "`\"";
  out += v;
  return out + "\"`";
}

// An enum's values lead its meaning unless the doc already names each of them.
std::string meaningCell(const KeySpec& k) {
  std::string doc(k.doc);
  if (k.kind != KeyKind::Enum) return cell(doc);
  bool named = true;
  for (std::string_view v : k.allowed) named = named && doc.find(quoted(v)) != std::string::npos;
  if (named) return cell(doc);
  std::string values;
  for (std::size_t i = 0; i < k.allowed.size(); ++i) {
    if (i > 0) values += i + 1 == k.allowed.size() ? " or " : ", ";
    values += quoted(k.allowed[i]);
  }
  return cell(doc.empty() ? values : values + ": " + doc);
}

void keyTable(std::ostream& os, const config::KeyList& keys) {
  os << "| key | type | default | meaning |\n|---|---|---|---|\n";
  for (const KeySpec& k : keys)
    os << "| " << k.name << " | " << cell(config::kindText(k)) << " | " << defaultCell(k) << " | "
       << meaningCell(k) << " |\n";
}

template <typename Names>
std::string joined(const Names& names) {
  std::string out;
  for (const auto& n : names) {
    if (!out.empty()) out += ", ";
    out += n;
  }
  return out;
}

void eosSection(std::ostream& os) {
  os << "\n#### `[materials.parameters]`\n\nThe keys depend on the material's `eos`; each is a "
        "number (SI) or a quantity (sources and equations: `docs/eos_tillotson.md`, "
        "`docs/eos_shock_jwl.md`).\n";
  for (const EosKind& kind : eosKinds()) {
    os << "\n`eos = \"" << kind.name << "\"`: " << kind.doc << ".";
    if (!kind.libraryNames.empty()) os << " Library: " << joined(kind.libraryNames) << ".";
    if (kind.parameters.empty()) {
      os << " No parameters";
      if (!kind.constantsElsewhere.empty()) os << ": " << kind.constantsElsewhere;
      os << ".\n";
      continue;
    }
    os << "\n\n| parameter | type | meaning |\n|---|---|---|\n";
    for (const EosParameter& p : kind.parameters) {
      const std::string unit = siUnit(p.dimension);
      os << "| " << p.key << " | " << (unit.empty() ? "number" : "Q [" + unit + "]") << " | "
         << cell(p.doc) << " |\n";
    }
  }
}

void modelTable(std::ostream& os, const ModelFamily& family) {
  os << "\n| model | its keys | meaning |\n|---|---|---|\n";
  for (const ModelKind& m : family.models)
    os << "| " << m.name << " | " << (m.keys.empty() ? "—" : joined(m.keys)) << " | "
       << cell(m.doc) << " |\n";
}

std::vector<std::string> strengthLibraryNames() {
  std::vector<std::string> out;
  for (const StrengthLibraryEntry& e : strengthLibrary()) out.push_back(e.name);
  return out;
}
std::vector<std::string> thermalLibraryNames() {
  std::vector<std::string> out;
  for (const ThermalLibraryEntry& e : thermalLibrary()) out.push_back(e.name);
  return out;
}

}  // namespace

std::string sceneKeyReferenceMarkdown() {
  std::ostringstream os;
  os << "Q = quantity: a number in SI or a string with units, [unit] its SI unit. A vector has "
        "one entry per coordinate of the scene (`[x]`, `[x, y]`, `[r, z]`, `[x, y, z]`).\n";
  for (const SceneTable& t : sceneTables()) {
    if (t.heading.empty()) continue;
    const bool model = t.path.rfind("materials[].", 0) == 0;
    os << "\n" << (model ? "#### " : "### ") << t.heading << "\n\n";
    if (!t.summary.empty()) os << t.summary << "\n\n";
    keyTable(os, t.keys);
    if (t.path == "materials[]") eosSection(os);
    if (t.path == "materials[].thermal")
      os << "\nLibrary: " << joined(thermalLibraryNames()) << ".\n";
    if (t.path == "materials[].strength") {
      modelTable(os, strengthModelFamily());
      os << "\nLibrary: " << joined(strengthLibraryNames()) << ".\n";
    }
    if (t.path == "materials[].fracture") modelTable(os, fractureModelFamily());
    if (t.path == "materials[].porosity") modelTable(os, porosityModelFamily());
    if (t.path == "bodies[]") {
      os << "\n| shape | its keys | meaning |\n|---|---|---|\n";
      for (const SceneShape& shape : sceneShapes())
        os << "| " << shape.name << " | " << joined(shape.keys) << " | " << cell(shape.doc)
           << " |\n";
    }
  }
  return os.str();
}

namespace {

// Where the generated text lies in `doc`: [begin, end).
std::pair<std::size_t, std::size_t> referenceSpan(const std::string& doc) {
  const std::size_t b = doc.find(kKeyReferenceBegin);
  const std::size_t e = doc.find(kKeyReferenceEnd);
  if (b == std::string::npos || e == std::string::npos || e < b) {
    std::string what = "no key reference markers (";
    what += kKeyReferenceBegin;
    what += " ... ";
    what += kKeyReferenceEnd;
    throw std::invalid_argument(what + ")");
  }
  return {b + kKeyReferenceBegin.size(), e};
}

}  // namespace

std::string keyReferenceIn(const std::string& doc) {
  const auto [b, e] = referenceSpan(doc);
  std::string text = doc.substr(b, e - b);
  const std::size_t first = text.find_first_not_of('\n');
  const std::size_t last = text.find_last_not_of('\n');
  return first == std::string::npos ? "" : text.substr(first, last - first + 1) + "\n";
}

std::string withCurrentKeyReference(const std::string& doc) {
  const auto [b, e] = referenceSpan(doc);
  return doc.substr(0, b) + "\n\n" + sceneKeyReferenceMarkdown() + "\n" + doc.substr(e);
}

}  // namespace ejecta
