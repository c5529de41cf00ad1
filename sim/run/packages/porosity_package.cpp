#include "sim/run/packages/porosity_package.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ejecta {

PorosityPackage::PorosityPackage(const MaterialTable& materials, DensityMethod density)
    : density_(density),
      palpha_(materials.size(), nullptr),
      epsilonAlpha_(materials.size(), nullptr),
      initialDistention_(materials.size(), 1.0),
      porousSolid_(materials.size(), 0) {
  for (std::size_t m = 0; m < materials.size(); ++m) {
    const PorosityModel* model = materials[m].porosity.get();
    if (!model) continue;
    porousSolid_[m] = materials[m].strength.has_value();
    anyPorousSolid_ = anyPorousSolid_ || porousSolid_[m];
    initialDistention_[m] = model->initialDistention();
    palpha_[m] = dynamic_cast<const PalphaModel*>(model);
    epsilonAlpha_[m] = dynamic_cast<const EpsilonAlphaModel*>(model);
    anyEpsilonAlpha_ = anyEpsilonAlpha_ || epsilonAlpha_[m];
  }
  largestInitialDistention_ = *std::max_element(initialDistention_.begin(), initialDistention_.end());
}

void PorosityPackage::registerFields(ParticleSet& p) {
  const bool carried = p.field(kDistention) != nullptr;  // read back from a snapshot
  FieldSpec alpha = scalarField(kDistention, "1",
                                "distention alpha = matrix density / bulk density (1: no pores)",
                                FieldOutput::Particles);
  alpha.grid = true;
  alpha.absent = 1.0;
  alpha.fill = 1.0;
  alpha.evolution = Evolution::Kicked;
  alpha.rate = kDistentionRate;
  alpha.limit = KickLimit::Clamp;
  alpha.lo = 1.0;
  alpha.hi = largestInitialDistention_;
  p.declare(alpha);
  p.declare(scalarField(kDistentionRate, "1/s", "rate of the distention", FieldOutput::Restart));
  if (anyEpsilonAlpha_) {
    FieldSpec strain = scalarField(
        kStrain, "1", "volumetric strain ln(V/V0) less the matrix's thermal part (epsilon-alpha)",
        FieldOutput::Restart);
    strain.evolution = Evolution::Kicked;
    strain.rate = kStrainRate;
    p.declare(strain);
    p.declare(scalarField(kStrainRate, "1/s", "rate of the volumetric strain", FieldOutput::Restart));
    p.declare(scalarField(kLeastStrain, "1",
                          "the most compressive volumetric strain reached (epsilon-alpha)",
                          FieldOutput::Restart));
  }
  if (anyPorousSolid_) {
    FieldSpec f = scalarField(kCompactionFactorField, "1",
                              "compaction factor f: the matrix's share of the bulk's volumetric "
                              "strain over the last step (porous solids; 1: rigid pores)",
                              FieldOutput::Particles);
    f.absent = 1.0;
    f.fill = 1.0;
    p.declare(f);
    // 0: not yet set (the first equation of state sets them, after the first density pass).
    p.declare(scalarField(kStartDistention, "1", "distention at the start of the step",
                          FieldOutput::Restart));
    p.declare(scalarField(kStartDensity, "kg/m^3", "bulk density at the start of the step",
                          FieldOutput::Restart));
  }
  if (carried) return;
  std::vector<double>& values = p.column(*p.field(kDistention), 0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto m = static_cast<std::size_t>(p.material[i]);
    if (m < initialDistention_.size()) values[i] = initialDistention_[m];
  }
}

void PorosityPackage::updateState(ParticleSet& p, const PackageContext& c) {
  std::vector<double>& alpha = p.column(*p.field(kDistention), 0);
  const std::size_t n = p.numReal;
  matrixDensity_.resize(n);
  matrixPressure_.resize(n);
  matrixSoundSpeed_.resize(n);
  for (std::size_t m = 0; m < c.materials.size(); ++m) {
    const Material& material = c.materials[m];
    if (!material.porosity) continue;
    members_.clear();
    for (std::size_t i = 0; i < n; ++i)
      if (static_cast<std::size_t>(p.material[i]) == m && selected(c.active, i)) members_.push_back(i);
    if (const EpsilonAlphaModel* model = epsilonAlpha_[m]) {
      // The distention of the present strain (kicked or predicted) and the history.
      const std::vector<double>& eps = p.column(*p.field(kStrain), 0);
      const std::vector<double>& least = p.column(*p.field(kLeastStrain), 0);
      const std::ptrdiff_t count = static_cast<std::ptrdiff_t>(members_.size());
#pragma omp parallel for schedule(static)
      for (std::ptrdiff_t k = 0; k < count; ++k) {
        const std::size_t i = members_[static_cast<std::size_t>(k)];
        alpha[i] = model->distention(eps[i], least[i]);
      }
    }
    for (std::size_t i : members_) matrixDensity_[i] = alpha[i] * p.rho[i];
    material.eos->evaluate(matrixDensity_.data(), p.u.data(), matrixPressure_.data(),
                           matrixSoundSpeed_.data(), members_.data(), members_.size());
    for (std::size_t i : members_) {
      p.P[i] = matrixPressure_[i] / alpha[i];
      p.cs[i] = material.porosity->soundSpeed(matrixSoundSpeed_[i], alpha[i]);
    }
    if (!porousSolid_[m]) continue;
    // A porous solid's first step starts here: from the first density pass's density (a run
    // from t = 0, or a snapshot written before these fields were).
    const MatrixShare share = matrixShare(p);
    for (std::size_t i : members_)
      if (share.startDensity[i] == 0.0) {
        share.startDensity[i] = p.rho[i];
        share.startDistention[i] = alpha[i];
      }
  }
}

void PorosityPackage::evaluateDerivatives(ParticleSet& p, const PackageContext& c) {
  const Field& field = *p.field(kDistention);
  const std::vector<double>& alpha = p.column(field, 0);
  std::vector<double>& rate = p.column(*p.field(kDistentionRate), 0);
  double* strainRate = anyEpsilonAlpha_ ? p.column(*p.field(kStrainRate), 0).data() : nullptr;
  const double* strain = anyEpsilonAlpha_ ? p.column(*p.field(kStrain), 0).data() : nullptr;
  const double* least = anyEpsilonAlpha_ ? p.column(*p.field(kLeastStrain), 0).data() : nullptr;
  const int components = anyPorousSolid_ ? p.stressComponents() : 0;
  const bool continuity = density_ == DensityMethod::Continuity;
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(p.numReal);
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    const std::size_t i = static_cast<std::size_t>(k);
    if (!selected(c.active, i)) continue;
    const auto m = static_cast<std::size_t>(p.material[i]);
    rate[i] = 0.0;
    // Summation density has no rate of its own: the continuity equation's, from the velocity
    // divergence of the density pass.
    const double rhoRate = continuity ? p.drho_dt[i] : -p.rho[i] * p.divv[i];
    double alphaRate = 0.0;
    if (const EpsilonAlphaModel* strainModel = epsilonAlpha_[m]) {
      strainRate[i] = strainModel->strainRate(-rhoRate / p.rho[i], p.du_dt[i]);
      if (porousSolid_[m])
        alphaRate = strainModel->signedDistentionRate(strain[i], least[i], strainRate[i]);
    } else if (const PalphaModel* model = palpha_[m]) {
      if (strainRate) strainRate[i] = 0.0;
      const Material& material = c.materials[m];
      const double rhoS = alpha[i] * p.rho[i];
      const EquationOfState::Slopes s = material.eos->pressureSlopes(rhoS, p.u[i]);
      rate[i] =
          model->distentionRate(alpha[i], p.P[i], p.rho[i], s.dRho, s.dU, rhoRate, p.du_dt[i]);
      alphaRate = rate[i];
    } else if (strainRate) {
      strainRate[i] = 0.0;
    }
    // The bulk carries the matrix's deviatoric stress over alpha (S = S_s/alpha): as the pores
    // close, the same matrix stress is a larger bulk stress.
    if (porousSolid_[m] && alphaRate != 0.0)
      for (int q = 0; q < components; ++q)
        p.dstress_dt[q][i] -= p.stress[q][i] * alphaRate / alpha[i];
  }
}

void PorosityPackage::finalize(ParticleSet& p, const PackageContext& c) {
  // P-alpha: the return to the crush curve of the states the step's integration left above it
  // (and to alpha = 1 past Ps), with the pressure and sound speed of the state returned to.
  // epsilon-alpha: the step's strain joins the history (alpha, a function of both, is
  // unchanged by it). Porous solids: the compaction factor of the step (followMatrix).
  std::vector<double>& alpha = p.column(*p.field(kDistention), 0);
  const double* eps = anyEpsilonAlpha_ ? p.column(*p.field(kStrain), 0).data() : nullptr;
  double* least = anyEpsilonAlpha_ ? p.column(*p.field(kLeastStrain), 0).data() : nullptr;
  const MatrixShare share = matrixShare(p);
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(p.numReal);
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t k = 0; k < n; ++k) {
    const std::size_t i = static_cast<std::size_t>(k);
    if (!selected(c.active, i)) continue;
    const auto m = static_cast<std::size_t>(p.material[i]);
    double alphaNow = alpha[i];
    if (const EpsilonAlphaModel* strainModel = epsilonAlpha_[m]) {
      least[i] = std::min(least[i], eps[i]);
      // The column may hold the step-start value (it is kicked with rate 0): the step's own.
      if (porousSolid_[m]) alphaNow = strainModel->distention(eps[i], least[i]);
    } else if (const PalphaModel* model = palpha_[m]) {
      const Material& material = c.materials[m];
      const double returned = model->returnToCrushCurve(alpha[i], p.rho[i], p.u[i], *material.eos);
      if (returned != alpha[i]) {
        // The return closes pores, not the matrix: the matrix's stress alpha S is kept.
        if (porousSolid_[m])
          for (int q = 0; q < p.stressComponents(); ++q) p.stress[q][i] *= alpha[i] / returned;
        alpha[i] = alphaNow = returned;
        const double rhoS = returned * p.rho[i];
        p.P[i] = material.eos->pressure(rhoS, p.u[i]) / returned;
        p.cs[i] = model->soundSpeed(material.eos->soundSpeed(rhoS, p.u[i]), returned);
        // A solid's sound speed carries its shear modulus too (applySolidSoundSpeed).
        if (material.strength) {
          const double G = material.strength->shearModulus / returned;
          p.cs[i] = std::sqrt(p.cs[i] * p.cs[i] + 4.0 * G / (3.0 * p.rho[i]));
        }
      }
    }
    if (porousSolid_[m]) followMatrix(p, share, i, alphaNow);
  }
}

PorosityPackage::MatrixShare PorosityPackage::matrixShare(ParticleSet& p) const {
  if (!anyPorousSolid_) return {};
  return {p.column(*p.field(kCompactionFactorField), 0).data(),
          p.column(*p.field(kStartDistention), 0).data(),
          p.column(*p.field(kStartDensity), 0).data()};
}

void PorosityPackage::followMatrix(ParticleSet& p, const MatrixShare& share, std::size_t i,
                                   double alpha) const {
  // The step's volumetric strains, the bulk's ln(rho/rho_start) and the pores'
  // ln(alpha/alpha_start): the matrix took 1 + pores/bulk of the bulk's, clamped to [0, 1] (where
  // the matrix's own thermal expansion outruns it, or numerical noise). Where the pores did not
  // move that is 1; where the bulk did not (heating alone moving a P-alpha distention) the share
  // is undefined and the last one is kept.
  const double bulk = std::log(p.rho[i] / share.startDensity[i]);
  const double pores = std::log(alpha / share.startDistention[i]);
  if (pores == 0.0) share.factor[i] = 1.0;
  else if (bulk != 0.0) share.factor[i] = std::clamp(1.0 + pores / bulk, 0.0, 1.0);
  share.startDistention[i] = alpha;
  share.startDensity[i] = p.rho[i];
}

PorosityPackage::StepColumns PorosityPackage::stepColumns(const ParticleSet& p) const {
  StepColumns columns;
  columns.distentionRate = p.column(*p.field(kDistentionRate), 0).data();
  if (anyEpsilonAlpha_) {
    columns.strain = p.column(*p.field(kStrain), 0).data();
    columns.leastStrain = p.column(*p.field(kLeastStrain), 0).data();
    columns.strainRate = p.column(*p.field(kStrainRate), 0).data();
  }
  return columns;
}

double PorosityPackage::particleTimestep(const ParticleSet& p, const PackageContext& c,
                                         const StepColumns& columns, std::size_t i) const {
  const auto m = static_cast<std::size_t>(p.material[i]);
  const PorosityModel* model = c.materials[m].porosity.get();
  if (!model) return std::numeric_limits<double>::infinity();
  const EpsilonAlphaModel* strainModel = epsilonAlpha_[m];
  const double r = strainModel ? strainModel->distentionRate(columns.strain[i], columns.leastStrain[i],
                                                             columns.strainRate[i])
                               : std::abs(columns.distentionRate[i]);
  if (!(r > 0.0)) return std::numeric_limits<double>::infinity();
  return model->maxChangePerStep() / r;
}

double PorosityPackage::timestep(const ParticleSet& p, const PackageContext& c) const {
  const StepColumns columns = stepColumns(p);
  double dt = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < p.numReal; ++i) dt = std::min(dt, particleTimestep(p, c, columns, i));
  return dt;
}

void PorosityPackage::particleTimesteps(const ParticleSet& p, const PackageContext& c,
                                        std::span<const std::size_t> which,
                                        std::span<double> dt) const {
  const StepColumns columns = stepColumns(p);
  for (std::size_t k = 0; k < which.size(); ++k)
    dt[k] = std::min(dt[k], particleTimestep(p, c, columns, which[k]));
}

}  // namespace ejecta
