// libFuzzer target: the TOML scene reader (sim/setup/scene.hpp) on arbitrary text.
// The reader's promise: any text is either a Scene or an InputError whose message names the
// file; never a crash, a hang, an unbounded allocation or another exception type. Anything that
// escapes this function (a std::out_of_range from a bad index, say) aborts, and libFuzzer keeps
// the input as a crash. Built with clang by `make fuzz`; replayed over the corpus in every test
// run by fuzz_replay_main.cpp.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <string>

#include "core/input_error.hpp"
#include "sim/setup/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  // A name in a folder of its own: relative file references in the scene (a spacecraft, a
  // study) resolve to nothing rather than to files of the tree the fuzzer runs in.
  const std::string name = "/nonexistent-fuzz-folder/scene.toml";
  try {
    const ejecta::Scene scene = ejecta::parseScene(text, name);
    (void)scene;
  } catch (const ejecta::InputError& e) {
    const std::string message = e.what();
    // Every refusal names the file (the reader's contract, docs/robustness.md).
    if (message.find(name) == std::string::npos) {
      std::fprintf(stderr, "scene refusal without the file name: %s\n", message.c_str());
      std::abort();
    }
  }
  return 0;
}
