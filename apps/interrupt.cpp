#include "apps/interrupt.hpp"

#include <unistd.h>

#include <atomic>
#include <cstring>

namespace ejecta::app {

namespace {

// Written by the handler, read by the run's interruption hook: lock-free, so signal-safe.
std::atomic<int> receivedSignal{0};
static_assert(std::atomic<int>::is_always_lock_free);

void onSignal(int signal) {
  if (receivedSignal.exchange(signal) != 0) {
    // The second signal: the user means it. The default action ends the process.
    std::signal(signal, SIG_DFL);
    std::raise(signal);
    return;
  }
  // write(2) is async-signal-safe; printf is not.
  const char message[] =
      "\nejecta: interrupted: finishing the current step and writing a last snapshot "
      "(signal again to abandon it)\n";
  [[maybe_unused]] const ssize_t n = ::write(STDERR_FILENO, message, sizeof message - 1);
}

void install(int signal, struct sigaction& previous) {
  struct sigaction action {};
  action.sa_handler = onSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // file writes in progress are not cut short by EINTR
  sigaction(signal, &action, &previous);
}

}  // namespace

InterruptGuard::InterruptGuard() {
  receivedSignal = 0;
  install(SIGINT, previousInt_);
  install(SIGTERM, previousTerm_);
}

InterruptGuard::~InterruptGuard() {
  sigaction(SIGINT, &previousInt_, nullptr);
  sigaction(SIGTERM, &previousTerm_, nullptr);
}

int InterruptGuard::received() { return receivedSignal.load(); }

}  // namespace ejecta::app
