// ejecta_bench_exact_solutions: what the reference solutions that verification compares against
// cost (sim/exact/): evaluations of the Sedov-Taylor solution per second, and the radial Euler
// solver's cell updates per second on the sod_2d reference (a disc of radius 0.4 in [0, 1], to
// t = 0.25). The Sedov solution is evaluated at every particle of a verified snapshot and the
// radial solver is run once per comparison, so their cost sets how often a run can be compared
// with them.
//
//   ejecta_bench_exact_solutions [--evaluations 1000000] [--cells 4000] [--json]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "arguments.hpp"
#include "sim/exact/radial_euler.hpp"
#include "sim/exact/sedov.hpp"

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  using namespace ejecta::exact;
  long evaluations = 1'000'000;
  int cells = 4000;
  bool json = false;
  ejecta::bench::Arguments args(argc, argv);
  for (std::string option; args.next(option);) {
    if (option == "--evaluations") evaluations = std::atol(args.value());
    else if (option == "--cells") cells = std::atoi(args.value());
    else if (option == "--json") json = true;
    else {
      std::fprintf(stderr, "ejecta_bench_exact_solutions: unknown option %s\n", option.c_str());
      return 2;
    }
  }
  if (evaluations < 1 || cells < 4) {
    std::fprintf(stderr, "ejecta_bench_exact_solutions: --evaluations >= 1 and --cells >= 4\n");
    return 2;
  }

  // Sedov: the 3D blast of the SPH-EXA problem (gamma 5/3, E = rho = 1), sampled inside and
  // just beyond the shock at t = 0.05.
  const SedovSolution sedov(3, 5.0 / 3.0, 1.0, 1.0);
  const double radius = sedov.shockRadius(0.05);
  auto start = std::chrono::steady_clock::now();
  double checksum = 0.0;  // keeps the evaluations from being optimised away
  for (long i = 0; i < evaluations; ++i)
    checksum += sedov.at(1.1 * radius * (static_cast<double>(i) + 0.5) / evaluations, 0.05).p;
  const double sedovSeconds = secondsSince(start);

  // Circular Sod (the sod_2d reference).
  start = std::chrono::steady_clock::now();
  RadialRiemannSolution sod(2, GasState{1.0, 0.0, 1.0}, GasState{0.125, 0.0, 0.1}, 0.4, 1.4, 1.0,
                            cells);
  sod.advanceTo(0.25);
  const double sodSeconds = secondsSince(start);
  const double cellUpdates = static_cast<double>(cells) * sod.steps();

  if (json) {
    std::printf("{\"sedov_evaluations\": %ld, \"sedov_seconds\": %.6g, \"sedov_per_second\": %.6g, "
                "\"sod_cells\": %d, \"sod_steps\": %d, \"sod_seconds\": %.6g, "
                "\"sod_cell_updates_per_second\": %.6g, \"checksum\": %.17g}\n",
                evaluations, sedovSeconds, evaluations / sedovSeconds, cells, sod.steps(),
                sodSeconds, cellUpdates / sodSeconds, checksum);
  } else {
    std::printf("Sedov-Taylor (3D, gamma 5/3): %ld evaluations in %.3f s, %.3g per second\n",
                evaluations, sedovSeconds, evaluations / sedovSeconds);
    std::printf("radial Euler (circular Sod, %d cells to t = 0.25): %d steps in %.3f s, "
                "%.3g cell updates per second\n",
                cells, sod.steps(), sodSeconds, cellUpdates / sodSeconds);
  }
  return checksum > 0.0 ? 0 : 1;
}
