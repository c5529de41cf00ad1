// Snapshot particles -> emitter spheres; RZ rings revolved into copies about the axis.
#include "coupling/snapshot_emitters.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <regex>
#include <stdexcept>

namespace ejecta::coupling {

namespace fs = std::filesystem;

int ringCopies(double r, double h, int maxCopies) {
  if (!(h > 0.0) || !std::isfinite(r)) return 1;
  const double n = std::ceil(2.0 * std::numbers::pi * std::abs(r) / h);
  return static_cast<int>(std::clamp(n, 1.0, static_cast<double>(std::max(1, maxCopies))));
}

radiation::Emitters emittersFromParticles(const ParticleSet& p, Geometry geometry,
                                          const SnapshotEmitterOptions& options,
                                          SnapshotEmitterStats* stats) {
  if (geometry == Geometry::Line || geometry == Geometry::Planar)
    throw std::invalid_argument(std::string("thermal: a ") + std::string(geometryName(geometry)) +
                                " run has no 3D extent to radiate from; use an RZ or 3D run");
  const bool rz = geometry == Geometry::Axisymmetric;
  const std::size_t n = p.numReal;
  std::vector<double> x, y, z, radius, temperature;
  std::vector<int> material;
  SnapshotEmitterStats s;
  s.particles = n;
  for (std::size_t i = 0; i < n; ++i) {
    // Select first (the threshold), then revolve: cold rings are never expanded.
    if (!(p.temperature[i] >= options.minTemperature)) continue;
    ++s.hot;
    if (!(p.rho[i] > 0.0) || !(p.mass[i] > 0.0))
      throw std::invalid_argument("thermal: particle " + std::to_string(i) +
                                  " has no positive mass and density, so no volume");
    const double volume = p.mass[i] / p.rho[i];
    if (!rz) {
      x.push_back(p.x[0][i]);
      y.push_back(p.x[1][i]);
      z.push_back(p.x[2][i]);
      radius.push_back(radiation::equalVolumeRadius(volume));
      temperature.push_back(p.temperature[i]);
      material.push_back(p.material[i]);
      continue;
    }
    const double r = p.x[0][i];
    const int copies = ringCopies(r, p.h[i], options.maxRingCopies);
    s.maxCopies = std::max(s.maxCopies, copies);
    const double a = radiation::equalVolumeRadius(volume / copies);
    for (int k = 0; k < copies; ++k) {
      const double phi = 2.0 * std::numbers::pi * (k + 0.5) / copies;
      x.push_back(r * std::cos(phi));
      y.push_back(p.x[1][i]);
      z.push_back(r * std::sin(phi));
      radius.push_back(a);
      temperature.push_back(p.temperature[i]);
      material.push_back(p.material[i]);
    }
  }
  radiation::EmitterSelection selection;
  selection.minTemperature = options.minTemperature;
  selection.emissivityByMaterial = options.emissivityByMaterial;
  selection.defaultEmissivity = options.defaultEmissivity;
  selection.materialNames = options.materialNames;
  radiation::Emitters e = radiation::selectEmitters({x, y, z, radius, temperature, material}, selection);
  s.emitters = e.size();
  if (stats) *stats = s;
  return e;
}

std::string resolveSnapshotPath(const std::string& input) {
  const fs::path in(input);
  if (!fs::exists(in)) throw std::runtime_error(input + ": no such run directory or snapshot");
  if (!fs::is_directory(in)) return input;
  const fs::path dir = in / "snapshots";
  const std::regex pattern(R"(snap_(\d{4,})\.h5)");
  fs::path best;
  long bestIndex = -1;
  if (fs::is_directory(dir))
    for (const auto& e : fs::directory_iterator(dir)) {
      const std::string name = e.path().filename().string();
      if (!std::regex_match(name, pattern)) continue;
      const long index = std::stol(name.substr(5));
      if (index > bestIndex) bestIndex = index, best = e.path();
    }
  if (bestIndex < 0) throw std::runtime_error(input + ": no snapshots/snap_NNNN.h5 in this run directory");
  return best.string();
}

}  // namespace ejecta::coupling
