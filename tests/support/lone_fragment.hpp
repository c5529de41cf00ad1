#pragma once
// A lone fragment reaching a body, shared by tests/sim/run/test_closing_speed.cpp and
// tests/parallel/test_mpi_runs.cpp: a 40 x 40 block of rubble granite (1 cm spacing, at rest,
// zero pressure, no tension), 2D planar, continuity density and the interface form; one particle
// leaving its face at 3 km/s (from x = 0.405 m); with `secondBlock`, a 20 x 20 block from
// x = 0.60 m that the particle reaches at ~59 us. `sph` and `time` are lines added to [sph] and
// [time] (t_end among them); no snapshots.
#include <string>

namespace ejecta::test {

inline std::string loneFragmentScene(const std::string& sph, const std::string& time,
                                     bool secondBlock) {
  const std::string block = R"(
material = "granite"
shape = "box"
spacing = "1 cm"
density = "2680 kg/m^3"
pressure = 0.0
)";
  std::string toml = R"(
[scene]
name = "lone_fragment"
dimension = "2d"
[sph]
form = "interface"
density = "continuity"
)" + sph + R"(
[time]
)" + time + R"(
[output]
snapshots = false
[[materials]]
name = "granite"
eos = "tillotson"
library = "granite"
parameters = { minimum_pressure = 0.0 }
[[bodies]]
name = "block"
min = [0.0, 0.0]
max = ["0.4 m", "0.4 m"]
)" + block + R"(
[[bodies]]
name = "fragment"
min = ["0.40 m", "0.19 m"]
max = ["0.41 m", "0.20 m"]
velocity = ["3 km/s", 0.0]
)" + block;
  if (secondBlock)
    toml += R"(
[[bodies]]
name = "second_block"
min = ["0.60 m", "0.10 m"]
max = ["0.80 m", "0.30 m"]
)" + block;
  return toml;
}

}  // namespace ejecta::test
