#include "sim/solid/solid_state.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "sim/solid/fracture.hpp"
#include "sim/solid/porosity.hpp"
#include "sim/state/tensor.hpp"

namespace ejecta {

namespace {

// Flaws of particle i that its present state activates, out of all it holds; {0, 0} for a
// particle outside the Grady-Kipp tables.
struct FlawActivity {
  std::uint32_t active = 0;
  std::uint32_t total = 0;
};

// The shear modulus of particle i: its material's, over its distention where it is porous (the
// bulk carries the matrix's stress over alpha, as its pressure: docs/porosity.md).
double shearModulusOf(const Material& mat, std::size_t i, const double* distention) {
  return distention ? mat.strength->shearModulus / distention[i] : mat.strength->shearModulus;
}

// The bulk modulus of the intact material, rho c^2 with c the equation of state's sound speed:
// p.cs holds sqrt(c^2 + 4G/(3 rho)) (applySolidSoundSpeed) and no damage enters either.
double intactBulkModulus(const ParticleSet& p, std::size_t i, double shearModulus) {
  return std::max(p.rho[i] * p.cs[i] * p.cs[i] - 4.0 * shearModulus / 3.0, 0.0);
}

FlawActivity flawActivity(const ParticleSet& p, const Material& mat, const FlawSet& flaws,
                          int dimension, std::size_t i, const double* distention) {
  const std::size_t id = static_cast<std::size_t>(p.id[i]);
  if (flaws.empty() || id >= flaws.tableOfId.size() || flaws.tableOfId[id] < 0) return {};
  const FlawTable& table = flaws.tables[static_cast<std::size_t>(flaws.tableOfId[id])];
  const std::size_t row = flaws.rowOfId[id];
  FlawActivity a;
  a.total = table.count(row);
  const double D = p.damage(i);
  if (D >= 1.0) {
    a.active = a.total;
    return a;
  }
  // Largest principal stress of the damaged stress state, tension positive.
  const SymTensor sigma = effectiveStress(p, i, mat.strength->yieldCarriesDamage());
  double tension;
  if (dimension == 3) {
    std::array<double, 3> values;
    symmetricEigen(sigma, values, nullptr);
    tension = values[2];
  } else {
    double lo, hi, c, s;
    planeEigen(sigma[kXX], sigma[kYY], sigma[kXY], lo, hi, c, s);
    tension = std::max(hi, sigma[kZZ]);  // zz (hoop in RZ) is principal too
  }
  if (tension <= 0.0) return a;
  const double G = shearModulusOf(mat, i, distention);
  const double strain = tension / ((1.0 - D) * youngsModulus(intactBulkModulus(p, i, G), G));
  a.active = table.activeCount(row, strain);
  return a;
}

}  // namespace

FlawSet distributeMaterialFlaws(const ParticleSet& initial, const MaterialTable& materials) {
  FlawSet set;
  bool any = false;
  for (std::size_t m = 0; m < materials.size(); ++m)
    any = any || materials[m].fracture.kind == FractureKind::GradyKipp;
  if (!any) return set;
  std::int64_t maxId = -1;
  for (std::size_t i = 0; i < initial.numReal; ++i) maxId = std::max(maxId, initial.id[i]);
  set.tables.resize(materials.size());
  set.tableOfId.assign(static_cast<std::size_t>(maxId + 1), -1);
  set.rowOfId.assign(static_cast<std::size_t>(maxId + 1), 0);
  for (std::size_t m = 0; m < materials.size(); ++m) {
    const FractureModel& f = materials[m].fracture;
    if (f.kind != FractureKind::GradyKipp) continue;
    // Particles in id order, so the draw does not depend on how the set was sorted. The flaws
    // are the matrix's, on its volume m/rho_s = m/(alpha_0 rho) where the material is porous
    // (Jutzi, Benz & Michel 2008, as Spheral's Benz-Asphaug seeding reads it: the porosity's
    // solid density): a porous body has fewer, so its weakest flaw is stronger by alpha_0^(1/m).
    const PorosityModel* porosity = materials[m].porosity.get();
    const double alpha0 = porosity ? porosity->initialDistention() : 1.0;
    std::vector<std::pair<std::int64_t, double>> members;
    for (std::size_t i = 0; i < initial.numReal; ++i)
      if (initial.material[i] == static_cast<int>(m))
        members.emplace_back(initial.id[i], initial.mass[i] / (alpha0 * initial.rho[i]));
    if (members.empty()) continue;
    std::sort(members.begin(), members.end());
    std::vector<double> volumes(members.size());
    for (std::size_t k = 0; k < members.size(); ++k) {
      volumes[k] = members[k].second;
      set.tableOfId[static_cast<std::size_t>(members[k].first)] = static_cast<std::int32_t>(m);
      set.rowOfId[static_cast<std::size_t>(members[k].first)] = static_cast<std::uint32_t>(k);
    }
    set.tables[m] = distributeFlaws(volumes, f.weibull, f.seed * 1000003ull + m);
  }
  return set;
}

void applyTemperature(ParticleSet& p, const MaterialTable& materials, const ParticleMask* only) {
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < p.numReal; ++i)
    if (selected(only, i))
      p.temperature[i] = materials[static_cast<std::size_t>(p.material[i])].thermal.temperature(p.u[i]);
}

void applyDamageToTension(ParticleSet& p, const ParticleMask* only) {
  if (!p.hasFracture()) return;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < p.numReal; ++i)
    if (selected(only, i) && p.P[i] < 0.0) p.P[i] *= 1.0 - p.damage(i);
}

void applySolidSoundSpeed(ParticleSet& p, const MaterialTable& materials, const ParticleMask* only) {
  const double* distention = distentionColumn(p);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < p.numReal; ++i) {
    if (!selected(only, i)) continue;
    const Material& mat = materials[static_cast<std::size_t>(p.material[i])];
    if (!mat.strength) continue;
    const double G = shearModulusOf(mat, i, distention);
    const double c2 = p.cs[i] * p.cs[i] + 4.0 * G / (3.0 * p.rho[i]);
    p.cs[i] = std::sqrt(c2);
  }
}

void applyPlasticity(ParticleSet& p, const MaterialTable& materials, bool accumulate,
                     const ParticleMask* only) {
  const int nc = p.stressComponents();
  if (nc == 0) return;
  const double* distention = distentionColumn(p);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < p.numReal; ++i) {
    if (!selected(only, i)) continue;
    const Material& mat = materials[static_cast<std::size_t>(p.material[i])];
    if (!mat.strength) continue;
    const StrengthModel& s = *mat.strength;
    const double D = p.damage(i);
    // A porous particle yields where its matrix does: at the matrix pressure alpha P, the bulk
    // carrying the matrix's flow stress over alpha.
    const double alpha = distention ? distention[i] : 1.0;
    const double flow = s.flowStress(p.plasticStrain[i], p.strainRate[i], p.temperature[i],
                                     mat.thermal.meltTemperature, alpha * p.P[i], D) / alpha;
    SymTensor S;
    for (int c = 0; c < nc; ++c) S[c] = p.stress[c][i];
    const double dEp = radialReturn(S, flow, s.shearModulus / alpha);
    if (dEp == 0.0) continue;
    for (int c = 0; c < nc; ++c) p.stress[c][i] = S[c];
    // Only the intact fraction 1 - D yields (applyPlasticity in solid_state.hpp); with a
    // damaged yield surface (Collins) the whole particle flows.
    if (accumulate) p.plasticStrain[i] += (s.yieldCarriesDamage() ? 1.0 : 1.0 - D) * dEp;
  }
}

void computeCrackGrowth(ParticleSet& p, const MaterialTable& materials, const FlawSet& flaws,
                        int dimension, const ParticleMask* only) {
  if (!p.hasFracture()) return;
  const double* distention = distentionColumn(p);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < p.numReal; ++i) {
    if (!selected(only, i)) continue;
    p.dcrack_dt[i] = 0.0;
    const Material& mat = materials[static_cast<std::size_t>(p.material[i])];
    if (mat.fracture.kind != FractureKind::GradyKipp || p.damage(i) >= 1.0) continue;
    const FlawActivity activity = flawActivity(p, mat, flaws, dimension, i, distention);
    if (activity.active == 0) continue;
    // c_g = 0.4 c_l of the intact material: undamaged K and G (miluphcuda lowers G by 1 - D).
    const double G = shearModulusOf(mat, i, distention);
    const double cl = intactLongitudinalSpeed(intactBulkModulus(p, i, G), G, p.rho[i]);
    p.dcrack_dt[i] = crackGrowthRate(activity.active, activity.total, p.crack[i], cl, p.h[i],
                                     mat.fracture.crackSpeedFactor);
  }
}

std::vector<double> crackCaps(const ParticleSet& p, const MaterialTable& materials,
                              const FlawSet& flaws, int dimension) {
  std::vector<double> caps(p.numReal, 1.0);
  if (!p.hasFracture()) return caps;
  const double* distention = distentionColumn(p);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < p.numReal; ++i) {
    // Only growing cracks need their cap (and the eigenvalues behind it).
    if (!(p.dcrack_dt[i] > 0.0)) continue;
    const Material& mat = materials[static_cast<std::size_t>(p.material[i])];
    if (mat.fracture.kind != FractureKind::GradyKipp) continue;
    const FlawActivity activity = flawActivity(p, mat, flaws, dimension, i, distention);
    caps[i] = crackCap(activity.active, activity.total);
  }
  return caps;
}

double crackGrowthTimestep(const ParticleSet& p, const MaterialTable& materials) {
  double dt = std::numeric_limits<double>::infinity();
  if (!p.hasFracture()) return dt;
  for (std::size_t i = 0; i < p.numReal; ++i) {
    if (!(p.dcrack_dt[i] > 0.0)) continue;
    const FractureModel& f = materials[static_cast<std::size_t>(p.material[i])].fracture;
    dt = std::min(dt, crackStepLimit(p.dcrack_dt[i], f.maxCrackIncrement));
  }
  return dt;
}

void crackGrowthTimesteps(const ParticleSet& p, const MaterialTable& materials,
                          std::span<const std::size_t> which, std::span<double> dt) {
  if (!p.hasFracture()) return;
  for (std::size_t k = 0; k < which.size(); ++k) {
    const std::size_t i = which[k];
    if (!(p.dcrack_dt[i] > 0.0)) continue;
    const FractureModel& f = materials[static_cast<std::size_t>(p.material[i])].fracture;
    dt[k] = std::min(dt[k], crackStepLimit(p.dcrack_dt[i], f.maxCrackIncrement));
  }
}

std::size_t applyFailure(ParticleSet& p, const MaterialTable& materials, const ParticleMask* only) {
  if (!p.hasFracture()) return 0;
  std::size_t failed = 0;
#pragma omp parallel for schedule(static) reduction(+ : failed)
  for (std::size_t i = 0; i < p.numReal; ++i) {
    if (!selected(only, i)) continue;
    if (p.crack[i] >= 1.0) continue;
    const FractureModel& f = materials[static_cast<std::size_t>(p.material[i])].fracture;
    bool fails = p.stressComponents() > 0 && p.totalStrain[i] > f.erosionStrain;
    if (!fails && f.kind == FractureKind::PrincipalStress) {
      std::array<double, 3> values;
      const Material& mat = materials[static_cast<std::size_t>(p.material[i])];
      const bool carries = mat.strength && mat.strength->yieldCarriesDamage();
      symmetricEigen(effectiveStress(p, i, carries), values, nullptr);
      fails = values[2] > f.tensileStrength;
    }
    if (!fails) continue;
    p.crack[i] = 1.0;
    p.P[i] = std::max(p.P[i], 0.0);
    ++failed;
  }
  return failed;
}

}  // namespace ejecta
