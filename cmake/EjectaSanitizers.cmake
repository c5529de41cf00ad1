# Checked builds (docs/robustness.md), each in a build folder of its own:
#   EJECTA_SANITIZE=ON  every ejecta target and test built with AddressSanitizer and
#                       UndefinedBehaviorSanitizer (`make sanitize`); any report fails the test.
#   EJECTA_FUZZ=ON      clang only: the same sanitizers plus libFuzzer's coverage, and the fuzz
#                       targets of tests/fuzz linked with libFuzzer (`make fuzz`).
# -O1 keeps the stacks readable and the run a few times slower than Release, not tens of times.
option(EJECTA_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
option(EJECTA_FUZZ "Build the libFuzzer targets (clang), with the sanitizers" OFF)

if(EJECTA_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "EJECTA_FUZZ needs clang (libFuzzer): configure with "
                        "-DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang")
  endif()
  set(EJECTA_SANITIZE ON)
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()

if(EJECTA_SANITIZE)
  # Undefined behaviour stops the program (no recovery), so a test sees it as a failure.
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=undefined
                      -fno-omit-frame-pointer -O1 -g)
  add_link_options(-fsanitize=address,undefined)
endif()
