#include "sim/state/particles.hpp"

#include <algorithm>
#include <limits>

namespace ejecta {

namespace {

template <typename T>
void permuteArray(std::vector<T>& data, const std::vector<std::size_t>& order) {
  std::vector<T> out(order.size());
  for (std::size_t i = 0; i < order.size(); ++i) out[i] = data[order[i]];
  data.swap(out);
}

// Applies f to every per-particle array.
template <typename F>
void forEachArray(ParticleSet& p, F&& f) {
  for (int d = 0; d < 3; ++d) { f(p.x[d]); f(p.v[d]); f(p.a[d]); }
  f(p.mass); f(p.rho); f(p.u); f(p.h); f(p.material); f(p.id);
  f(p.P); f(p.cs); f(p.du_dt); f(p.drho_dt); f(p.dh_dt);
  f(p.omega); f(p.divv); f(p.curlv); f(p.areaDensity); f(p.temperature);
  for (int c = 0; c < p.stressComponents(); ++c) { f(p.stress[c]); f(p.dstress_dt[c]); }
  if (p.stressComponents() > 0) { f(p.plasticStrain); f(p.totalStrain); f(p.strainRate); }
  if (p.hasFracture()) { f(p.crack); f(p.dcrack_dt); }
  if (p.hasBurn()) { f(p.lightingTime); f(p.burnFraction); }
  if (p.hasViscositySwitch()) { f(p.alpha); f(p.dalpha_dt); }
}

}  // namespace

void ParticleSet::resize(std::size_t n) {
  const std::size_t old = size();
  forEachArray(*this, [n](auto& arr) { arr.resize(n); });
  for (std::size_t i = old; i < n; ++i) omega[i] = 1.0;
}

void ParticleSet::enableStrength(int components) {
  stressComponents_ = components;
  const std::size_t n = size();
  for (int c = 0; c < components; ++c) {
    stress[c].assign(n, 0.0);
    dstress_dt[c].assign(n, 0.0);
  }
  plasticStrain.assign(n, 0.0);
  totalStrain.assign(n, 0.0);
  strainRate.assign(n, 0.0);
}

void ParticleSet::enableFracture() {
  fracture_ = true;
  crack.assign(size(), 0.0);
  dcrack_dt.assign(size(), 0.0);
}

void ParticleSet::enableBurn() {
  burn_ = true;
  lightingTime.assign(size(), -std::numeric_limits<double>::infinity());
  burnFraction.assign(size(), 1.0);
}

void ParticleSet::enableViscositySwitch(double initial) {
  viscositySwitch_ = true;
  alpha.assign(size(), initial);
  dalpha_dt.assign(size(), 0.0);
}

void ParticleSet::append(const std::array<double, 3>& pos, const std::array<double, 3>& vel,
                         double m, double density, double specificEnergy,
                         double smoothingLength, int mat) {
  const std::size_t i = size();
  resize(i + 1);
  for (int d = 0; d < 3; ++d) { x[d][i] = pos[d]; v[d][i] = vel[d]; }
  mass[i] = m;
  rho[i] = density;
  u[i] = specificEnergy;
  h[i] = smoothingLength;
  material[i] = mat;
  id[i] = static_cast<std::int64_t>(i);
  numReal = size();
}

void ParticleSet::clearGhosts() {
  forEachArray(*this, [this](auto& arr) { arr.resize(numReal); });
  ghostSource.clear();
}

void ParticleSet::permute(const std::vector<std::size_t>& order) {
  clearGhosts();
  forEachArray(*this, [&order](auto& arr) { permuteArray(arr, order); });
}

}  // namespace ejecta
