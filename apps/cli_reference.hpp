#pragma once
// The manual page and the bash completion of `ejecta`, generated from the command line's own
// definition (main.cpp's CLI11 App), so neither can drift from the options the binary takes.
// `ejecta --man` and `ejecta --bash-completion` print them; the build writes both files
// (apps/CMakeLists.txt) and `cmake --install` installs them.
#include <string>

namespace CLI {
class App;
}

namespace ejecta::app {

// troff source of ejecta(1): every subcommand with its positionals and options.
std::string manPage(CLI::App& app, const std::string& version);

// A bash completion script: subcommands, each one's options, shipped scene names for `run` and
// `sweep` (asked of `ejecta scenes` when completing), files otherwise.
std::string bashCompletion(CLI::App& app);

}  // namespace ejecta::app
