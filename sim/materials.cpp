#include "sim/materials.hpp"

#include "sim/scene.hpp"

namespace ejecta {

MaterialTable MaterialTable::fromScene(const Scene& scene) {
  MaterialTable table;
  for (const MaterialSpec& spec : scene.materials) {
    if (spec.eos == "ideal_gas") {
      table.add({spec.name, std::make_shared<IdealGas>(spec.gamma)});
    } else {
      throw SceneError(scene.sourcePath + ":" + std::to_string(spec.line) + ": material '" +
                       spec.name + "': unknown eos '" + spec.eos + "'");
    }
  }
  return table;
}

}  // namespace ejecta
