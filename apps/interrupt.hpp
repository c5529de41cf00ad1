#pragma once
// SIGINT and SIGTERM during `ejecta run`: the first asks the run to stop after its current step
// (a last snapshot, summary.json with status "interrupted", exit code 128 + the signal's number:
// 130 for Ctrl-C, 143 for SIGTERM); a second one ends the process at once, as the default
// action would. docs/robustness.md.
#include <csignal>

namespace ejecta::app {

class InterruptGuard {
 public:
  InterruptGuard();   // installs the handlers
  ~InterruptGuard();  // restores the previous ones
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  // The signal received (0: none yet). Safe to call from any thread.
  static int received();
  // 128 + the signal received, the shell's convention for a command ended by a signal.
  static int exitCode() { return 128 + received(); }

 private:
  struct sigaction previousInt_ {}, previousTerm_ {};
};

}  // namespace ejecta::app
