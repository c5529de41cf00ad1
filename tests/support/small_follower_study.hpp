#pragma once
// A small thermal study shared by the chain tests: a 0.1 m box coming down the axis towards the
// crater of the tiny impact (tests/support/tiny_impact.hpp; its target's top at y = 0, the RZ
// axis being the world y axis), from 0.3 m to 0.15 m above it. The tiny impact at 3 km/s heats
// the crater floor to about 1e3 K, so the threshold is lowered to 500 K to have emitters; fixed
// ray counts keep it fast and deterministic.
namespace ejecta::test {

inline constexpr const char* kSmallFollowerStudy = R"(
[study]
name = "small_follower"
[spacecraft]
shape = "box"
size = [0.1, 0.1, 0.1]
[approach]
target = [0.0, 0.0, 0.0]
distance = "0.3 m"
direction = [0.0, 1.0, 0.0]
speed = "150 m/s"
duration = "1 ms"
samples = 3
[emitters]
min_temperature = 500.0
[[walls]]
layers = [{ material = "aluminium", thickness = "1 mm", cells = 10 }]
[sizing]
coatings = ["tungsten"]
patches = ["side0"]
[sampling]
rays = 65536
)";

}  // namespace ejecta::test
