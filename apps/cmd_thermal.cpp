// `ejecta thermal`: placeholder until the chain lands (issue 6).
#include <stdexcept>

#include "apps/commands.hpp"

namespace ejecta::app {

int thermalCommand(const ThermalArgs&) {
  throw std::runtime_error("ejecta thermal is not implemented yet");
}

}  // namespace ejecta::app
