#pragma once
// Radiative balance of a spacecraft face (the seed's eq. 4.8) and the incident-flux histories
// that drive the wall heat model.
//
// Eq. 4.8 balances absorbed and re-emitted flux at steady state:
//   alpha_r * q_incident = eps_r * sigma * T_r^4
// where the seed writes q_incident = Sum_i Omega_i eps_e sigma T_e,i^4 over the emitters a face
// sees. Here q_incident is an input: the view-factor code computes it (with the 1/pi and the
// cosines the seed's sum omits, docs/thermal_wall.md). The transient wall model uses the same
// balance out of equilibrium as its hot-face flux, netAbsorbedFlux below.
#include <filesystem>
#include <functional>
#include <vector>

#include "radiation/constants.hpp"

namespace ejecta::radiation {

// Incident radiative flux [W/m^2] at time t [s] and position y [m] along a face (y = 0 in 1D).
// The wall solvers call it from one thread; a caller that runs several solvers at once (shield
// sizing) must give a thread-safe function.
using SurfaceFlux = std::function<double(double t, double y)>;

// The seed's optical choices (sec. 4.5): polished aluminium receiver (its ref. [26]); its granite
// emitter is kGraniteEmissivity (radiation/constants.hpp). The wall materials table has sourced
// values; these reproduce the seed.
inline constexpr double kSeedAluminiumEmissivity = 0.02;
inline constexpr double kSeedAluminiumAbsorptivity = 0.08;

// alpha * q - eps * sigma * (T^4 - T_sink^4) [W/m^2]: what a face at temperature T keeps.
inline double netAbsorbedFlux(double incident, double absorptivity, double emissivity,
                              double temperature, double sinkTemperature = 0.0) {
  const double t2 = temperature * temperature, s2 = sinkTemperature * sinkTemperature;
  return absorptivity * incident - emissivity * kStefanBoltzmann * (t2 * t2 - s2 * s2);
}

// d(re-emitted flux)/dT = 4 eps sigma T^3 [W/(m^2 K)]: the radiative conductance used to
// linearise the T^4 term and in the explicit stability bound.
inline double radiativeConductance(double emissivity, double temperature) {
  return 4.0 * emissivity * kStefanBoltzmann * temperature * temperature * temperature;
}

// Steady face temperature of eq. 4.8 [K]: (alpha q / (eps sigma) + T_sink^4)^(1/4).
// Throws std::invalid_argument for a negative flux, alpha outside [0, 1] or eps outside (0, 1].
double equilibriumTemperature(double incidentFlux, double absorptivity, double emissivity,
                              double sinkTemperature = 0.0);

// The incident flux that holds a face at temperature T [W/m^2] (eq. 4.8 solved for q).
double incidentFluxForTemperature(double temperature, double absorptivity, double emissivity,
                                  double sinkTemperature = 0.0);

// Eq. 4.8 for every face at once: steady temperatures of faces with the given incident fluxes.
std::vector<double> equilibriumTemperatures(const std::vector<double>& incidentFlux,
                                            double absorptivity, double emissivity,
                                            double sinkTemperature = 0.0);

// A tabulated flux history q(t) [W/m^2]: linear between samples, held at the first and last
// values outside them. Times strictly increasing, fluxes finite (std::invalid_argument if not).
class FluxSeries {
 public:
  FluxSeries(std::vector<double> times, std::vector<double> fluxes);
  double operator()(double t) const;
  const std::vector<double>& times() const { return times_; }
  const std::vector<double>& fluxes() const { return fluxes_; }

 private:
  std::vector<double> times_;
  std::vector<double> fluxes_;
};

// Reads flux histories from a CSV file: a header line (column names, ignored beyond their
// count), then rows "t, q_0, q_1, ..." with t in seconds and one flux per patch in W/m^2.
// Returns one series per patch column. Blank lines and lines starting with '#' are skipped.
// Throws std::runtime_error naming the file, the line and the reason (unreadable file, wrong
// number of values, a value that is not a number, times not increasing, no data).
std::vector<FluxSeries> readFluxSeriesCsv(const std::filesystem::path& path);

// A flux along a 2D face from per-patch histories: patch p covers
// [patchEdges[p], patchEdges[p+1]) along the face (the last patch includes its end), so
// patchEdges has one entry more than `patches`; positions outside take the nearest patch.
SurfaceFlux patchFlux(std::vector<FluxSeries> patches, std::vector<double> patchEdges);

// A flux that is the same along the face: q(t).
SurfaceFlux uniformFlux(FluxSeries series);

}  // namespace ejecta::radiation
