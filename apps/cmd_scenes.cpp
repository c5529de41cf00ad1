// `ejecta scenes`: the scenes shipped with ejecta, what each is and the command that takes it;
// `ejecta scenes show NAME` prints one, to run as it is or to copy as a template.
#include <cstdio>
#include <stdexcept>
#include <string>

#include "apps/commands.hpp"
#include "sim/setup/scene_catalog.hpp"

namespace ejecta::app {

namespace {

const char* commandFor(const std::string& kind) {
  if (kind == "scene") return "ejecta run";
  if (kind == "geometry") return "ejecta viewfactor";
  if (kind == "study") return "ejecta thermal / whipple";
  return "-";
}

}  // namespace

int scenesCommand(const ScenesArgs& args) {
  if (!args.show.empty()) {
    std::vector<std::string> ambiguous;
    const ShippedScene* s = findShippedScene(args.show, &ambiguous);
    if (!s) {
      std::string reason = "no shipped scene of that name (`ejecta scenes` lists them)";
      if (!ambiguous.empty()) {
        reason = "several shipped scenes have this name:";
        for (const std::string& c : ambiguous) reason += " " + c;
      }
      throw std::runtime_error(args.show + ": " + reason);
    }
    std::fwrite(s->text.data(), 1, s->text.size(), stdout);
    return 0;
  }
  if (!args.kind.empty() && args.kind != "scene" && args.kind != "geometry" && args.kind != "study")
    throw std::runtime_error("--kind must be scene, geometry or study, not '" + args.kind + "'");
  // Scenes are run by name (`ejecta run impact_rz`); the others are printed to a file first
  // (`ejecta scenes show geometry/seed_follower > g.toml`), since those commands take paths.
  std::printf("%-36s %-26s %s\n", "name", "taken by", "description");
  for (const ShippedScene& s : shippedScenes()) {
    if (!args.kind.empty() && s.kind != args.kind) continue;
    std::printf("%-36s %-26s %s\n", s.name.c_str(), commandFor(s.kind),
                (s.description.empty() ? s.title : s.description).c_str());
  }
  return 0;
}

}  // namespace ejecta::app
