#pragma once
// The scene's schema: every table a scene may hold and, for each key, its kind, dimension (SI),
// default, allowed values and doc. It is the one source of the reader's allowed keys (and so of
// its unknown-key errors) and of the key reference in docs/scenes.md, which
// sceneKeyReferenceMarkdown() generates (`ejecta keys --markdown`; tests compare the two).
// The tables are written in scene_schema_*.cpp by section group, like the readers.
#include <string>
#include <string_view>
#include <vector>

#include "core/table_reader.hpp"

namespace ejecta {

struct SceneTable {
  std::string_view path;     // schema path: "sph.viscosity", "bodies[]"; "" = the document
  std::string_view heading;  // its heading in the key reference; "" = not listed on its own
  std::string_view summary;  // a line under the heading (may be empty)
  config::KeyList keys;      // in the order the unknown-key message lists them
};

// A shape of [[bodies]] and the keys it takes there (keys of another shape are errors).
struct SceneShape {
  std::string_view name;
  std::vector<std::string_view> keys;
  std::string_view doc;
};
// Every shape, in the order of the key reference ("paraboloid": void bodies only).
const std::vector<SceneShape>& sceneShapes();
const SceneShape& sceneShape(std::string_view name);  // throws std::out_of_range if none

// Every table, in the order of the key reference.
const std::vector<SceneTable>& sceneTables();
// The same, by schema path, for the reader (core/table_reader.hpp).
const config::SchemaTables& sceneSchema();

// The key reference of docs/scenes.md, as Markdown: the tables of the schema, the eos parameters
// of sim/eos/eos_catalog.hpp and the material models of sim/solid/model_keys.hpp.
std::string sceneKeyReferenceMarkdown();
// The markers around it in docs/scenes.md.
inline constexpr std::string_view kKeyReferenceBegin =
    "<!-- BEGIN GENERATED KEY REFERENCE (ejecta keys --markdown) -->";
inline constexpr std::string_view kKeyReferenceEnd = "<!-- END GENERATED KEY REFERENCE -->";
// The text between the markers of `doc` (without the blank lines next to them); throws
// std::invalid_argument when a marker is missing.
std::string keyReferenceIn(const std::string& doc);
// `doc` with the text between its markers replaced by sceneKeyReferenceMarkdown().
std::string withCurrentKeyReference(const std::string& doc);

namespace scene_schema_detail {
std::vector<SceneTable> runTables();       // document, [scene], [domain], [sph], [time], [output]
std::vector<SceneTable> outputTables();    // [fields], [crater], [images], [thermal]
std::vector<SceneTable> materialTables();  // [[materials]] and its model tables
std::vector<SceneTable> bodyTables();      // [[bodies]], [[energy_deposits]], [[detonations]], [[gauges]]
}  // namespace scene_schema_detail

}  // namespace ejecta
