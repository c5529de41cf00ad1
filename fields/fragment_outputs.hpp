#pragma once
// The fragment census of `ejecta run` for a scene with a [fragments] table (fields/fragments):
//   RUN_DIR/fragments.csv        every fragment at the end, largest first
//   RUN_DIR/size_frequency.csv   the cumulative size-frequency distribution at the end
//   RUN_DIR/fragments/fragments_NNNN.csv   with every Nth snapshot ([fragments] every = N)
// and summary.json's "fragments_*" entries. A distributed run's census is taken at rank 0 on
// every rank's particles.
#include <functional>
#include <string>
#include <vector>

#include "fields/fragments.hpp"
#include "sim/run/run.hpp"

namespace ejecta::fields {

struct FragmentSummary {
  std::size_t fragments = 0, resolved = 0, failedParticles = 0;
  double largestMass = 0.0;           // [kg]
  double largestMassFraction = 0.0;   // of all the mass
  double largestDiameter = 0.0;       // [m] of the largest fragment
  double resolutionLimit = 0.0;       // [m] the smallest size measured (resolved spacings x
                                      // the median particle spacing)
  double fastestResolvedSpeed = 0.0;  // [m/s]
};

FragmentOptions fragmentOptions(const FragmentAnalysisOptions& scene);
FragmentSummary summarizeFragments(const FragmentCensus& census, const FragmentOptions& options);
// Writes the summary into summary.json's extras: the one place its keys are named.
void addToSummary(const FragmentSummary& f, RunSummary& summary);
// The size-frequency CSV: for each distinct diameter (largest first), the count and mass of
// the fragments at least that large, and of the measured ones among them:
// diameter_m, count_at_least, mass_at_least_kg, measured_count_at_least, measured_mass_at_least_kg.
std::string sizeFrequencyCsv(const FragmentCensus& census);

// Adds the hooks (keeping any already there); `onFragments` is called at the end.
void addFragmentOutputs(RunOptions& options, const Scene& scene,
                        std::function<void(const FragmentSummary&)> onFragments = {});

}  // namespace ejecta::fields
