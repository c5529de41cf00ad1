#include "sim/run/packages/smoothing_length_cap_package.hpp"

#include <cmath>
#include <numbers>

namespace ejecta {

SmoothingLengthCapPackage::SmoothingLengthCapPackage(const SphOptions& sph, Geometry geometry)
    : factor_(sph.hMaxFactor),
      eta_(sph.eta),
      continuity_(sph.density == DensityMethod::Continuity),
      geometry_(geometry) {
  if (geometry == Geometry::Axisymmetric) axis_.emplace(sph.kernel);
}

void SmoothingLengthCapPackage::registerFields(ParticleSet& p) {
  const bool carried = p.field(kCap) != nullptr;  // read back from a snapshot
  p.declare(scalarField(kCap, "m",
                        "largest smoothing length the particle may take (sph.h_max_factor x its "
                        "first h)",
                        FieldOutput::Restart));
  if (carried) return;
  std::vector<double>& values = p.column(*p.field(kCap), 0);
  for (std::size_t i = 0; i < p.size(); ++i) values[i] = factor_ * p.h[i];
}

void SmoothingLengthCapPackage::afterDrift(ParticleSet& p, const PackageContext&) {
  holdToCaps(p, nullptr);  // every particle's state is predicted
}

void SmoothingLengthCapPackage::holdToCaps(ParticleSet& p, const ParticleMask* only) const {
  const double* cap = caps(p);
  if (!cap) return;
  const int D = spatialDimension(geometry_);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < p.numReal; ++i) {
    if (!selected(only, i)) continue;
    if (p.h[i] > cap[i]) p.h[i] = cap[i];
    if (!continuity_) continue;
    // h = eta (m / sigma)^(1/D) (setSmoothingFromDensity) is the cap at sigma = m (eta/cap)^D,
    // sigma the density (RZ: the area density 2 pi rt rho).
    double sigma = p.mass[i] * std::pow(eta_ / cap[i], D);
    if (axis_) {
      double rt, drt;
      axis_->smoothedRadius(p.x[0][i], cap[i], rt, drt);
      sigma /= 2.0 * std::numbers::pi * rt;
    }
    if (p.rho[i] < sigma) p.rho[i] = sigma;  // a NaN stays for the health check
  }
}

const double* SmoothingLengthCapPackage::caps(const ParticleSet& p) {
  const Field* f = p.field(kCap);
  return f ? p.column(*f, 0).data() : nullptr;
}

}  // namespace ejecta
