#include "sim/materials.hpp"

#include "sim/eos_catalog.hpp"
#include "sim/scene.hpp"

namespace ejecta {

MaterialTable MaterialTable::fromScene(const Scene& scene) {
  MaterialTable table;
  for (const MaterialSpec& spec : scene.materials) {
    try {
      table.add({spec.name, makeEquationOfState(spec)});
    } catch (const std::invalid_argument& e) {
      throw SceneError(scene.sourcePath + ":" + std::to_string(spec.line) + ": material '" +
                       spec.name + "': " + e.what());
    }
  }
  return table;
}

}  // namespace ejecta
