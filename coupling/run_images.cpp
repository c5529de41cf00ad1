#include "coupling/run_images.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include "core/join.hpp"
#include "coupling/crater_charts.hpp"
#include "coupling/csv_header.hpp"
#include "coupling/category_images.hpp"
#include "coupling/grid_images.hpp"
#include "coupling/particle_images.hpp"
#include "fields/grid_slice.hpp"
#include "fields/run_outputs.hpp"
#include "render/charts.hpp"
#include "render/frame_names.hpp"
#include "sim/run/energy_ledger.hpp"
#include "sim/run/simulation.hpp"

namespace fs = std::filesystem;

namespace ejecta::coupling {

namespace {

// energy.png (totals), energy_partition.png (per material), coupling.png (target_share) and
// gauges.png (pressure at each gauge), from the run's CSVs.
std::vector<std::string> writeRunCharts(const fs::path& dir, const Scene& scene) {
  render::ChartRunner charts;
  std::vector<std::string> written;
  const fs::path energy = dir / "energy.csv";
  const std::vector<std::string> columns = csvHeader(energy);
  if (columns.empty()) return written;
  render::ChartSpec totals{.csv = energy, .x = "time_s",
                           .series = {{.y = "kinetic_J", .label = "kinetic"},
                                      {.y = "internal_J", .label = "internal"},
                                      {.y = "total_J", .label = "total"}},
                           .xlabel = "t [s]", .ylabel = "energy [J]",
                           .title = scene.name + ": energy", .out = dir / "energy.png"};
  charts.writeChart(totals);
  written.push_back("energy.png");
  if (scene.materials.size() > 1) {
    render::ChartSpec partition{.csv = energy, .x = "time_s", .xlabel = "t [s]",
                                .ylabel = "energy [J]",
                                .title = scene.name + ": energy by material",
                                .out = dir / "energy_partition.png"};
    for (const MaterialSpec& m : scene.materials) {
      const std::string key = ledgerKey(m.name);
      if (!hasColumn(columns, key + "_kinetic_J")) continue;
      partition.series.push_back({.y = key + "_kinetic_J", .label = m.name + " kinetic"});
      partition.series.push_back({.y = key + "_internal_J", .label = m.name + " internal"});
    }
    if (!partition.series.empty()) {
      charts.writeChart(partition);
      written.push_back("energy_partition.png");
    }
  }
  if (hasColumn(columns, "target_share")) {
    charts.writeChart({.csv = energy, .x = "time_s",
                       .series = {{.y = "target_share", .label = "target's share"}},
                       .xlabel = "t [s]",
                       .ylabel = scene.detonations.empty() && scene.deposits.empty()
                                     ? "share of the impactor's kinetic energy"
                                     : "share of the yield",
                       .title = scene.name + ": energy coupled into the target",
                       .out = dir / "coupling.png"});
    written.push_back("coupling.png");
  }
  if (!scene.gauges.empty() && fs::exists(dir / "gauges.csv")) {
    render::ChartSpec gauges{.csv = dir / "gauges.csv", .x = "time_s", .xlabel = "t [s]",
                             .ylabel = "pressure [Pa]", .title = scene.name + ": gauges",
                             .out = dir / "gauges.png"};
    for (const GaugeSpec& g : scene.gauges)
      gauges.series.push_back({.y = g.name + "_pressure_Pa", .label = g.name});
    charts.writeChart(gauges);
    written.push_back("gauges.png");
  }
  for (const std::string& c : writeCraterCharts(charts, dir, scene.name, scene.geometry)) written.push_back(c);
  return written;
}

bool listed(const std::vector<std::string>& list, const std::string& name) {
  return std::find(list.begin(), list.end(), name) != list.end();
}

// The pictures of one grid file: slices through z = 0 and the surface coloured by temperature.
// A picture that cannot be drawn (a grid with no active voxel yet, no surface) is reported and
// skipped: the run goes on.
void writeGridFrames(render::Renderer& renderer, const fs::path& dir, const ImageOutputOptions& im, long index) {
  const fs::path file = dir / "fields" / fields::fieldFileName(index);
  const int frame = static_cast<int>(index);
  auto attempt = [&](const fs::path& out, auto draw) {
    try {
      draw(out);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "ejecta: warning: %s not drawn: %s\n", out.c_str(), e.what());
    }
  };
  for (const std::string& grid : im.grids)
    attempt(render::framePath(dir, "grid_" + grid, frame), [&](const fs::path& out) {
      GridSliceImageOptions o;
      o.grid = grid;
      o.axis = 2;
      o.value = 0.0;
      o.log = listed(im.log, grid);
      writeGridSliceImage(renderer, file, o, out);
    });
  if (im.surface)
    attempt(render::framePath(dir, "surface", frame), [&](const fs::path& out) {
      IsoSurfaceImageOptions o;
      o.grid = "surface";
      const std::vector<std::string> names = fields::gridNames(file.string());
      if (listed(names, "temperature")) o.colorBy = "temperature";
      o.log = listed(im.log, "temperature");
      o.cut = im.cut;
      o.cutAt = im.cutAt;
      if (im.camera) o.camera = renderCamera(*im.camera);
      writeIsoSurfaceImage(renderer, file, o, out);
    });
}

}  // namespace

void addImageOutputs(RunOptions& options, const Scene& scene, bool charts) {
  if (options.outDir.empty()) return;
  const fs::path dir = options.outDir;
  if (scene.images.enabled) {
    const ImageOutputOptions im = scene.images;
    const Geometry geometry = scene.geometry;
    const std::string name = scene.name;
    // The fields hook runs before this one (cmd_run.cpp's configure adds it first), so at an
    // output its cadence selects, the grid file of that output is on disk.
    const bool gridFrames = scene.fields.enabled && (!im.grids.empty() || im.surface);
    // The categorical pictures: where each material is (more than one), and the failure status
    // (any strength or fracture).
    MaterialLegend legend;
    bool solids = false;
    for (const MaterialSpec& m : scene.materials) {
      legend.names.push_back(m.name);
      legend.strength.push_back(m.strength.present);
      solids = solids || m.strength.present || m.fracture.present;
    }
    const bool materialFrames = scene.materials.size() > 1;
    const int fieldsEvery = scene.fields.every;
    // One renderer (one GL context) for the whole run, made at the first frame.
    auto renderer = std::make_shared<std::unique_ptr<render::Renderer>>();
    auto previous = options.onOutput;
    options.onOutput = [=](const Simulation& sim, const SnapshotInfo& info, bool final) {
      if (previous) previous(sim, info, final);
      if (!final && info.snapshotIndex % im.every != 0) return;
      // Drawn by rank 0 from every rank's particles (gathered by all).
      const ParticleSet& all = sim.gatheredParticles();
      if (!sim.ranks().isRoot()) return;
      if (!*renderer) {
        fs::create_directories(dir / "images");
        *renderer = std::make_unique<render::Renderer>(
            render::RenderSettings{.width = im.size, .height = im.size});
      }
      for (const std::string& field : im.fields) {
        ParticleImageOptions o;
        o.field = field;
        o.log = std::find(im.log.begin(), im.log.end(), field) != im.log.end();
        o.cut = im.cut;
        o.cutAt = im.cutAt.value_or(0.0);
        if (im.camera) o.camera = renderCamera(*im.camera);
        writeParticleImage(**renderer, all, geometry, info.time, name, o,
                           render::framePath(dir, field, static_cast<int>(info.snapshotIndex)));
      }
      ParticleImageOptions view;
      view.cut = im.cut;
      view.cutAt = im.cutAt.value_or(0.0);
      if (im.camera) view.camera = renderCamera(*im.camera);
      const int frame = static_cast<int>(info.snapshotIndex);
      if (materialFrames)
        writeCategoryImage(**renderer, all, geometry, info.time, name + ": materials",
                           materialCategories(all, legend), view, render::framePath(dir, "materials", frame));
      if (solids)
        writeCategoryImage(**renderer, all, geometry, info.time, name + ": failure status",
                           failureCategories(all, legend), view, render::framePath(dir, "failure", frame));
      if (gridFrames && (final || info.snapshotIndex % fieldsEvery == 0))
        writeGridFrames(**renderer, dir, im, info.snapshotIndex);
    };
  }
  if (!charts) return;
  auto previous = options.onFinish;
  const Scene copy = scene;
  options.onFinish = [=](const Simulation& sim, RunSummary& summary) {
    if (previous) previous(sim, summary);
    if (!sim.ranks().isRoot()) return;
    render::ChartRunner probe;
    if (!probe.chartsAvailable()) {
      summary.extras.push_back({"charts_note", "no charts: " + probe.unavailableReason() +
                                                   " (the CSVs are written)"});
      return;
    }
    try {
      summary.extras.push_back({"charts", joinList(writeRunCharts(dir, copy))});
    } catch (const std::exception& e) {
      summary.extras.push_back({"charts_note", std::string("charts failed: ") + e.what()});
    }
  };
}

}  // namespace ejecta::coupling
