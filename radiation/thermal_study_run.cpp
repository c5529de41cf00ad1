// The chain a thermal study drives (docs/thermal.md): flux along the pass, the steady face
// temperature of eq. 4.8, the transient wall and the shield sizing. The study file is read by
// thermal_study_reader.cpp, the outputs written by thermal_study_report.cpp.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "core/join.hpp"
#include "radiation/radiative_balance.hpp"
#include "radiation/thermal_study.hpp"
#include "radiation/wall_implicit.hpp"

namespace ejecta::radiation {

namespace {

double seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

// The wall that applies to a patch: the first naming it, else the first with no patch list.
const WallSpec* wallFor(const ThermalStudy& s, const std::string& patch) {
  for (const WallSpec& w : s.walls)
    if (std::find(w.patches.begin(), w.patches.end(), patch) != w.patches.end()) return &w;
  for (const WallSpec& w : s.walls)
    if (w.patches.empty()) return &w;
  return nullptr;
}

FaceCondition coldFace(const WallSpec& w) {
  return w.coldEmissivity > 0.0 ? FaceCondition::radiating(w.coldEmissivity) : FaceCondition::insulated();
}

}  // namespace

ThermalResult runThermalStudy(const ThermalStudy& study, const Emitters& emitters) {
  return runThermalStudy(study, emitters, nullptr);
}

ThermalResult runThermalStudy(const ThermalStudy& study, const Emitters& emitters,
                              const TriangleMesh* occluder) {
  const std::vector<PassFrame> frames(study.approach.times().size(), PassFrame{&emitters, occluder});
  return runThermalStudy(study, frames);
}

ThermalResult runThermalStudy(const ThermalStudy& study, const std::vector<PassFrame>& frames) {
  ThermalResult r;
  r.name = study.name;
  r.source = study.source;
  r.times = study.approach.times();
  if (frames.size() != r.times.size())
    throw ThermalStudyError(study.source + ": " + std::to_string(frames.size()) +
                            " frames of hot material for " + std::to_string(r.times.size()) +
                            " sample times of the approach");
  for (const PassFrame& f : frames) {
    if (!f.emitters) throw ThermalStudyError(study.source + ": a frame of the pass has no emitters");
    const bool occluded = f.occluder && !f.occluder->triangles.empty();
    if (occluded && (&f == &frames.front() || f.occluder != (&f - 1)->occluder))
      validateMesh(*f.occluder, study.source + ": occluder");
    r.occluderTriangles = std::max(r.occluderTriangles, occluded ? f.occluder->triangleCount() : 0);
    if (f.emitters->size() >= r.emitterCount) {
      r.emitterCount = f.emitters->size();
      r.groupNames = f.emitters->groupNames;
    }
  }
  const bool occluded = r.occluderTriangles > 0;

  // The spacecraft's patches, in the body frame placed at t = 0 (to read names and areas).
  GeometryConfig craft;
  craft.source = study.source;
  craft.spacecraft = study.spacecraft;
  TriangleMesh mesh0;
  try {
    mesh0 = buildRadiationScene(craft, 0.0).surfaces;
  } catch (const GeometryFileError& e) {
    throw ThermalStudyError(e.what());
  }
  for (std::size_t p = 0; p < mesh0.patchCount(); ++p) {
    PatchThermal pt;
    pt.patch = mesh0.patchNames[p];
    pt.area = mesh0.patchArea(p);
    r.patches.push_back(std::move(pt));
  }
  auto checkPatches = [&](const std::vector<std::string>& names, const std::string& where) {
    for (const std::string& n : names)
      if (mesh0.findPatch(n) < 0)
        throw ThermalStudyError(study.source + ": " + where + ": the spacecraft has no patch '" + n +
                                "'; its patches: " + joinList(mesh0.patchNames));
  };
  for (const WallSpec& w : study.walls)
    checkPatches(w.patches, "line " + std::to_string(w.line) + ", walls");
  checkPatches(study.sizing.patches, "sizing.patches");

  // 1. Flux along the pass: the spacecraft moves, the hot material is the frame's.
  auto t0 = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < r.times.size(); ++i) {
    const double t = r.times[i];
    const Emitters& emitters = *frames[i].emitters;
    const TriangleMesh* occluder = frames[i].occluder;
    RadiationScene scene;
    scene.surfaces = buildRadiationScene(craft, t).surfaces;
    scene.emitters = emitters;
    if (occluder && !occluder->triangles.empty() && !emitters.empty())
      scene.occluder.mesh = *occluder;  // opaque, cold (T = 0)
    const ViewFactorSolver solver(std::move(scene));
    for (std::size_t p = 0; p < r.patches.size(); ++p) {
      PatchThermal& pt = r.patches[p];
      if (emitters.empty()) {
        pt.flux.push_back({});
        pt.seedFlux.push_back(0.0);
        if (occluded) pt.toOccluder.push_back({});
        continue;
      }
      const ReceiverResult rr = solver.fromPatch(p, study.sampling);
      r.rays += rr.rays;
      pt.flux.push_back(rr.flux);
      if (occluded) pt.toOccluder.push_back(rr.toOccluder);  // zero in a frame without one
      pt.seedFlux.push_back(seedBaseline(emitters, solver.scene().surfaces, p, study.baseline).flux);
    }
  }
  r.raySeconds = seconds(t0);

  // 2. Peaks and the steady face temperature (eq. 4.8).
  for (PatchThermal& pt : r.patches) {
    for (std::size_t i = 0; i < pt.flux.size(); ++i) {
      if (i == 0 || pt.flux[i].value > pt.peakFlux) {
        pt.peakFlux = pt.flux[i].value;
        pt.peakFluxError = pt.flux[i].standardError;
        pt.peakTime = r.times[i];
        if (!pt.toOccluder.empty()) pt.peakOccluderFactor = pt.toOccluder[i].value;
      }
      pt.peakSeedFlux = std::max(pt.peakSeedFlux, pt.seedFlux[i]);
    }
    const WallSpec* w = wallFor(study, pt.patch);
    // Without a wall, a black face (alpha = eps = 1) stands for the face's own optics.
    pt.absorptivity = 1.0;
    pt.emissivity = 1.0;
    if (w) {
      const WallMaterial& outer = w->layers.front().material;
      pt.absorptivity = w->absorptivity.value_or(outer.absorptivity);
      pt.emissivity = w->emissivity.value_or(outer.emissivity);
    }
    pt.steadyTemperature = pt.emissivity > 0.0
                               ? equilibriumTemperature(pt.peakFlux, pt.absorptivity, pt.emissivity)
                               : std::numeric_limits<double>::infinity();
    pt.seedSteadyTemperature = equilibriumTemperature(pt.peakSeedFlux, kSeedAluminiumAbsorptivity,
                                                      kSeedAluminiumEmissivity);
  }

  // 3. The transient wall of every patch that has one, through its flux history.
  const double dt = study.timeStep > 0.0 ? study.timeStep : study.approach.duration / 2000.0;
  t0 = std::chrono::steady_clock::now();
  for (PatchThermal& pt : r.patches) {
    const WallSpec* w = wallFor(study, pt.patch);
    if (!w) continue;
    std::vector<double> q;
    for (const Estimate& e : pt.flux) q.push_back(e.value);
    WallGrid grid{LayeredWall(w->layers)};
    WallBoundaries bc;
    bc.hot = FaceCondition::irradiated(uniformFlux(FluxSeries(r.times, q)), pt.absorptivity, pt.emissivity);
    bc.cold = coldFace(*w);
    CrankNicolsonWallSolver solver(grid, bc, study.initialTemperature);
    WallHistory history(grid);
    solver.run(study.approach.duration, dt, &history);
    for (std::size_t l = 0; l < grid.wall().layerCount(); ++l) {
      pt.layerPeak.push_back(history.peakTemperature(l));
      pt.layerMeltTime.push_back(history.meltTime(l));
    }
    pt.structureLimit = study.limit.temperatureFor(w->layers.back().material);
    pt.structureWithinLimit = pt.layerPeak.back() < pt.structureLimit;
    pt.wall.emplace(std::move(history));
  }
  r.wallSeconds = seconds(t0);

  // 4. Sizing: each candidate coating on the structural (last) layer, per patch.
  t0 = std::chrono::steady_clock::now();
  if (!study.sizing.coatings.empty()) {
    std::vector<WallMaterial> candidates;
    for (const std::string& c : study.sizing.coatings) candidates.push_back(wallMaterial(c));
    for (const std::string& c : study.sizing.coatings) r.totalAddedMass[wallMaterial(c).name] = 0.0;
    for (PatchThermal& pt : r.patches) {
      const WallSpec* w = wallFor(study, pt.patch);
      const auto& only = study.sizing.patches;
      if (!w || (!only.empty() && std::find(only.begin(), only.end(), pt.patch) == only.end())) continue;
      std::vector<double> q;
      for (const Estimate& e : pt.flux) q.push_back(e.value);
      ShieldSizingProblem p;
      p.structure = w->layers.back();
      p.hotFace = FaceCondition::irradiated(uniformFlux(FluxSeries(r.times, q)), 1.0, 0.0);
      p.useCoatingOptics = true;
      p.coldFace = coldFace(*w);
      p.initialTemperature = study.initialTemperature;
      p.duration = study.approach.duration;
      p.timeStep = dt;
      p.limit = study.limit;
      p.patchArea = pt.area;
      p.maxThickness = study.sizing.maxThickness;
      p.tolerance = study.sizing.tolerance;
      p.coatingCells = study.sizing.coatingCells;
      pt.sizing = sizeShield(p, candidates);
      for (const ShieldSizing& z : pt.sizing)
        r.totalAddedMass[z.material] += z.feasible ? z.addedMass : std::numeric_limits<double>::quiet_NaN();
    }
  }
  r.sizingSeconds = seconds(t0);
  return r;
}

}  // namespace ejecta::radiation
