// Scene files: TOML parsed by toml++, overrides applied to the tree, then every key checked
// against the schema (scene_schema.cpp) and converted to SI by the sections (scene_*_sections.cpp,
// scene_materials.cpp, scene_bodies.cpp, scene_sources.cpp). Messages follow
// "FILE:LINE: key 'a.b': reason".
#include "sim/setup/scene.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "sim/setup/resting_bodies.hpp"
#include "sim/setup/scene_sections.hpp"

namespace ejecta {

using namespace scene_detail;

namespace {

Scene validate(const toml::table& doc, const std::string& sourceName) {
  const Context ctx(sourceName, doc, schemaTables());
  const TableReader root(ctx, doc, "", "");
  Scene scene;
  scene.sourcePath = sourceName;
  readScene(root, scene);
  readDomain(root, scene);
  readTime(root, scene.time);
  readSph(root, scene.sph);
  readOutput(root, scene.output, scene.time.tEnd);
  readMaterials(root, scene);
  checkGradientScheme(root, scene);
  checkVolumeElements(root, scene);
  checkDissipation(root, scene);
  readBodies(root, scene);
  placeRestingBodies(scene);  // before anything reads where the bodies are
  readDeposits(root, scene);
  readDetonations(root, scene);
  readGauges(root, scene);
  readFields(root, scene);
  readCrater(root, scene);
  readFragments(root, scene);
  readShield(root, scene);
  readImages(root, scene);
  readThermal(root, scene);
  return scene;
}

}  // namespace

Scene parseScene(const std::string& tomlText, const std::string& sourceName,
                 const std::vector<std::string>& overrides) {
  toml::table doc;
  try {
    doc = toml::parse(tomlText, sourceName);
  } catch (const toml::parse_error& e) {
    throw SceneError(sourceName + ":" + std::to_string(e.source().begin.line) +
                     ": TOML syntax error: " + std::string(e.description()));
  }
  for (const std::string& o : overrides) applyOverride(doc, o, sourceName);
  return validate(doc, sourceName);
}

Scene loadScene(const std::string& path, const std::vector<std::string>& overrides) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw SceneError(path + ": is a directory, not a scene file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path + ": cannot open the scene file");
  std::ostringstream text;
  text << in.rdbuf();
  return parseScene(text.str(), path, overrides);
}

}  // namespace ejecta
