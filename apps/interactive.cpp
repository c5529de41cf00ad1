#include <unistd.h>

#include <cstdlib>

#include "apps/commands.hpp"

namespace ejecta::app {

bool interactive() { return isatty(STDERR_FILENO) && std::getenv("CI") == nullptr; }

}  // namespace ejecta::app
