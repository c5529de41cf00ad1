#pragma once
// The error a one-body 1D scene gives when its materials are built: the message of the
// SceneError that parsing or MaterialTable::fromScene throws, or "no error". Shared by the tests
// that check bad material keys are named (strength, fracture, rock strength).
#include <string>

#include "sim/solid/materials.hpp"
#include "sim/setup/scene.hpp"

namespace ejecta::test {

inline std::string materialSceneError(const std::string& sceneText) {
  try {
    const Scene s = parseScene(sceneText, "bad.toml");
    MaterialTable::fromScene(s);
  } catch (const SceneError& e) {
    return std::string(e.what());
  }
  return std::string("no error");
}

}  // namespace ejecta::test
