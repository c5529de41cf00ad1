#pragma once
// HDF5 particle snapshots: the science output of a run and, through the /restart group, the
// state needed to resume it bit for bit. The layout is documented in docs/output_format.md.
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "sim/parallel/communicator.hpp"
#include "sim/state/geometry.hpp"
#include "sim/state/particles.hpp"

namespace ejecta {

// Written as the root attribute `ejecta_version` (and into run summaries).
inline constexpr std::string_view kEjectaVersion = "0.1.0";

// One entry of the run's material table, as /materials stores it: what a particle's `material`
// id means to a reader that does not have the scene (ParaView's legend, Python).
struct SnapshotMaterial {
  std::string name;      // the scene's [[materials]] name
  std::string eos;       // equation of state, with its library entry: "tillotson (granite)"
  std::string strength;  // strength model, or "none" (a fluid)
  std::string fracture;  // fracture model, or "none"
  bool operator==(const SnapshotMaterial&) const = default;
};

// Run-level state stored alongside the particles. Everything here is written; on reading every
// field is restored exactly.
struct SnapshotInfo {
  double time = 0.0;             // simulation time [s]                  (root `time`)
  long step = 0;                 // steps taken so far                    (root `step`)
  Geometry geometry = Geometry::Spatial;  //                              (root `geometry`)
  std::string scene;             // scene name                            (root `scene`)

  // --- Restart state (attributes of /restart) ---
  double dtNext = 0.0;           // time step the integrator would take next [s]
  long snapshotIndex = 0;        // index of this snapshot in the output series
  double nextOutputTime = 0.0;   // time at which the next snapshot is due [s]
  double initialEnergy = 0.0;    // total energy at t = 0 [J], for conservation diagnostics
  std::array<double, 3> initialMomentum{};  // total momentum at t = 0 [kg m/s]
  // Kinetic and internal energy of each material at t = 0 [J] (the energy ledger's reference);
  // empty in snapshots written before the ledger existed.
  std::vector<double> initialMaterialKinetic, initialMaterialInternal;
  double wallSeconds = 0.0;      // wall-clock time spent on the run so far [s]
  // The material table by id (group /materials); empty in snapshots written before it existed.
  std::vector<SnapshotMaterial> materials;
  // Full text of the scene file the run was started from, so a resumed run does not depend on
  // the file being unchanged on disk. May be empty. Stored as dataset /restart/scene_source.
  std::string sceneSource;
};

// Writes the real particles [0, p.numReal) and `info` to `path`, atomically (temporary file in
// the same directory, then rename): on any failure the earlier file at `path` is intact.
// Position components beyond the geometry's dimension are written as 0 (1D: (x,0,0); 2D and
// RZ: (x,y,0)). Throws std::runtime_error naming the file on failure.
void writeSnapshot(const std::string& path, const ParticleSet& p, const SnapshotInfo& info);
// A distributed run's snapshot (a collective): every rank's real particles in one file of the
// same layout, written by the ranks in turn so that none holds another's particles. Rows are in
// rank order, each rank's in its own order (a particle is followed by its `id`, as on one rank,
// whose rows are in its locality order). Atomic as above: a failure on any rank throws the same
// error on every rank and leaves the earlier file intact.
void writeSnapshot(const std::string& path, const ParticleSet& p, const SnapshotInfo& info,
                   const Communicator& ranks);

// Reads a snapshot written by writeSnapshot. Every stored array is restored bit for bit;
// numReal = N and there are no ghosts; omega is 1 and divv, curlv, areaDensity are 0 (they are
// recomputed by the density pass). Optional arrays (stress, crack, burn, viscosity alpha) are
// restored when the file has them. Throws std::runtime_error naming the file and the missing
// or malformed dataset/attribute.
ParticleSet readSnapshot(const std::string& path, SnapshotInfo& info);
// Slice `part` of `parts` near-equal slices of the stored particles (rows in file order): what
// each rank of a distributed restart reads, so that no rank holds them all.
ParticleSet readSnapshot(const std::string& path, SnapshotInfo& info, int part, int parts);
// What the reader does with the particle values it reads: Checked (the default) refuses a file
// that fails sim/io/snapshot_checks.hpp (NaN, non-positive density, ...); AsStored returns them
// as written: for looking at the last snapshot of a failed run, which holds the offending state,
// never for resuming or post-processing one. The run-level info is checked either way.
enum class SnapshotValues { Checked, AsStored };
ParticleSet readSnapshot(const std::string& path, SnapshotInfo& info, SnapshotValues values);
// The snapshot's info (time, step, stored scene...) without its particles.
SnapshotInfo readSnapshotInfo(const std::string& path);

// What a snapshot file holds for its XDMF grid: the names of its /particles datasets and whether
// it has the /xdmf/vertices connectivity (files written before either was added lack some).
struct SnapshotLayout {
  std::vector<std::string> particleDatasets;
  bool xdmfVertices = false;
};
SnapshotLayout readSnapshotLayout(const std::string& path);

}  // namespace ejecta
