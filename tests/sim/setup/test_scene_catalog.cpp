// The shipped scenes by name (sim/setup/scene_catalog.hpp): every file has a kind and a
// description, every [scene] file parses, names resolve exactly, by their last part, and refuse
// clearly when missing or ambiguous; a file on disk wins over a shipped name.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "core/input_error.hpp"
#include "sim/setup/scene.hpp"
#include "sim/setup/scene_catalog.hpp"

namespace ejecta {
namespace {

namespace fs = std::filesystem;

TEST(SceneCatalog, EveryShippedFileHasAKindAndADescription) {
  const std::vector<ShippedScene> scenes = shippedScenes();
  // One entry per file under scenes/ (the CMake glob embeds them all).
  std::size_t files = 0;
  for (const auto& e : fs::recursive_directory_iterator(fs::path(EJECTA_SOURCE_DIR) / "scenes"))
    if (e.path().extension() == ".toml") ++files;
  EXPECT_EQ(scenes.size(), files);
  std::set<std::string> kinds;
  for (const ShippedScene& s : scenes) {
    EXPECT_FALSE(s.kind.empty()) << s.name << ": no [scene], [geometry] or [study] table";
    EXPECT_FALSE(s.title.empty()) << s.name;
    kinds.insert(s.kind);
  }
  EXPECT_EQ(kinds, (std::set<std::string>{"geometry", "scene", "study"}));
  EXPECT_TRUE(std::is_sorted(scenes.begin(), scenes.end(),
                             [](const auto& a, const auto& b) { return a.name < b.name; }));
}

TEST(SceneCatalog, EveryRunnableSceneParses) {
  for (const ShippedScene& s : shippedScenes()) {
    if (s.kind != "scene") continue;
    EXPECT_NO_THROW(parseScene(std::string(s.text), s.name)) << s.name;
    EXPECT_FALSE(s.description.empty()) << s.name << ": `ejecta scenes` would show no description";
  }
}

TEST(SceneCatalog, NamesResolveExactlyAndByTheirLastPart) {
  const ShippedScene* full = findShippedScene("verification/sod_1d");
  ASSERT_NE(full, nullptr);
  EXPECT_EQ(full->kind, "scene");
  EXPECT_EQ(findShippedScene("sod_1d"), full);
  EXPECT_EQ(findShippedScene("sod_1d.toml"), full);
  ASSERT_NE(findShippedScene("impact_rz"), nullptr);
  EXPECT_EQ(findShippedScene("impact_rz")->name, "impact_rz");
  EXPECT_EQ(findShippedScene("no_such_scene"), nullptr);
  EXPECT_EQ(findShippedScene(""), nullptr);
  EXPECT_EQ(findShippedScene("other/sod_1d"), nullptr);  // a path is matched whole
}

TEST(SceneCatalog, AnAmbiguousShortNameListsTheCandidates) {
  const std::vector<ShippedScene> scenes = {{"a/follower", "study", "f", "", ""},
                                            {"b/follower", "scene", "f", "", ""},
                                            {"follower_rz", "scene", "g", "", ""}};
  std::vector<std::string> ambiguous;
  EXPECT_EQ(findScene(scenes, "follower", &ambiguous), nullptr);
  EXPECT_EQ(ambiguous, (std::vector<std::string>{"a/follower", "b/follower"}));
  EXPECT_EQ(findScene(scenes, "b/follower"), &scenes[1]);
  EXPECT_EQ(findScene(scenes, "follower_rz"), &scenes[2]);
}

TEST(SceneCatalog, AFileOnDiskWinsOverAShippedName) {
  const fs::path dir = fs::temp_directory_path() / "ejecta_scene_catalog_test";
  fs::create_directories(dir);
  const fs::path file = dir / "impact_rz";
  { std::ofstream(file) << "# not the shipped one\n"; }
  const fs::path cwd = fs::current_path();
  fs::current_path(dir);
  const SceneText local = readSceneArgument("impact_rz");
  fs::current_path(cwd);
  EXPECT_EQ(local.text, "# not the shipped one\n");
  EXPECT_EQ(local.label, "impact_rz");
  // A directory of the name (a run's --out) does not hide the shipped scene.
  fs::remove(file);
  fs::create_directories(dir / "impact_rz");
  fs::current_path(dir);
  const SceneText overDirectory = readSceneArgument("impact_rz");
  fs::current_path(cwd);
  EXPECT_EQ(overDirectory.label, "shipped scene 'impact_rz'");
  const SceneText shipped = readSceneArgument("impact_rz");
  EXPECT_EQ(shipped.label, "shipped scene 'impact_rz'");
  EXPECT_EQ(shipped.text, std::string(findShippedScene("impact_rz")->text));
  // Relative paths in a file resolve beside it; a shipped file's against the current directory.
  EXPECT_EQ(local.directory, fs::path());  // a bare name: the current directory
  { std::ofstream(dir / "study.toml") << "x = 1\n"; }
  EXPECT_EQ(readSceneArgument((dir / "study.toml").string()).directory, dir);
  EXPECT_EQ(shipped.directory, fs::path());
  fs::remove_all(dir);
}

TEST(SceneCatalog, RefusalsNameTheArgumentAndTheReason) {
  try {
    readSceneArgument("impact_zr");
    FAIL() << "no error";
  } catch (const SceneError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("impact_zr"), std::string::npos) << what;
    EXPECT_NE(what.find("ejecta scenes"), std::string::npos) << what;
  }
  // An empty file is read (and then refused by the scene reader, which names the key).
  const fs::path empty = fs::temp_directory_path() / "ejecta_empty_scene.toml";
  { std::ofstream touch(empty); }
  EXPECT_EQ(readSceneArgument(empty.string()).text, "");
  fs::remove(empty);
  try {
    readSceneArgument(fs::temp_directory_path().string());
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("is a directory"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("ejecta run --restart"), std::string::npos) << e.what();
  }
  // A study's messages name its kind, without the run's --restart pointer.
  try {
    readSceneArgument(fs::temp_directory_path().string(), "thermal study");
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("is a directory, not a thermal study file"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find("--restart"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ejecta
