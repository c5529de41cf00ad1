#pragma once
// Gauges: fixed points where a run records pressure, density and velocity every step
// (gauges.csv), as pressure transducers in an experiment (the seed's UNDEX gauges, Sec. 3.2.2).
// The value at a point is the Shepard-normalised SPH interpolant sum_j V_j f_j W_j / sum_j V_j W_j
// over the particles whose support reaches it (RZ: ring volumes over 2 pi r, the 2D measure).
#include <array>
#include <string>
#include <vector>

#include "sim/state/particles.hpp"
#include "sim/sources/source_specs.hpp"
#include "sim/sph/sph_options.hpp"
#include "sim/state/geometry.hpp"

namespace ejecta {

struct GaugeReading {
  double pressure;             // [Pa]; NaN where no particle's support reaches the gauge
  double density;              // [kg/m^3]
  std::array<double, 3> velocity;  // [m/s]
};

// Where a run's gauges are, and how its fields are interpolated there.
struct GaugeLayout {
  const std::vector<GaugeSpec>& gauges;
  Geometry geometry;
  KernelKind kernel;
};

// One reading per gauge, in the layout's order.
std::vector<GaugeReading> readGauges(const GaugeLayout& layout, const ParticleSet& p);

// The CSV header of gauges.csv: step,time_s, then <name>_pressure_Pa, <name>_density_kg_m3,
// <name>_velocity_<axis>_m_s (as many axes as the geometry has) per gauge.
std::string gaugeHeader(const GaugeLayout& layout);
// One CSV row (without step and time) of readings.
std::string gaugeRow(const GaugeLayout& layout, const std::vector<GaugeReading>& readings);

}  // namespace ejecta
