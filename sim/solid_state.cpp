#include "sim/solid_state.hpp"

#include <algorithm>
#include <cmath>

#include "sim/fracture.hpp"
#include "sim/tensor.hpp"

namespace ejecta {

SymTensor effectiveStress(const ParticleSet& p, std::size_t i) {
  SymTensor sigma;
  const double intact = 1.0 - p.damage(i);
  for (int c = 0; c < p.stressComponents(); ++c) sigma[c] = intact * p.stress[c][i];
  for (int c = 0; c < 3; ++c) sigma[c] -= p.P[i];
  return sigma;
}

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
    // Particles in id order, so the draw does not depend on how the set was sorted.
    std::vector<std::pair<std::int64_t, double>> members;
    for (std::size_t i = 0; i < initial.numReal; ++i)
      if (initial.material[i] == static_cast<int>(m))
        members.emplace_back(initial.id[i], initial.mass[i] / initial.rho[i]);
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

void applyMaterialState(ParticleSet& p, const MaterialTable& materials) {
  const bool fracture = p.hasFracture();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < p.numReal; ++i) {
    const Material& mat = materials[static_cast<std::size_t>(p.material[i])];
    p.temperature[i] = mat.thermal.temperature(p.u[i]);
    if (fracture && p.P[i] < 0.0) p.P[i] *= 1.0 - p.damage(i);
    if (mat.strength) {
      const double c2 = p.cs[i] * p.cs[i] + 4.0 * mat.strength->shearModulus / (3.0 * p.rho[i]);
      p.cs[i] = std::sqrt(c2);
    }
  }
}

void applyPlasticity(ParticleSet& p, const MaterialTable& materials, bool accumulate) {
  const int nc = p.stressComponents();
  if (nc == 0) return;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < p.numReal; ++i) {
    const Material& mat = materials[static_cast<std::size_t>(p.material[i])];
    if (!mat.strength) continue;
    const StrengthModel& s = *mat.strength;
    const double flow = s.flowStress(p.plasticStrain[i], p.strainRate[i], p.temperature[i],
                                     mat.thermal.meltTemperature);
    SymTensor S;
    for (int c = 0; c < nc; ++c) S[c] = p.stress[c][i];
    const double dEp = radialReturn(S, flow, s.shearModulus);
    if (dEp == 0.0) continue;
    for (int c = 0; c < nc; ++c) p.stress[c][i] = S[c];
    if (accumulate) p.plasticStrain[i] += dEp;
  }
}

void computeCrackGrowth(ParticleSet& p, const MaterialTable& materials, const FlawSet& flaws,
                        int dimension) {
  if (!p.hasFracture()) return;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < p.numReal; ++i) {
    p.dcrack_dt[i] = 0.0;
    const Material& mat = materials[static_cast<std::size_t>(p.material[i])];
    if (mat.fracture.kind != FractureKind::GradyKipp || flaws.empty()) continue;
    const std::size_t id = static_cast<std::size_t>(p.id[i]);
    if (id >= flaws.tableOfId.size() || flaws.tableOfId[id] < 0) continue;
    const double D = p.damage(i);
    if (D >= 1.0) continue;
    // Largest principal stress of the damaged stress state, tension positive.
    const SymTensor sigma = effectiveStress(p, i);
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
    if (tension <= 0.0) continue;
    const double G = mat.strength->shearModulus;
    const double bulk = std::max(p.rho[i] * p.cs[i] * p.cs[i] - 4.0 * G / 3.0, 0.0);
    const double strain = tension / ((1.0 - D) * youngsModulus(bulk, G));
    const FlawTable& table = flaws.tables[static_cast<std::size_t>(flaws.tableOfId[id])];
    const std::size_t row = flaws.rowOfId[id];
    p.dcrack_dt[i] = crackGrowthRate(table.activeCount(row, strain), table.count(row), p.crack[i],
                                     p.cs[i], p.h[i], mat.fracture.crackSpeedFactor);
  }
}

std::size_t applyFailure(ParticleSet& p, const MaterialTable& materials) {
  if (!p.hasFracture()) return 0;
  std::size_t failed = 0;
#pragma omp parallel for schedule(static) reduction(+ : failed)
  for (std::size_t i = 0; i < p.numReal; ++i) {
    if (p.crack[i] >= 1.0) continue;
    const FractureModel& f = materials[static_cast<std::size_t>(p.material[i])].fracture;
    bool fails = p.stressComponents() > 0 && p.totalStrain[i] > f.erosionStrain;
    if (!fails && f.kind == FractureKind::PrincipalStress) {
      std::array<double, 3> values;
      symmetricEigen(effectiveStress(p, i), values, nullptr);
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
