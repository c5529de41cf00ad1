#pragma once
// A small impact scene shared by tests: a 0.1 m aluminium ball at 3 km/s on a 2 x 0.6 m granite
// block (RZ: a 1 m radius cylinder), 0.02 m spacing, about 1,500 particles in RZ.
#include <string>

namespace ejecta::test {

struct TinyImpact {
  std::string dimension = "rz";             // "2d" or "rz"
  std::string tEnd = "60 us";
  std::string snapshotInterval = "30 us";
  std::string impactorMaterial = "aluminium";
  std::string extra;                        // more TOML tables ([fields], [crater], ...)
};

inline std::string tinyImpactScene(const TinyImpact& o = {}) {
  const bool planar = o.dimension == "2d";
  return R"(
[scene]
name = "tiny_impact"
dimension = ")" + o.dimension + R"("
[sph]
density = "continuity"
form = "interface"
[time]
t_end = ")" + o.tEnd + R"("
[output]
snapshot_interval = ")" + o.snapshotInterval + R"("
)" + o.extra + R"(
[[materials]]
name = "granite"
eos = "tillotson"
library = "granite"
[[materials]]
name = ")" + o.impactorMaterial + R"("
eos = "mie_gruneisen"
library = "Al-2024"
[[bodies]]
name = "impactor"
material = ")" + o.impactorMaterial + R"("
shape = "sphere"
center = [0.0, "0.12 m"]
radius = "0.1 m"
spacing = "0.02 m"
density = "2785 kg/m^3"
pressure = 0.0
velocity = [0.0, "-3 km/s"]
[[bodies]]
name = "target"
material = "granite"
shape = "box"
min = [)" + (planar ? std::string("\"-1 m\"") : std::string("0.0")) + R"(, "-0.6 m"]
max = ["1 m", 0.0]
spacing = "0.02 m"
density = "2680 kg/m^3"
pressure = 0.0
)";
}

}  // namespace ejecta::test
