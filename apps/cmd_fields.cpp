// `ejecta fields SNAPSHOT.h5`: the snapshot's particles as sparse VDB grids, after the fact.
#include <cstdio>

#include "apps/commands.hpp"
#include "core/units.hpp"
#include "fields/crater_setup.hpp"
#include "fields/grid_set.hpp"
#include "fields/vdb_grids.hpp"
#include "sim/io/snapshot.hpp"
#include "sim/io/snapshot_checks.hpp"
#include "sim/run/run.hpp"

namespace ejecta::app {

namespace {

FieldNormalisation parseNormalisation(const std::string& text) {
  if (text == "auto") return FieldNormalisation::Auto;
  if (text == "shepard") return FieldNormalisation::Shepard;
  if (text == "none") return FieldNormalisation::None;
  throw std::runtime_error("--normalise: unknown value '" + text + "' (auto, shepard, none)");
}

}  // namespace

int fieldsCommand(const FieldsArgs& args) {
  SnapshotInfo info;
  const ParticleSet particles = readSnapshot(args.snapshot, info);
  const Scene scene = storedScene(info, args.snapshot);
  checkSnapshotMaterials(particles, scene.materials.size(), args.snapshot);
  fields::GridRequest request = fields::GridRequest::fromScene(scene.fields);
  if (!args.grids.empty()) request.grids = args.grids;
  if (!args.voxel.empty()) request.voxel = parseQuantity(args.voxel, Dimension::Length);
  if (!args.normalise.empty()) request.normalise = parseNormalisation(args.normalise);
  if (request.voxel < 0.0) throw std::runtime_error("--voxel: must be positive");

  const fields::ParticleContext ctx = fields::ParticleContext::fromScene(scene);
  const fields::GridSet set = fields::buildGridSet(particles, ctx, request);
  fields::GridFileMeta meta;
  meta.scene = scene.name;
  meta.time = info.time;
  meta.step = info.step;
  meta.levelSet = !args.noLevelSet;
  meta.crater = fields::craterSetupFromScene(scene);
  const std::string out = args.out.empty() ? "fields.vdb" : args.out;
  fields::writeGridFile(out, set, meta);
  std::printf("ejecta fields: %s (t = %.6g s, %zu particles) -> %s: %zu grids, voxel %.4g m, "
              "%zu active voxels per grid\n",
              args.snapshot.c_str(), info.time, particles.numReal, out.c_str(),
              set.grids.size() + (meta.levelSet ? 1 : 0), set.lattice.voxel(),
              [&] {
                std::size_t n = 0;
                for (std::size_t b = 0; b < set.lattice.blockCount(); ++b) {
                  const float* w = set.lattice.data(b, 0);
                  for (int v = 0; v < set.lattice.blockVolume(); ++v) n += w[v] > 0.0f;
                }
                return n;
              }());
  return 0;
}

}  // namespace ejecta::app
