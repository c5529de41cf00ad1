#pragma once
// Command-line reading shared by the bench commands: walk argv, take an option's value or stop
// with a message when it is missing.
#include <cstdio>
#include <cstdlib>
#include <string>

namespace ejecta::bench {

class Arguments {
 public:
  Arguments(int argc, char** argv) : argc_(argc), argv_(argv) {}
  // The next option name, or false at the end.
  bool next(std::string& option) {
    if (++index_ >= argc_) return false;
    option = argv_[index_];
    return true;
  }
  // The value following the current option (exits with status 2 when there is none).
  const char* value() {
    if (index_ + 1 >= argc_) {
      std::fprintf(stderr, "missing value for %s\n", argv_[index_]);
      std::exit(2);
    }
    return argv_[++index_];
  }

 private:
  int argc_;
  char** argv_;
  int index_ = 0;
};

}  // namespace ejecta::bench
