#pragma once
// Order statistics of values spread over ranks, found without gathering them: the k-th smallest
// of every rank's values by eight rounds of a 256-bin histogram over the bits of a total-order
// key of each double, most significant byte first (integer counts, summed exactly). The answer
// is the one a sort of all values would give, on every rank. Used for the median smoothing
// length that sets a distributed run's default voxel (fields/grid_set.hpp).
#include <cstdint>
#include <span>

#include "sim/parallel/communicator.hpp"

namespace ejecta {

// The k-th smallest (0-based) of all ranks' `values` (a collective). Throws std::out_of_range
// on every rank when k is not below their total count. NaN is not ordered; do not pass it.
double kthSmallest(std::span<const double> values, std::uint64_t k, const Communicator& ranks);

// The element at index n / 2 of all ranks' n values sorted (the upper median; a collective).
double upperMedian(std::span<const double> values, const Communicator& ranks);

}  // namespace ejecta
