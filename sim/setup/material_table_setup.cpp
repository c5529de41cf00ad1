// The scene's materials as a MaterialTable (sim/solid/materials.hpp).
#include "sim/setup/scene.hpp"
#include "sim/solid/materials.hpp"

namespace ejecta {

MaterialTable MaterialTable::fromScene(const Scene& scene) {
  return fromSpecs(scene.materials, scene.sourcePath);
}

}  // namespace ejecta
