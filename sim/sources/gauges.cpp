#include "sim/sources/gauges.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "sim/sph/kernel.hpp"

namespace ejecta {

namespace {

template <template <int> class K, int D>
GaugeReading readGauge(const std::array<double, 3>& at, const ParticleSet& p, bool rz) {
  double sumW = 0.0, P = 0.0, rho = 0.0;
  std::array<double, 3> v{};
  for (std::size_t j = 0; j < p.numReal; ++j) {
    double r2 = 0.0;
    for (int d = 0; d < D; ++d) r2 += (p.x[d][j] - at[d]) * (p.x[d][j] - at[d]);
    const double h = p.h[j];
    if (r2 >= kKernelSupport * kKernelSupport * h * h) continue;
    double w, dw;
    K<D>::shape(std::sqrt(r2) / h, w, dw);
    double volume = p.mass[j] / p.rho[j];
    if (rz) volume /= 2.0 * std::numbers::pi * std::max(p.x[0][j], 1e-300);
    const double weight = volume * w / hPowerD<D>(h);
    sumW += weight;
    P += weight * p.P[j];
    rho += weight * p.rho[j];
    for (int d = 0; d < 3; ++d) v[d] += weight * p.v[d][j];
  }
  if (!(sumW > 0.0)) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {nan, nan, {nan, nan, nan}};
  }
  for (double& c : v) c /= sumW;
  return {P / sumW, rho / sumW, v};
}

}  // namespace

std::vector<GaugeReading> readGauges(const GaugeLayout& layout, const ParticleSet& p) {
  std::vector<GaugeReading> out;
  const int dim = spatialDimension(layout.geometry);
  const bool rz = layout.geometry == Geometry::Axisymmetric;
  for (const GaugeSpec& g : layout.gauges)
    out.push_back(withKernel(layout.kernel, [&]<template <int> class K>() {
      if (dim == 1) return readGauge<K, 1>(g.position, p, false);
      if (dim == 2) return readGauge<K, 2>(g.position, p, rz);
      return readGauge<K, 3>(g.position, p, false);
    }));
  return out;
}

std::string gaugeHeader(const GaugeLayout& layout) {
  const int dim = spatialDimension(layout.geometry);
  std::string h = "step,time_s";
  for (const GaugeSpec& g : layout.gauges) {
    h += "," + g.name + "_pressure_Pa," + g.name + "_density_kg_m3";
    for (int d = 0; d < dim; ++d) h += "," + g.name + "_velocity_" + "xyz"[d] + "_m_s";
  }
  return h;
}

std::string gaugeRow(const GaugeLayout& layout, const std::vector<GaugeReading>& readings) {
  const int dim = spatialDimension(layout.geometry);
  std::ostringstream s;
  s.precision(10);
  for (const GaugeReading& r : readings) {
    s << ',' << r.pressure << ',' << r.density;
    for (int d = 0; d < dim; ++d) s << ',' << r.velocity[d];
  }
  return s.str();
}

}  // namespace ejecta
