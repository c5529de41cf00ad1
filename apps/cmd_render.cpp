// `ejecta render SNAPSHOT.h5|RUN_DIR`: a PNG of the particles coloured by a field.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <regex>
#include <stdexcept>

#include "apps/commands.hpp"
#include "apps/particle_images.hpp"
#include "sim/snapshot.hpp"

namespace fs = std::filesystem;

namespace ejecta::app {

namespace {

// A run directory's last snapshot, or the path itself.
fs::path snapshotOf(const fs::path& input) {
  if (!fs::is_directory(input)) return input;
  const fs::path dir = input / "snapshots";
  std::vector<fs::path> files;
  const std::regex pattern(R"(snap_(\d{4,})\.h5)");
  if (fs::is_directory(dir))
    for (const auto& e : fs::directory_iterator(dir))
      if (std::regex_match(e.path().filename().string(), pattern)) files.push_back(e.path());
  if (files.empty()) throw std::runtime_error(input.string() + ": no snapshots/snap_NNNN.h5");
  auto index = [](const fs::path& f) { return std::stol(f.stem().string().substr(5)); };
  return *std::max_element(files.begin(), files.end(),
                           [&](const fs::path& a, const fs::path& b) { return index(a) < index(b); });
}

}  // namespace

int renderCommand(const RenderArgs& args) {
  const fs::path snapshot = snapshotOf(args.input);
  SnapshotInfo info;
  const ParticleSet p = readSnapshot(snapshot.string(), info);
  ParticleImageOptions options;
  if (!args.field.empty()) options.field = args.field;
  options.log = args.log;
  if (!args.cut.empty()) options.cut = args.cut;
  Geometry geometry = info.geometry;
  if (args.view == "plane") geometry = Geometry::Planar;
  else if (args.view == "rz") geometry = Geometry::Axisymmetric;
  else if (args.view == "3d") geometry = Geometry::Spatial;
  else if (!args.view.empty() && args.view != "auto")
    throw std::invalid_argument("--view '" + args.view + "': expected auto, plane, rz or 3d");
  const fs::path out = args.out.empty() ? fs::path(options.field + ".png") : fs::path(args.out);
  if (args.size < 64 || args.size > 8192)
    throw std::invalid_argument("--size " + std::to_string(args.size) + ": expected 64 to 8192 pixels");
  render::Renderer renderer({.width = args.size, .height = args.size});
  writeParticleImage(renderer, p, geometry, info.time, info.scene, options, out);
  std::printf("ejecta: %s (%s at t = %.6g s, %zu particles) -> %s\n", options.field.c_str(),
              snapshot.filename().c_str(), info.time, p.numReal, out.c_str());
  return 0;
}

}  // namespace ejecta::app
