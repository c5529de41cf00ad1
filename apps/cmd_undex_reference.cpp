// `ejecta undex-reference SCENE [--zones N] [--out DIR] [--set KEY=VALUE ...]`: the converged 1D
// reference of a centred charge in an inert medium (docs/undex.md, "The converged 1D reference";
// the mapping: sim/verify/undex_reference.hpp; Cole's law: sim/exact/underwater_explosion_laws.hpp).
// The scene's geometry maps to the 1D symmetry (RZ and 3D: a sphere; 2D planar: a cylinder; 1D:
// a slab), its explosive body to the inner region (radius, density, energy, programmed burn from
// the detonation point), its one inert body to the outer region (out to its nearest face that is
// not a symmetry plane), and its gauges to their distances from the charge's centre. The 1D
// Lagrangian hydrocode (sim/exact/radial_lagrangian.hpp) runs to the scene's t_end with the outer
// node free at the medium's initial pressure, writes DIR/gauges_reference.csv (the layout of the
// SPH run's gauges.csv; default DIR runs/<scene name>, beside it) and prints the medium's share
// of the yield, each gauge's pulse (sim/sources/gauge_decay.hpp) and, for a sphere, Cole's similitude
// values.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "apps/commands.hpp"
#include "sim/exact/radial_lagrangian.hpp"
#include "sim/exact/underwater_explosion_laws.hpp"
#include "core/atomic_file.hpp"
#include "sim/setup/scene.hpp"
#include "sim/sources/gauge_decay.hpp"
#include "sim/verify/undex_reference.hpp"

namespace fs = std::filesystem;

namespace ejecta::app {

int undexReferenceCommand(const UndexReferenceArgs& args) {
  const Scene scene = loadScene(args.scene, args.overrides);
  const verify::UndexReference ref = verify::buildUndexReference(scene, args.zones);
  const exact::RadialSetup& setup = ref.setup;
  exact::RadialLagrangian run(setup);
  for (std::size_t g = 0; g < scene.gauges.size(); ++g)
    run.addGauge(scene.gauges[g].name, ref.gaugeRadius[g]);
  const int j = ref.symmetry;
  const char* symmetry[] = {"", "planar", "cylindrical", "spherical"};
  const double chargeMass = run.regionMass(0);
  const char* perUnit[] = {"", " per m^2", " per m", ""};
  std::printf(
      "ejecta undex-reference: %s (%s): %s 1D Lagrangian reference, %zu zones of %.4g mm to %.4g "
      "m, "
      "charge %.4g m (%.4g kg%s), t_end %.4g ms\n",
      scene.name.c_str(), args.scene.c_str(), symmetry[j], run.zoneCount(),
      setup.zoneWidth * 1e3, ref.extent, ref.chargeRadius, chargeMass, perUnit[j],
      scene.time.tEnd * 1e3);
  std::fflush(stdout);
  const double energy0 = run.totalEnergy();
  const double mediumEnergy0 = run.regionInternalEnergy(1) + run.regionKineticEnergy(1);
  const auto start = std::chrono::steady_clock::now();
  run.advanceTo(scene.time.tEnd);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "  %ld steps in %.2f s wall (one core); energy error %.2g (with the outer pressure's work)\n",
      run.steps(), wall, (run.totalEnergy() - run.boundaryWork() - energy0) / energy0);
  // The charge's yield is its chemical energy, e0 x mass, as the energy ledger of `ejecta run`
  // counts it; the medium's share is what it gained (the outer pressure's work counted in).
  if (ref.chargeDetonationEnergy > 0.0) {
    const double yield = chargeMass * ref.chargeDetonationEnergy;
    const double gained = run.regionInternalEnergy(1) + run.regionKineticEnergy(1) - mediumEnergy0 -
                          run.boundaryWork();
    std::printf("  at t_end the %s holds %.1f%% of the charge's yield (%.4g J%s): %.1f%% kinetic\n",
                setup.regions[1].name.c_str(), 100.0 * gained / yield, yield, perUnit[j],
                100.0 * run.regionKineticEnergy(1) / yield);
  }

  // The printed pulses below are measured on every step, the CSV's rows thinned.
  const fs::path out = args.outDir.empty() ? fs::path("runs") / scene.name : fs::path(args.outDir);
  fs::create_directories(out);
  writeFileAtomically(out / "gauges_reference.csv",
                      verify::undexReferenceGaugeCsv(scene, ref, run.gauges()));

  const std::vector<exact::RadialGauge>& gauges = run.gauges();
  const exact::SimilitudeLaw& law = exact::kColeTnt;
  const bool cole = j == 3;
  std::printf("  %-10s %8s %11s %13s %11s %11s", "gauge", "R [m]", "peak [MPa]", "arrival [ms]",
              "θ 1/e [µs]", "θ fit [µs]");
  if (cole) std::printf(" %16s %6s %14s %6s", "Cole peak [MPa]", "ratio", "Cole θ [µs]", "ratio");
  std::printf("\n");
  for (std::size_t g = 0; g < gauges.size(); ++g) {
    const double radius = ref.gaugeRadius[g];
    std::printf("  %-10s %8.4g", gauges[g].name.c_str(), radius);
    try {
      const ShockPulse pulse = measureShockPulse(gauges[g].time, gauges[g].pressure, ref.ambient);
      std::printf(" %11.4g %13.5g %11.4g %11.4g", pulse.peakPressure * 1e-6, pulse.arrival * 1e3,
                  pulse.eFoldTime * 1e6, pulse.fitTime * 1e6);
      if (cole) {
        const double p = law.peakPressure(chargeMass, radius), t = law.decayTime(chargeMass, radius);
        std::printf(" %16.4g %6.3f %14.4g %6.3f", p * 1e-6, pulse.peakPressure / p, t * 1e6,
                    pulse.eFoldTime / t);
      }
    } catch (const std::invalid_argument&) {
      std::printf(" %11s", "no pulse");
    }
    std::printf("\n");
  }
  if (cole)
    std::printf(
        "  Cole: %.3g (W^(1/3)/R)^%.3g MPa, θ = %.3g W^(1/3) (W^(1/3)/R)^(%.2g) µs "
        "(docs/undex.md); "
        "it applies beyond about %.0f charge radii\n",
        law.peakCoefficient * 1e-6, law.peakExponent, law.decayCoefficient * 1e6,
        law.decayExponent, exact::kColeInnerLimitChargeRadii);
  std::printf("wrote %s\n", (out / "gauges_reference.csv").string().c_str());
  return 0;
}

}  // namespace ejecta::app
