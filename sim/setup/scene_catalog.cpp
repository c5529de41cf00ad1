#include "sim/setup/scene_catalog.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/input_error.hpp"
#include "core/join.hpp"
#include "sim/setup/embedded_scenes.hpp"

namespace ejecta {

namespace {

constexpr std::string_view kKinds[] = {"scene", "geometry", "study"};

ShippedScene describe(const EmbeddedScene& embedded) {
  ShippedScene s;
  s.name = std::string(embedded.name);
  s.text = embedded.text;
  // Shipped files are checked by the tests (test_scene_catalog.cpp); a file that does not parse
  // still lists, with no kind, rather than hiding the others.
  toml::table doc;
  try {
    doc = toml::parse(embedded.text, s.name);
  } catch (const toml::parse_error&) {
    return s;
  }
  for (const std::string_view kind : kKinds) {
    if (const toml::table* t = doc[kind].as_table()) {
      s.kind = std::string(kind);
      s.title = (*t)["name"].value_or(std::string());
      s.description = (*t)["description"].value_or(std::string());
      break;
    }
  }
  return s;
}

std::string_view withoutToml(std::string_view name) {
  constexpr std::string_view suffix = ".toml";
  if (name.size() > suffix.size() && name.substr(name.size() - suffix.size()) == suffix)
    name.remove_suffix(suffix.size());
  return name;
}

std::string_view lastPart(std::string_view name) {
  const std::size_t slash = name.rfind('/');
  return slash == std::string_view::npos ? name : name.substr(slash + 1);
}

const std::vector<ShippedScene>& catalog() {
  static const std::vector<ShippedScene> scenes = [] {
    std::vector<ShippedScene> out;
    for (const EmbeddedScene& e : embeddedScenes()) out.push_back(describe(e));
    std::sort(out.begin(), out.end(),
              [](const ShippedScene& a, const ShippedScene& b) { return a.name < b.name; });
    return out;
  }();
  return scenes;
}

}  // namespace

std::vector<ShippedScene> shippedScenes() { return catalog(); }

const ShippedScene* findShippedScene(std::string_view name, std::vector<std::string>* ambiguous) {
  return findScene(catalog(), name, ambiguous);
}

const ShippedScene* findScene(const std::vector<ShippedScene>& scenes, std::string_view name,
                              std::vector<std::string>* ambiguous) {
  name = withoutToml(name);
  if (name.empty()) return nullptr;
  for (const ShippedScene& s : scenes)
    if (s.name == name) return &s;
  if (name.find('/') != std::string_view::npos) return nullptr;
  const ShippedScene* found = nullptr;
  std::vector<std::string> candidates;
  for (const ShippedScene& s : scenes) {
    if (lastPart(s.name) != name) continue;
    found = &s;
    candidates.push_back(s.name);
  }
  if (candidates.size() > 1) {
    if (ambiguous) *ambiguous = candidates;
    return nullptr;
  }
  return found;
}

SceneText readSceneArgument(const std::string& argument, const std::string& what) {
  namespace fs = std::filesystem;
  std::error_code ec;
  // A directory of that name (a run's --out) does not hide a shipped scene.
  if (fs::is_directory(argument, ec) && !findShippedScene(argument))
    throw SceneError(argument + ": is a directory, not a " + what + " file" +
                     (what == "scene" ? " (to resume the run in it: ejecta run --restart " + argument + ")" : ""));
  if (fs::exists(argument, ec) && !fs::is_directory(argument, ec)) {
    std::ifstream in(argument, std::ios::binary);
    if (!in) throw SceneError(argument + ": cannot open the " + what + " file");
    std::ostringstream text;
    text << in.rdbuf();  // (an empty file sets the failbit of `text`: that is no error)
    if (in.bad()) throw SceneError(argument + ": cannot read the " + what + " file");
    return {text.str(), argument, fs::path(argument).parent_path()};
  }
  std::vector<std::string> ambiguous;
  if (const ShippedScene* s = findShippedScene(argument, &ambiguous))
    return {std::string(s->text), "shipped scene '" + s->name + "'", {}};
  if (!ambiguous.empty()) {
    throw SceneError(argument + ": several shipped scenes have this name (" + joinList(ambiguous) +
                     "): give the full name");
  }
  throw SceneError(argument + ": cannot open: no such file, and no shipped scene of that name "
                   "(`ejecta scenes` lists them)");
}

}  // namespace ejecta
