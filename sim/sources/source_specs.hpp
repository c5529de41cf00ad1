#pragma once
// Sources and probes as a scene gives them: energy deposits, detonations, gauges.
#include <array>
#include <string>

namespace ejecta {

enum class DepositProfile { TopHat, Gaussian };

// Direct energy deposition (DED): energy added at `time` (default 0) to the particles of a region,
// or of one body (the device, as the seed's Sec. 3.1.1 models a yield as high-energy granite
// particles). A delayed deposit (time > 0) goes to the particles in its region at that moment.
struct EnergyDepositSpec {
  std::string name;
  double energy = 0.0;                      // [J]; in 2D planar per metre depth
  double time = 0.0;                        // [s]; > 0: fired at the first step start >= time
  int body = -1;                            // index into Scene::bodies; -1: every particle
  bool hasCenter = true;                    // false: a body deposit over the whole body
  std::array<double, 3> center{};
  double radius = 0.0;                      // TopHat: particles with |x - c| <= radius
  DepositProfile profile = DepositProfile::TopHat;
  double width = 0.0;                       // Gaussian: exp(-r^2/width^2)
  int line = 0;
};

// A detonation of a JWL explosive by programmed burn (docs/sources.md): each particle of the
// material is lit at t_L = time + (distance to the initiation point or line) / velocity, and its
// pressure is scaled by a burn fraction that rises from 0 to 1 as the front crosses it.
struct DetonationSpec {
  std::string name;
  int material = 0;                         // index into Scene::materials (a JWL explosive)
  std::array<double, 3> point{};            // initiation point, or the start of the line
  bool alongLine = false;                   // true: initiated along the segment point -> lineEnd
  std::array<double, 3> lineEnd{};
  double time = 0.0;                        // initiation time [s]
  double velocity = 0.0;                    // [m/s]; 0 = the explosive's C-J velocity
  int line = 0;                             // source line in the scene file
};

// A gauge: a fixed point whose pressure, density and velocity are written every step
// (gauges.csv; sim/sources/gauges.hpp).
struct GaugeSpec {
  std::string name;
  std::array<double, 3> position{};
  int line = 0;
};

}  // namespace ejecta
