#include "sim/run/packages/porosity_package.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ejecta {

namespace {

const PalphaModel* porosityOf(const MaterialTable& materials, int material) {
  const Material& m = materials[static_cast<std::size_t>(material)];
  return m.porosity ? &*m.porosity : nullptr;
}

}  // namespace

PorosityPackage::PorosityPackage(const MaterialTable& materials, DensityMethod density)
    : density_(density), initialDistention_(materials.size(), 1.0) {
  for (std::size_t m = 0; m < materials.size(); ++m)
    if (materials[m].porosity) initialDistention_[m] = materials[m].porosity->initialDistention();
  largestInitialDistention_ = *std::max_element(initialDistention_.begin(), initialDistention_.end());
}

void PorosityPackage::registerFields(ParticleSet& p) {
  const bool carried = p.field(kDistention) != nullptr;  // read back from a snapshot
  FieldSpec alpha;
  alpha.name = kDistention;
  alpha.units = "1";
  alpha.description = "distention alpha = matrix density / bulk density (1: no pores)";
  alpha.output = FieldOutput::Particles;
  alpha.grid = true;
  alpha.absent = 1.0;
  alpha.fill = 1.0;
  alpha.evolution = Evolution::Kicked;
  alpha.rate = kDistentionRate;
  alpha.limit = KickLimit::Clamp;
  alpha.lo = 1.0;
  alpha.hi = largestInitialDistention_;
  FieldSpec rate;
  rate.name = kDistentionRate;
  rate.units = "1/s";
  rate.description = "rate of the distention";
  rate.output = FieldOutput::Restart;
  p.declare(alpha);
  p.declare(rate);
  if (carried) return;
  std::vector<double>& values = p.column(*p.field(kDistention), 0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto m = static_cast<std::size_t>(p.material[i]);
    if (m < initialDistention_.size()) values[i] = initialDistention_[m];
  }
}

void PorosityPackage::updateState(ParticleSet& p, const PackageContext& c) {
  const Field& field = *p.field(kDistention);
  const std::vector<double>& alpha = p.column(field, 0);
  const std::size_t n = p.numReal;
  matrixDensity_.resize(n);
  matrixPressure_.resize(n);
  matrixSoundSpeed_.resize(n);
  for (std::size_t m = 0; m < c.materials.size(); ++m) {
    const Material& material = c.materials[m];
    if (!material.porosity) continue;
    members_.clear();
    for (std::size_t i = 0; i < n; ++i)
      if (static_cast<std::size_t>(p.material[i]) == m && selected(c.active, i)) {
        members_.push_back(i);
        matrixDensity_[i] = alpha[i] * p.rho[i];
      }
    material.eos->evaluate(matrixDensity_.data(), p.u.data(), matrixPressure_.data(),
                           matrixSoundSpeed_.data(), members_.data(), members_.size());
    for (std::size_t i : members_) {
      p.P[i] = matrixPressure_[i] / alpha[i];
      p.cs[i] = material.porosity->soundSpeed(matrixSoundSpeed_[i], alpha[i]);
    }
  }
}

void PorosityPackage::evaluateDerivatives(ParticleSet& p, const PackageContext& c) {
  const Field& field = *p.field(kDistention);
  const std::vector<double>& alpha = p.column(field, 0);
  std::vector<double>& rate = p.column(*p.field(kDistentionRate), 0);
  const bool continuity = density_ == DensityMethod::Continuity;
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(p.numReal);
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    const std::size_t i = static_cast<std::size_t>(k);
    if (!selected(c.active, i)) continue;
    const Material& material = c.materials[static_cast<std::size_t>(p.material[i])];
    if (!material.porosity) {
      rate[i] = 0.0;
      continue;
    }
    const double rhoS = alpha[i] * p.rho[i];
    const EquationOfState::Slopes s = material.eos->pressureSlopes(rhoS, p.u[i]);
    // Summation density has no rate of its own: the continuity equation's, from the velocity
    // divergence of the density pass.
    const double rhoRate = continuity ? p.drho_dt[i] : -p.rho[i] * p.divv[i];
    rate[i] = material.porosity->distentionRate(alpha[i], p.P[i], p.rho[i], s.dRho, s.dU,
                                                rhoRate, p.du_dt[i]);
  }
}

void PorosityPackage::finalize(ParticleSet& p, const PackageContext& c) {
  // The return to the crush curve of the states the step's integration left above it (and to
  // alpha = 1 past Ps), with the pressure and sound speed of the state returned to.
  std::vector<double>& alpha = p.column(*p.field(kDistention), 0);
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(p.numReal);
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    const std::size_t i = static_cast<std::size_t>(k);
    if (!selected(c.active, i)) continue;
    const Material& material = c.materials[static_cast<std::size_t>(p.material[i])];
    if (!material.porosity) continue;
    const double returned =
        material.porosity->returnToCrushCurve(alpha[i], p.rho[i], p.u[i], *material.eos);
    if (returned == alpha[i]) continue;
    alpha[i] = returned;
    const double rhoS = returned * p.rho[i];
    p.P[i] = material.eos->pressure(rhoS, p.u[i]) / returned;
    p.cs[i] = material.porosity->soundSpeed(material.eos->soundSpeed(rhoS, p.u[i]), returned);
  }
}

double PorosityPackage::particleTimestep(const ParticleSet& p, const PackageContext& c,
                                         std::size_t i) const {
  const PalphaModel* model = porosityOf(c.materials, p.material[i]);
  const double r = std::abs(p.column(*p.field(kDistentionRate), 0)[i]);
  if (!model || !(r > 0.0)) return std::numeric_limits<double>::infinity();
  return model->parameters().maxChangePerStep / r;
}

double PorosityPackage::timestep(const ParticleSet& p, const PackageContext& c) const {
  double dt = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < p.numReal; ++i) dt = std::min(dt, particleTimestep(p, c, i));
  return dt;
}

void PorosityPackage::particleTimesteps(const ParticleSet& p, const PackageContext& c,
                                        std::span<const std::size_t> which,
                                        std::span<double> dt) const {
  for (std::size_t k = 0; k < which.size(); ++k)
    dt[k] = std::min(dt[k], particleTimestep(p, c, which[k]));
}

}  // namespace ejecta
