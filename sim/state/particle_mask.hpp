#pragma once
// A selection of the real particles: what a pass or a package hook acts on. With individual time
// steps (sim/run/time_bins.hpp) only the particles whose step ends now are evaluated; the others
// keep their rates, so a hook must not touch them. nullptr selects every real particle.
#include <cstddef>
#include <vector>

namespace ejecta {

using ParticleMask = std::vector<unsigned char>;  // one entry per real particle, 1 = selected

inline bool selected(const ParticleMask* mask, std::size_t i) { return !mask || (*mask)[i] != 0; }

}  // namespace ejecta
