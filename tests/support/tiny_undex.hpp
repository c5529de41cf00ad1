#pragma once
// A small underwater explosion shared by tests: a 1 kg TNT sphere (the undex_rz charge, radius
// 5.27 cm at 1630 kg/m^3) in a 0.3 m quarter of water, RZ, 5 mm spacing, to 0.1 ms. The caller
// adds its gauges (TOML [[gauges]] tables).
#include <string>

namespace ejecta::test {

inline std::string tinyUndexRzScene(const std::string& gauges) {
  return R"(
[scene]
name = "tiny_undex"
dimension = "rz"
[domain]
x = { min = 0.0, max = 0.3 }
y = { min = 0.0, max = 0.3, lower = "wall", upper = "open" }
[time]
t_end = "0.1 ms"
[[materials]]
name = "water"
eos = "mie_gruneisen"
library = "water"
[[materials]]
name = "tnt"
eos = "jwl"
library = "TNT"
[[bodies]]
name = "charge"
material = "tnt"
shape = "sphere"
center = [0.0, 0.0]
radius = "5.27 cm"
spacing = "5 mm"
density = "1630 kg/m^3"
[[bodies]]
name = "water"
material = "water"
shape = "box"
min = [0.0, 0.0]
max = [0.3, 0.3]
spacing = "5 mm"
density = "1000 kg/m^3"
pressure = "101325 Pa"
[[detonations]]
name = "centre"
material = "tnt"
point = [0.0, 0.0]
)" + gauges;
}

}  // namespace ejecta::test
