#pragma once
// A small periodic 2D blast shared by tests: a strong shock, every particle moving, nothing
// touching a wall (1,600 particles, 0.02 s). `sphTables` is TOML inserted after [domain], e.g.
// "[sph.viscosity]\nswitch = \"morris_monaghan\"\n".
#include <string>

namespace ejecta::test {

inline std::string periodicBlastScene(const std::string& sphTables = "") {
  return R"(
[scene]
name = "test_blast"
dimension = "2d"
[domain]
x = { min = -0.5, max = 0.5, boundary = "periodic" }
y = { min = -0.5, max = 0.5, boundary = "periodic" }
)" + sphTables + R"(
[time]
t_end = 0.02
[output]
snapshot_interval = 0.005
[[materials]]
name = "gas"
eos = "ideal_gas"
gamma = 1.4
[[bodies]]
name = "box"
material = "gas"
shape = "box"
min = [-0.5, -0.5]
max = [0.5, 0.5]
spacing = 0.025
density = 1.0
pressure = 1e-4
[[energy_deposits]]
name = "blast"
energy = 0.1
center = [0.0, 0.0]
radius = 0.06
)";
}

}  // namespace ejecta::test
