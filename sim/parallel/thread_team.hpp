#pragma once
// When a loop is worth a thread team. Starting and joining a team costs a few microseconds (far
// more where the waiting threads have gone to sleep), which a loop of simple per-particle work
// over a few thousand particles does not repay. Individual time steps run dozens of such loops at
// every sub-step, most of them over the few particles that are active, so a loop below this count
// runs on the calling thread (`#pragma omp parallel for if (n >= kThreadTeamFrom)`). The split
// never changes a result: the loops it guards write each element on its own or take a minimum or
// maximum.
#include <cstddef>

namespace ejecta {

inline constexpr std::size_t kThreadTeamFrom = 2048;

}  // namespace ejecta
