// `ejecta keys`: the keys a scene may hold, from the scene's schema (sim/setup/scene_schema.hpp).
// With --markdown, the key reference that docs/scenes.md holds between its markers.
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "apps/commands.hpp"
#include "core/atomic_file.hpp"
#include "sim/setup/scene_schema.hpp"

namespace ejecta::app {

int keysCommand(const KeysArgs& args) {
  if (!args.write.empty()) {
    std::ifstream in(args.write, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + args.write);
    std::stringstream text;
    text << in.rdbuf();
    writeFileAtomically(args.write, withCurrentKeyReference(text.str()));
    std::fprintf(stderr, "ejecta: %s: key reference regenerated\n", args.write.c_str());
    return 0;
  }
  if (args.markdown) {
    std::fputs(sceneKeyReferenceMarkdown().c_str(), stdout);
    return 0;
  }
  // One line per key: path.key  type  default  doc.
  for (const SceneTable& t : sceneTables()) {
    for (const config::KeySpec& k : t.keys) {
      std::string path(t.path);
      if (!path.empty()) path += '.';
      path += k.name;
      const std::string type = config::kindText(k);
      std::printf("%-40s %-22s %-28s %s\n", path.c_str(), type.c_str(),
                  std::string(k.defaultText.empty() ? "-" : k.defaultText).c_str(),
                  std::string(k.doc).c_str());
    }
  }
  return 0;
}

}  // namespace ejecta::app
