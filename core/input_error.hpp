#pragma once
// The errors input readers throw for bad input (scenes, geometry files, studies, shield files).
#include <stdexcept>

namespace ejecta {

// Base of every bad-input error: the message names the file, the line (when known), the key and
// the reason, e.g. "scenes/x.toml:12: key 'bodies[1].spacing': must be positive (got -0.1 m)".
// Callers that only need "the input was wrong" catch this.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A bad scene file (sim/setup).
class SceneError : public InputError {
 public:
  using InputError::InputError;
};

}  // namespace ejecta
