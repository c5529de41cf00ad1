#include "fields/fragment_outputs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/atomic_file.hpp"
#include "core/csv.hpp"

namespace fs = std::filesystem;

namespace ejecta::fields {

namespace {

std::vector<std::string> materialNames(const Scene& scene) {
  std::vector<std::string> names;
  for (const MaterialSpec& m : scene.materials) names.push_back(m.name);
  return names;
}

// The median of the fragments' own particle spacings, each counted once per particle.
double medianSpacing(const FragmentCensus& c) {
  std::vector<std::pair<double, std::size_t>> spacings;
  std::size_t total = 0;
  for (const Fragment& f : c.fragments) {
    spacings.emplace_back(f.spacing, f.particles);
    total += f.particles;
  }
  std::sort(spacings.begin(), spacings.end());
  std::size_t seen = 0;
  for (const auto& [spacing, count] : spacings) {
    seen += count;
    if (2 * seen >= total) return spacing;
  }
  return 0.0;
}

}  // namespace

FragmentOptions fragmentOptions(const FragmentAnalysisOptions& s) {
  FragmentOptions o;
  o.linkFactor = s.linkFactor;
  o.damageThreshold = s.damageThreshold;
  o.resolvedSpacings = s.resolvedSpacings;
  return o;
}

FragmentSummary summarizeFragments(const FragmentCensus& c, const FragmentOptions& o) {
  FragmentSummary s;
  s.fragments = c.fragments.size();
  s.resolved = c.resolvedCount();
  s.failedParticles = c.failedCount();
  if (!c.fragments.empty()) {
    s.largestMass = c.fragments.front().mass;
    s.largestMassFraction = c.totalMass > 0.0 ? s.largestMass / c.totalMass : 0.0;
    s.largestDiameter = c.fragments.front().diameter;
  }
  s.resolutionLimit = o.resolvedSpacings * medianSpacing(c);
  for (const Fragment& f : c.fragments)
    if (f.resolved) s.fastestResolvedSpeed = std::max(s.fastestResolvedSpeed, f.speed);
  return s;
}

void addToSummary(const FragmentSummary& f, RunSummary& summary) {
  auto& e = summary.extras;
  e.push_back({"fragments_count", static_cast<std::int64_t>(f.fragments)});
  e.push_back({"fragments_resolved", static_cast<std::int64_t>(f.resolved)});
  e.push_back({"fragments_failed_particles", static_cast<std::int64_t>(f.failedParticles)});
  e.push_back({"fragments_largest_mass_kg", f.largestMass});
  e.push_back({"fragments_largest_mass_fraction", f.largestMassFraction});
  e.push_back({"fragments_largest_diameter_m", f.largestDiameter});
  e.push_back({"fragments_resolution_limit_m", f.resolutionLimit});
  e.push_back({"fragments_fastest_resolved_speed_m_s", f.fastestResolvedSpeed});
}

std::string sizeFrequencyCsv(const FragmentCensus& c) {
  CsvWriter csv({"diameter_m", "count_at_least", "mass_at_least_kg", "measured_count_at_least",
                 "measured_mass_at_least_kg"});
  for (const SizeFrequencyRow& r : sizeFrequency(c))
    csv.number(r.diameter).count(r.countAtLeast).number(r.massAtLeast).count(r.measuredCountAtLeast)
        .number(r.measuredMassAtLeast).endRow();
  return csv.str();
}

void addFragmentOutputs(RunOptions& options, const Scene& scene,
                        std::function<void(const FragmentSummary&)> onFragments) {
  if (!scene.fragments.enabled) return;
  const FragmentOptions fo = fragmentOptions(scene.fragments);
  const Geometry geometry = scene.geometry;
  const std::vector<std::string> names = materialNames(scene);
  const std::string outDir = options.outDir;
  if (scene.fragments.every > 0 && !outDir.empty()) {
    const int every = scene.fragments.every;
    auto previous = options.onOutput;
    options.onOutput = [=](const Simulation& sim, const SnapshotInfo& info, bool final) {
      if (previous) previous(sim, info, final);
      if (info.snapshotIndex % every != 0) return;
      const ParticleSet& all = sim.gatheredParticles();
      if (!sim.ranks().isRoot()) return;
      char name[48];
      std::snprintf(name, sizeof name, "fragments_%04ld.csv", info.snapshotIndex);
      fs::create_directories(fs::path(outDir) / "fragments");
      writeFileAtomically(fs::path(outDir) / "fragments" / name,
                          fragmentsCsv(identifyFragments(all, geometry, fo), names));
    };
  }
  auto previous = options.onFinish;
  options.onFinish = [=](const Simulation& sim, RunSummary& summary) {
    if (previous) previous(sim, summary);
    const ParticleSet& all = sim.gatheredParticles();
    if (!sim.ranks().isRoot()) return;
    const FragmentCensus census = identifyFragments(all, geometry, fo);
    const FragmentSummary s = summarizeFragments(census, fo);
    if (!outDir.empty()) {
      writeFileAtomically(fs::path(outDir) / "fragments.csv", fragmentsCsv(census, names));
      writeFileAtomically(fs::path(outDir) / "size_frequency.csv", sizeFrequencyCsv(census));
    }
    addToSummary(s, summary);
    if (onFragments) onFragments(s);
  };
}

}  // namespace ejecta::fields
