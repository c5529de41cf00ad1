// The scene's schema, assembled from its section groups (scene_schema_*.cpp).
#include "sim/setup/scene_schema.hpp"

#include "sim/setup/scene_sections.hpp"

namespace ejecta {

const std::vector<SceneTable>& sceneTables() {
  static const std::vector<SceneTable> tables = [] {
    std::vector<SceneTable> all;
    for (auto part : {&scene_schema_detail::runTables, &scene_schema_detail::outputTables,
                      &scene_schema_detail::materialTables, &scene_schema_detail::bodyTables})
      for (SceneTable& t : part()) all.push_back(std::move(t));
    return all;
  }();
  return tables;
}

const config::SchemaTables& sceneSchema() {
  static const config::SchemaTables schema = [] {
    config::SchemaTables out;
    for (const SceneTable& t : sceneTables()) out.emplace(t.path, t.keys);
    return out;
  }();
  return schema;
}

namespace scene_detail {

const SchemaTables& schemaTables() { return sceneSchema(); }

const KeyList* allowedKeys(std::string_view schemaPath) {
  const SchemaTables& tables = schemaTables();
  const auto it = tables.find(schemaPath);
  return it == tables.end() ? nullptr : &it->second;
}

}  // namespace scene_detail

}  // namespace ejecta
