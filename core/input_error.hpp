#pragma once
// The error every scene, geometry and study reader throws for bad input.
#include <stdexcept>

namespace ejecta {

// Thrown for any bad scene: the message names the file, the line (when known), the key and the
// reason, e.g. "scenes/x.toml:12: key 'bodies[1].spacing': must be positive (got -0.1 m)".
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace ejecta
