// `ejecta viewfactor GEOMETRY.toml`: view factors between a spacecraft's patches, or from its
// patches to hot emitters, by Monte Carlo ray casting (radiation/geometry_file.hpp,
// docs/view_factors.md).
#include <cstdio>

#include "apps/commands.hpp"
#include "radiation/geometry_file.hpp"

namespace ejecta::app {

int viewfactorCommand(const ViewfactorArgs& args) {
  const radiation::GeometryConfig config = radiation::loadGeometryConfig(args.geometry);
  radiation::ViewFactorRunOptions run;
  if (args.rays > 0) run.rays = static_cast<std::uint64_t>(args.rays);
  if (args.tolerance > 0) run.tolerance = args.tolerance;
  const radiation::ViewFactorReport report = radiation::computeViewFactors(config, run);
  std::fputs((args.json ? radiation::formatViewFactorJson(report)
                        : radiation::formatViewFactorText(report)).c_str(), stdout);
  return 0;
}

}  // namespace ejecta::app
