// Runs the shipped Sod tube for 0.02 s through the installed ejecta::sim and checks the run
// conserved energy: what a code embedding ejecta's hydrocode would do first.
#include <cmath>
#include <cstdio>
#include <string>

#include "sim/run/run.hpp"
#include "sim/setup/scene.hpp"
#include "sim/setup/scene_catalog.hpp"

int main() {
  const ejecta::ShippedScene* shipped = ejecta::findShippedScene("sod_1d");
  if (!shipped) {
    std::fprintf(stderr, "consumer: no shipped scene sod_1d\n");
    return 1;
  }
  const ejecta::Scene scene =
      ejecta::parseScene(std::string(shipped->text), shipped->name, {"time.t_end=0.02 s"});
  ejecta::RunOptions options;  // no outDir: nothing written
  options.threads = 1;
  const ejecta::RunOutcome r = ejecta::runScene(scene, options);
  std::printf("consumer: %s: %zu particles, %ld steps, energy error %.3g\n", scene.name.c_str(),
              r.summary.particles, r.summary.steps, r.summary.energy.relativeError);
  // The tube's energy is conserved to the time-integration error (docs/verification.md: ~1e-6
  // over the whole 0.2 s run); 1e-4 fails only a broken build.
  return r.ok && r.summary.steps > 0 && std::abs(r.summary.energy.relativeError) < 1e-4 ? 0 : 1;
}
