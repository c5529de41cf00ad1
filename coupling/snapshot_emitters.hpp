#pragma once
// Snapshot particles -> radiation emitters (radiation/emitters.hpp), the glue between sim/ and
// radiation/ (which must not depend on sim/). docs/thermal.md.
//
// Each hot particle becomes an opaque sphere of its own volume, V = m / rho, radius
// (3 V / 4 pi)^(1/3). A 3D run maps x, y, z directly. An RZ run (x[0] = r, x[1] = z, each particle
// a ring about the z axis) is revolved about the world y axis, which is the run's z axis: the ring
// at (r, z) becomes N copies at (r cos phi_k, z, r sin phi_k), phi_k = 2 pi (k + 1/2) / N, each
// with V / N of the ring's volume (m is the whole ring's mass in RZ). N is chosen so that the
// copies lie about one smoothing length apart around the ring, N = ceil(2 pi r / h), at least 1
// and at most `maxRingCopies`: the ring is then sampled as finely as the run resolves the
// meridian plane (h ~ 1.2-2 particle spacings), and a copy's sphere (diameter about 1.2 h^(1/3)
// d^(2/3) for meridian spacing d) overlaps its neighbours. 1D and planar 2D runs have no 3D
// extent and are refused.
#include <cstddef>
#include <string>
#include <vector>

#include "radiation/emitters.hpp"
#include "sim/state/geometry.hpp"
#include "sim/state/particles.hpp"

namespace ejecta::coupling {

struct SnapshotEmitterOptions {
  double minTemperature = radiation::kMoltenRockThreshold;  // [K]
  std::vector<double> emissivityByMaterial;   // per material index
  double defaultEmissivity = radiation::kGraniteEmissivity;
  std::vector<std::string> materialNames;     // per material index (the emitter groups)
  int maxRingCopies = 4096;                   // RZ: copies per ring at most
};

struct SnapshotEmitterStats {
  std::size_t particles = 0;     // real particles in the snapshot
  std::size_t hot = 0;           // of them at or above the threshold
  std::size_t emitters = 0;      // spheres made (RZ: every ring's copies)
  int maxCopies = 0;             // RZ: the most copies one ring got
};

// Copies of an RZ ring of radius r [m] and smoothing length h [m]: ceil(2 pi r / h) in
// [1, maxCopies].
int ringCopies(double r, double h, int maxCopies);

// The emitters of the real particles of `p`. Throws std::invalid_argument for a 1D or planar
// run, or (from selectEmitters) a bad particle value.
radiation::Emitters emittersFromParticles(const ParticleSet& p, Geometry geometry,
                                          const SnapshotEmitterOptions& options,
                                          SnapshotEmitterStats* stats = nullptr);

// A run directory's last snapshot (snapshots/snap_NNNN.h5), or the path itself when it is a file.
std::string resolveSnapshotPath(const std::string& runDirOrSnapshot);

}  // namespace ejecta::coupling
