// The UNDEX criterion at full size (label `slow`, 7.5 minutes on two cores; `ctest -L
// slow`): scenes/undex_rz.toml as shipped (1 kg TNT, 3.5 mm, reconstructed viscosity) must read
// the peak pressure within 10% of Cole's similitude law where the law applies (0.75 and 1 m,
// beyond 12 charge radii), and within 8% of the converged 1D reference of the same model.
// docs/undex.md, "The reconstructed viscosity", has the numbers and the plot.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "sim/exact/underwater_explosion_laws.hpp"
#include "sim/sources/gauge_decay.hpp"
#include "support/command_line.hpp"

namespace fs = std::filesystem;

namespace ejecta {
namespace {

using test::kEjecta;
using test::runCommand;

double peakOf(const fs::path& csv, const std::string& gauge) {
  const GaugePressures g = readGaugePressures(csv.string());
  for (std::size_t k = 0; k < g.names.size(); ++k)
    if (g.names[k] == gauge) return measureShockPulse(g.time, g.pressure[k], 101325.0).peakPressure;
  ADD_FAILURE() << "no gauge " << gauge << " in " << csv;
  return 0.0;
}

TEST(UndexCole, ShippedSceneMeetsTenPercentOnPeak) {
  const fs::path dir = fs::temp_directory_path() / ("ejecta_slow_undex_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const std::string scene = std::string(EJECTA_SOURCE_DIR) + "/scenes/undex_rz.toml";
  std::string output;
  ASSERT_EQ(runCommand(kEjecta + " run " + scene + " --no-charts --out " + (dir / "sph").string(),
                       output),
            0)
      << output;
  ASSERT_EQ(runCommand(kEjecta + " undex-reference " + scene + " --out " +
                           (dir / "reference").string(),
                       output),
            0)
      << output;
  // Cole (1948) in SI, 52.4 (W^(1/3)/R)^1.13 MPa (sim/exact/underwater_explosion_laws.hpp), with
  // the charge as built (0.9993 kg at 3.5 mm, docs/undex.md; the lattice's mass error moves the
  // law by 0.02%).
  const double W = 0.9993;
  for (const auto& [gauge, R] : {std::pair{"g075", 0.75}, std::pair{"g100", 1.0}}) {
    const double cole = exact::kColeTnt.peakPressure(W, R);
    const double sph = peakOf(dir / "sph" / "gauges.csv", gauge);
    const double reference = peakOf(dir / "reference" / "gauges_reference.csv", gauge);
    std::printf("%s: SPH %.2f MPa, Cole %.2f MPa (%+.1f%%), 1D reference %.2f MPa (%+.1f%%)\n",
                gauge, sph / 1e6, cole / 1e6, 100.0 * (sph / cole - 1.0), reference / 1e6,
                100.0 * (sph / reference - 1.0));
    // The criterion. Measured -1.4% and -5.4%.
    EXPECT_LT(std::abs(sph / cole - 1.0), 0.10) << gauge;
    // The model's own solution at the command's default 10,000 zones: expected +4.4% and +5.5%
    // (+3.8% and +4.6% against the converged values; the crest's overshoot, docs/undex.md).
    // Asserted within 8%: the plain viscosity reads 27-29% below it.
    EXPECT_LT(std::abs(sph / reference - 1.0), 0.08) << gauge;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace ejecta
