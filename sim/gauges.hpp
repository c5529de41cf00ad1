#pragma once
// Gauges: fixed points where a run records pressure, density and velocity every step
// (gauges.csv), as pressure transducers in an experiment (the seed's UNDEX gauges, Sec. 3.2.2).
// The value at a point is the Shepard-normalised SPH interpolant sum_j V_j f_j W_j / sum_j V_j W_j
// over the particles whose support reaches it (RZ: ring volumes over 2 pi r, the 2D measure).
#include <array>
#include <string>
#include <vector>

#include "sim/particles.hpp"
#include "sim/scene.hpp"

namespace ejecta {

struct GaugeReading {
  double pressure;             // [Pa]; NaN where no particle's support reaches the gauge
  double density;              // [kg/m^3]
  std::array<double, 3> velocity;  // [m/s]
};

// One reading per scene gauge, in scene order.
std::vector<GaugeReading> readGauges(const Scene& scene, const ParticleSet& p);

// The CSV header of gauges.csv: step,time_s, then <name>_pressure_Pa, <name>_density_kg_m3,
// <name>_velocity_<axis>_m_s (as many axes as the geometry has) per gauge.
std::string gaugeHeader(const Scene& scene);
// One CSV row (without step and time) of readings.
std::string gaugeRow(const Scene& scene, const std::vector<GaugeReading>& readings);

}  // namespace ejecta
