// Verification problems of porous materials: the compaction wave driven by a piston, against the
// exact jumps of sim/exact/porous_compaction.hpp on the scene's own model: P-alpha aluminium
// (JBM08's test) fully and partly compacted; epsilon-alpha aluminium through every regime, and
// iSALE's sand.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sim/exact/porous_compaction.hpp"
#include "sim/run/packages/porosity_package.hpp"
#include "sim/solid/materials.hpp"
#include "sim/solid/porosity.hpp"
#include "sim/solid/strain_porosity.hpp"
#include "sim/verify/runner.hpp"

namespace ejecta::verify::detail {

namespace {

// The exact state at x (the wall's frame: the slab arrives at -u_p onto the wall at x = 0) and
// time t: compacted and at rest behind the shock, elastic behind the precursor, arriving ahead.
exact::PorousState exactAt(const exact::CompactionWave& w, double up, double x, double t) {
  exact::PorousState s = x < (w.shockSpeed - up) * t ? w.compacted
                         : (w.twoWaves() && x < (w.precursorSpeed - up) * t) ? w.elastic
                                                                              : w.initial;
  s.v -= up;
  return s;
}

// The exact wave on the slab's own model, whichever it is.
exact::CompactionWave exactWave(const Material& material, double pistonSpeed) {
  if (const auto* m = dynamic_cast<const EpsilonAlphaModel*>(material.porosity.get()))
    return exact::compactionWave(*material.eos, *m, pistonSpeed);
  if (const auto* m = dynamic_cast<const PalphaModel*>(material.porosity.get()))
    return exact::compactionWave(*material.eos, *m, pistonSpeed);
  throw std::logic_error("compaction: the slab is not porous");
}

struct Sampled {
  double rho = 0.0, P = 0.0, alpha = 0.0, u = 0.0;
};

// Means over the particles in [x0, x1].
Sampled meanBetween(const ParticleSet& p, const std::vector<double>& alpha, double x0, double x1) {
  Sampled s;
  int n = 0;
  for (std::size_t i = 0; i < p.numReal; ++i)
    if (p.x[0][i] > x0 && p.x[0][i] < x1) {
      s.rho += p.rho[i];
      s.P += p.P[i];
      s.alpha += alpha[i];
      s.u += p.u[i];
      ++n;
    }
  if (n == 0) throw std::runtime_error("compaction: no particles in the sampled interval");
  s.rho /= n, s.P /= n, s.alpha /= n, s.u /= n;
  return s;
}

// The rightmost particle position where `value` exceeds `level` (the fronts run in +x).
double frontWhere(const ParticleSet& p, const std::vector<double>& value, double level) {
  double x = 0.0;
  for (std::size_t i = 0; i < p.numReal; ++i)
    if (value[i] > level) x = std::max(x, p.x[0][i]);
  return x;
}

Report compaction(const std::string& problem, const std::string& sceneName,
                  const std::string& reference, Options options, std::vector<std::string> overrides) {
  for (std::string& o : overrides) options.overrides.push_back(std::move(o));
  Report report = convergenceStudy(sceneName, options, 2, [&](const Scene& scene,
                                                                  Finished& f) {
    const MaterialTable materials = MaterialTable::fromScene(scene);
    const Material& material = materials[0];
    const double up = -scene.bodies[0].velocity[0];
    const exact::CompactionWave w = exactWave(material, up);
    const ParticleSet& p = f.particles;
    const std::vector<double>& alpha = p.column(*p.field(PorosityPackage::kDistention), 0);
    const double t = f.time;
    const double xShock = (w.shockSpeed - up) * t, xPrecursor = (w.precursorSpeed - up) * t;
    // The fronts: where the density passes halfway between the states either side of it.
    const double shock =
        frontWhere(p, p.rho, 0.5 * (w.elastic.rho + w.compacted.rho));
    const double precursor = frontWhere(p, p.P, 0.5 * (w.elastic.P + w.initial.P));
    // The compacted plateau away from the wall's heating and the front's smearing.
    const Sampled behind = meanBetween(p, alpha, 0.25 * xShock, 0.75 * xShock);
    // L1 of density against the exact profile over the waves and as far again ahead (the slab's
    // free end, which the precursor has not reached, lies beyond).
    double err = 0.0, norm = 0.0;
    std::vector<std::vector<double>> rows;
    const double reach = 1.25 * std::max(xPrecursor, xShock);
    for (std::size_t i = 0; i < p.numReal; ++i) {
      const double x = p.x[0][i];
      const exact::PorousState e = exactAt(w, up, x, t);
      rows.push_back({x, p.rho[i], p.v[0][i], p.P[i], alpha[i], e.rho, e.v, e.P, e.alpha});
      if (x > reach) continue;
      const double volume = p.mass[i] / p.rho[i];
      err += volume * std::abs(p.rho[i] - e.rho);
      norm += volume * e.rho;
    }
    std::sort(rows.begin(), rows.end());
    auto relative = [](double a, double b) { return (a - b) / b; };
    f.run.metrics = {
        {"L1_density", err / norm, "1"},
        {"shock_position_error", relative(shock, xShock), "1"},
        {"compacted_density_error", relative(behind.rho, w.compacted.rho), "1"},
        {"compacted_pressure_error", relative(behind.P, w.compacted.P), "1"},
        {"compacted_distention", behind.alpha, "1"},
        {"compacted_distention_exact", w.compacted.alpha, "1"},
        {"compacted_energy_error", relative(behind.u, w.compacted.u), "1"},
    };
    if (w.twoWaves()) {
      const Sampled between = meanBetween(p, alpha, xShock + 0.25 * (xPrecursor - xShock),
                                          xShock + 0.75 * (xPrecursor - xShock));
      f.run.metrics.push_back({"precursor_position_error", relative(precursor, xPrecursor), "1"});
      f.run.metrics.push_back({"elastic_density_error", relative(between.rho, w.elastic.rho), "1"});
      f.run.metrics.push_back({"elastic_pressure_error", relative(between.P, w.elastic.P), "1"});
      f.run.metrics.push_back({"elastic_distention", between.alpha, "1"});
      f.run.metrics.push_back({"elastic_distention_exact", w.elastic.alpha, "1"});
    }
    writeProfile(options, problem, f.run, "x,rho,v,P,alpha,rho_exact,v_exact,P_exact,alpha_exact",
                 rows);
  });
  report.problem = problem;
  report.reference = reference;
  return report;
}

}  // namespace

std::vector<Problem> porosityProblems() {
  const std::string palpha =
      "exact precursor and compaction jumps on the scene's P-alpha model (Herrmann 1969; test of "
      "Jutzi, Benz & Michel 2008)";
  const std::string epsilonAlpha =
      "exact jumps on the scene's epsilon-alpha model (Wünnemann, Collins & Melosh 2006; Collins, "
      "Melosh & Wünnemann 2011), closed on the state's volumetric strain";
  return {
      {"compaction_1d",
       "Porous aluminium (alpha_0 = 1.275) at 458 m/s, 1D: precursor and full compaction", 2,
       [palpha](const Options& o) {
         return compaction("compaction_1d", "compaction_1d", palpha, o, {});
       }},
      {"compaction_partial_1d",
       "Porous aluminium at 150 m/s, 1D: precursor and partial compaction on the crush curve", 2,
       [palpha](const Options& o) {
         return compaction("compaction_partial_1d", "compaction_1d", palpha, o,
                           {"bodies[0].velocity=[\"-150 m/s\"]"});
       }},
      {"compaction_epsalpha_1d",
       "Porous aluminium under epsilon-alpha at 458 m/s, 1D: elastic precursor and compaction "
       "into the power-law regime",
       2,
       [epsilonAlpha](const Options& o) {
         return compaction("compaction_epsalpha_1d", "compaction_epsalpha_1d", epsilonAlpha, o, {});
       }},
      {"compaction_sand_1d",
       "44%-porous sand under epsilon-alpha (iSALE's parameters) at 500 m/s, 1D: one compaction "
       "shock",
       2,
       [epsilonAlpha](const Options& o) {
         return compaction("compaction_sand_1d", "compaction_sand_1d", epsilonAlpha, o, {});
       }},
  };
}

}  // namespace ejecta::verify::detail
