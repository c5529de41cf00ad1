#pragma once
// The scenes shipped with ejecta (scenes/, compiled in by cmake/EmbedScenes.cmake), listed with
// what each is and which command takes it, and found by name: `ejecta run impact_rz` works from
// any directory, `ejecta scenes` lists them, `ejecta scenes show NAME` prints one as a template.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace ejecta {

struct ShippedScene {
  std::string name;         // path under scenes/ without ".toml": "impact_rz", "verification/sod_1d"
  std::string kind;         // which of its tables it has, in this order: "scene" (ejecta run),
                            // "geometry" (ejecta viewfactor) or "study" (ejecta thermal / whipple)
  std::string title;        // the table's `name` key
  std::string description;  // the table's `description` key (may be empty)
  std::string_view text;    // the whole file
};

// Every shipped file, sorted by name.
std::vector<ShippedScene> shippedScenes();

// The shipped scene called `name`: its full name ("verification/sod_1d"), or the last part of it
// ("sod_1d") when only one scene has that last part; a trailing ".toml" is ignored. Returns
// nullptr when there is none (or the short name is ambiguous: `ambiguous` then lists the
// candidates, if given).
const ShippedScene* findShippedScene(std::string_view name,
                                     std::vector<std::string>* ambiguous = nullptr);
// The same lookup over any list (the tests give one with clashing short names).
const ShippedScene* findScene(const std::vector<ShippedScene>& scenes, std::string_view name,
                              std::vector<std::string>* ambiguous = nullptr);

// Where a scene argument comes from, and its text.
struct SceneText {
  std::string text;
  std::string label;  // the path, or "shipped scene 'impact_rz'" (names the source in errors)
  // The directory a file's relative paths (a study's mesh) resolve against: the file's own;
  // empty for a shipped file (the current directory, as a scene's shipped study has).
  std::filesystem::path directory;
};

// A path to an existing file wins; otherwise a shipped scene's name (also over a directory of
// that name, such as a run's --out). Throws SceneError naming
// the argument and the reason ("no such file and no shipped scene ...", a directory, unreadable,
// an ambiguous short name) with a pointer to `ejecta scenes`. `what` names the kind of file in
// those messages ("thermal study", "Whipple study", "geometry"); only a scene's directory gets
// the pointer to `ejecta run --restart`.
SceneText readSceneArgument(const std::string& argument, const std::string& what = "scene");

}  // namespace ejecta
