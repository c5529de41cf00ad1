#pragma once
// The in-situ radiation chain's result at the end of a run (coupling/run_thermal.hpp), typed: what
// summary.json's "thermal_*" entries hold (docs/output_format.md) and what `ejecta run` prints.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "sim/run/summary.hpp"

namespace ejecta::coupling {

struct ThermalSummary {
  struct Face {
    std::string name;
    double peakFlux = 0.0;                 // [W/m^2]
    double steadyTemperature = 0.0;        // eq. 4.8 at the peak flux [K]
    std::optional<double> structurePeak;   // the wall's innermost layer [K]; faces with a wall
  };
  struct Shield {
    std::string coating;
    double thicknessMm = 0.0;  // the thickest any face needs [mm]
    double mass = 0.0;         // over all faces [kg]
  };
  // The governing pass: the one with the hottest steady face.
  struct Pass {
    double time = 0.0;  // the material's time (snapshot), or the pass's start (evolving) [s]
    bool evolving = false;
    std::string dir;    // its files
    std::int64_t hotParticles = 0, emitters = 0, occluderTriangles = 0;
    std::vector<Face> faces;
    std::vector<Shield> shields;
    std::string recommendation;  // the thinnest sufficient coating, or why none
  };
  std::int64_t passes = 0;        // passes that finished
  std::optional<Pass> governing;  // none when no pass finished
  std::string note;               // failures, "; "-separated; empty: none
};

// Writes the result into the summary's extras: the one place its summary.json keys are named.
void addToSummary(const ThermalSummary& thermal, RunSummary& summary);

}  // namespace ejecta::coupling
