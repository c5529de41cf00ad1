#include "sim/sources/programmed_burn.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/input_error.hpp"
#include "sim/eos/jwl.hpp"

namespace ejecta {

namespace {

// Fraction of a spacing over which the burn fraction rises (LS-DYNA's 3/2, see the header).
constexpr double kBurnWidthInSpacings = 1.5;

using Point = std::array<double, 3>;

// Distance from x to the detonation's point, or to its segment for a line initiation.
double distanceToInitiation(const DetonationSpec& d, const Point& x, int dim) {
  Point a = d.point, ab{}, ax{};
  double ab2 = 0.0, t = 0.0;
  for (int k = 0; k < dim; ++k) {
    ab[k] = d.alongLine ? d.lineEnd[k] - a[k] : 0.0;
    ax[k] = x[k] - a[k];
    ab2 += ab[k] * ab[k];
  }
  if (ab2 > 0.0) {
    for (int k = 0; k < dim; ++k) t += ax[k] * ab[k];
    t = std::clamp(t / ab2, 0.0, 1.0);
  }
  double r2 = 0.0;
  for (int k = 0; k < dim; ++k) r2 += (ax[k] - t * ab[k]) * (ax[k] - t * ab[k]);
  return std::sqrt(r2);
}

}  // namespace

std::vector<double> burnVelocities(const std::vector<DetonationSpec>& detonations,
                                   const MaterialTable& materials) {
  std::vector<double> v(materials.size(), 0.0);
  for (const DetonationSpec& d : detonations) {
    const std::size_t m = static_cast<std::size_t>(d.material);
    if (d.velocity > 0.0) {
      v[m] = d.velocity;
    } else if (const auto* jwl = dynamic_cast<const Jwl*>(materials[m].eos.get())) {
      v[m] = jwl->params().dCJ;
    }
    if (!(v[m] > 0.0))
      throw SceneError("detonation '" + d.name + "': material '" + materials[m].name +
                       "' has no C-J velocity; give the detonation a 'velocity'");
  }
  return v;
}

BurnTable burnTable(const std::vector<DetonationSpec>& detonations, const MaterialTable& materials) {
  BurnTable table;
  table.velocity = burnVelocities(detonations, materials);
  table.rho0.assign(materials.size(), 0.0);
  table.cjRelativeVolume.assign(materials.size(), 0.0);
  for (std::size_t m = 0; m < materials.size(); ++m) {
    const auto* jwl = dynamic_cast<const Jwl*>(materials[m].eos.get());
    if (table.velocity[m] <= 0.0 || !jwl) continue;
    const JwlParams& j = jwl->params();
    // Rankine-Hugoniot across the C-J front: u_CJ = p_CJ / (rho0 D), V_CJ = 1 - u_CJ / D.
    const double vCJ = 1.0 - j.pCJ / (j.rho0 * j.dCJ * j.dCJ);
    if (j.rho0 > 0.0 && vCJ > 0.0 && vCJ < 1.0) {
      table.rho0[m] = j.rho0;
      table.cjRelativeVolume[m] = vCJ;
    }
  }
  return table;
}

void assignLightingTimes(const std::vector<DetonationSpec>& detonations, Geometry geometry,
                         const MaterialTable& materials, ParticleSet& p) {
  if (detonations.empty()) return;
  const std::vector<double> velocity = burnVelocities(detonations, materials);
  const int dim = spatialDimension(geometry);
  p.enableBurn();
  for (std::size_t i = 0; i < p.numReal; ++i) {
    const std::size_t m = static_cast<std::size_t>(p.material[i]);
    if (velocity[m] <= 0.0) continue;  // not an explosive: burnt from the start (F = 1)
    double tL = std::numeric_limits<double>::infinity();
    for (const DetonationSpec& d : detonations) {
      if (static_cast<std::size_t>(d.material) != m) continue;
      const Point x{p.x[0][i], p.x[1][i], p.x[2][i]};
      tL = std::min(tL, d.time + distanceToInitiation(d, x, dim) / velocity[m]);
    }
    p.lightingTime[i] = tL;
    p.burnFraction[i] = 0.0;
  }
}

void applyProgrammedBurn(ParticleSet& p, const BurnTable& burn, double eta, double t,
                         const ParticleMask* only) {
  if (!p.hasBurn()) return;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < p.numReal; ++i) {
    if (!selected(only, i)) continue;
    const auto m = static_cast<std::size_t>(p.material[i]);
    const double D = burn.velocity[m];
    if (D <= 0.0) continue;
    if (p.burnFraction[i] < 1.0) {
      double f = p.burnFraction[i];
      const double width = kBurnWidthInSpacings * p.h[i] / eta;
      if (t > p.lightingTime[i]) f = std::max(f, (t - p.lightingTime[i]) * D / width);
      // The compression burn only within one ramp width ahead of the programmed front: further
      // ahead, SPH's smoothing compresses explosive the front has not reached, and a burn lit by
      // that compression runs ahead of the front (at 0.8 mm the water shock left 2.7x early).
      const double vCJ = burn.cjRelativeVolume[m];
      if (vCJ > 0.0 && p.rho[i] > burn.rho0[m] && (p.lightingTime[i] - t) * D < width)
        f = std::max(f, (1.0 - burn.rho0[m] / p.rho[i]) / (1.0 - vCJ));
      p.burnFraction[i] = std::min(1.0, f);
    }
    p.P[i] *= p.burnFraction[i];
  }
}

}  // namespace ejecta
