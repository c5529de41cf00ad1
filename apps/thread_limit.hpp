#pragma once
// `--threads N` for the commands that do not pass a thread count down to a library (fields,
// crater, sweep, viewfactor, thermal, render, whipple, undex-reference): N caps OpenMP's team and
// oneTBB's arena (OpenVDB's tools run on TBB) for the rest of the process. 0 leaves the defaults
// (every core, or OMP_NUM_THREADS).
#include <memory>

namespace ejecta::app {

class ThreadLimit {
 public:
  explicit ThreadLimit(int threads);
  ~ThreadLimit();
  ThreadLimit(const ThreadLimit&) = delete;
  ThreadLimit& operator=(const ThreadLimit&) = delete;

 private:
  struct Control;
  std::unique_ptr<Control> control_;
};

}  // namespace ejecta::app
