#include "apps/thread_limit.hpp"

#include <omp.h>
#include <tbb/global_control.h>

namespace ejecta::app {

struct ThreadLimit::Control {
  explicit Control(int threads)
      : tbb(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads)) {}
  tbb::global_control tbb;
};

ThreadLimit::ThreadLimit(int threads) {
  if (threads <= 0) return;
  omp_set_num_threads(threads);
  control_ = std::make_unique<Control>(threads);
}

ThreadLimit::~ThreadLimit() = default;

}  // namespace ejecta::app
