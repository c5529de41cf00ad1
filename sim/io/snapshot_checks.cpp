#include "sim/io/snapshot_checks.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace ejecta {

namespace {

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::string groupOf(const Field& f) {
  return f.spec.output == FieldOutput::Particles ? "/particles/" : "/restart/";
}

[[noreturn]] void refuse(const ParticleSet& p, const Field& f, std::size_t i, std::size_t firstRow,
                         int component, const std::string& reason) {
  std::string where = "dataset '" + groupOf(f) + f.spec.name + "' row " + std::to_string(firstRow + i);
  if (i < p.id.size()) where += " (particle id " + std::to_string(p.id[i]) + ")";
  if (f.spec.components > 1) where += " component " + std::to_string(component);
  throw std::runtime_error(where + ": " + reason);
}

// Fields that must be positive: a particle with none of these has no volume, and the neighbour
// search and the kernel divide by them.
bool mustBePositive(const std::string& name) {
  return name == "mass" || name == "density" || name == "smoothing_length";
}

// Lengths beyond 1e12 m (7 au) belong to no impact or blast problem: a corrupt value, whose
// neighbour search or grid would span the solar system at the particles' spacing.
constexpr double kLargestLength = 1e12;
bool isLength(const std::string& name) { return name == "position" || name == "smoothing_length"; }

}  // namespace

void checkSnapshotInfo(const SnapshotInfo& info) {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw std::runtime_error(what);
  };
  require(std::isfinite(info.time) && info.time >= 0.0,
          "attribute 'time' of '/' is " + number(info.time) + " (must be finite and >= 0)");
  require(info.step >= 0, "attribute 'step' of '/' is " + std::to_string(info.step) + " (must be >= 0)");
  require(std::isfinite(info.dtNext) && info.dtNext >= 0.0,
          "attribute 'dt_next' of '/restart' is " + number(info.dtNext) + " (must be finite and >= 0)");
  require(info.snapshotIndex >= 0, "attribute 'snapshot_index' of '/restart' is negative");
  require(!std::isnan(info.nextOutputTime),
          "attribute 'next_output_time' of '/restart' is nan");
  require(std::isfinite(info.initialEnergy),
          "attribute 'initial_energy' of '/restart' is " + number(info.initialEnergy));
  for (double m : info.initialMomentum)
    require(std::isfinite(m), "attribute 'initial_momentum' of '/restart' is not finite");
  require(std::isfinite(info.wallSeconds) && info.wallSeconds >= 0.0,
          "attribute 'wall_seconds' of '/restart' is " + number(info.wallSeconds));
}

void checkSnapshotParticles(const ParticleSet& p, std::size_t firstRow) {
  const std::size_t n = p.numReal;
  for (const Field& f : p.fields()) {
    if (f.spec.output == FieldOutput::None || f.spec.derive) continue;
    if (f.storage.kind == FieldStorage::Kind::Int32 && f.spec.name == "material") {
      const std::vector<int>& m = p.*f.storage.int32;
      for (std::size_t i = 0; i < n && i < m.size(); ++i)
        if (m[i] < 0) refuse(p, f, i, firstRow, 0, "material index " + std::to_string(m[i]) + " is negative");
      continue;
    }
    if (f.storage.kind == FieldStorage::Kind::Int32 || f.storage.kind == FieldStorage::Kind::Int64)
      continue;
    // /restart holds legitimate infinities (a lighting time of -inf: not an explosive); the
    // science arrays in /particles do not.
    const bool finite = f.spec.output == FieldOutput::Particles;
    const bool positive = mustBePositive(f.spec.name);
    const bool length = isLength(f.spec.name);
    for (int c = 0; c < f.spec.components; ++c) {
      const std::vector<double>& values = p.column(f, c);
      for (std::size_t i = 0; i < n && i < values.size(); ++i) {
        const double v = values[i];
        if (std::isnan(v)) refuse(p, f, i, firstRow, c, "value is nan");
        if (finite && !std::isfinite(v)) refuse(p, f, i, firstRow, c, "value is " + number(v) + " (must be finite)");
        if (positive && !(v > 0.0)) refuse(p, f, i, firstRow, c, "value is " + number(v) + " (must be > 0)");
        if (length && std::abs(v) > kLargestLength)
          refuse(p, f, i, firstRow, c, "value is " + number(v) + " m (beyond 1e12 m: corrupt?)");
      }
    }
  }
}

void checkSnapshotMaterials(const ParticleSet& p, std::size_t materialCount, const std::string& path) {
  for (std::size_t i = 0; i < p.numReal && i < p.material.size(); ++i)
    if (p.material[i] < 0 || static_cast<std::size_t>(p.material[i]) >= materialCount)
      throw std::runtime_error("snapshot '" + path + "': dataset '/particles/material' row " +
                               std::to_string(i) + ": material index " + std::to_string(p.material[i]) +
                               " is not one of the scene's " + std::to_string(materialCount) +
                               " material(s)");
}

}  // namespace ejecta
