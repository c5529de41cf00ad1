// `ejecta render SNAPSHOT.h5|FILE.vdb|RUN_DIR`: a PNG of the particles coloured by a field, or of
// a grid file: a slice of a grid, or an iso-surface (coupling/grid_images.hpp).
#include <algorithm>
#include <array>
#include <optional>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <regex>
#include <stdexcept>

#include "apps/commands.hpp"
#include "coupling/category_images.hpp"
#include "coupling/grid_images.hpp"
#include "coupling/particle_images.hpp"
#include "core/units.hpp"
#include "fields/grid_slice.hpp"
#include "sim/io/snapshot.hpp"
#include "sim/io/snapshot_checks.hpp"
#include "sim/run/run.hpp"

namespace fs = std::filesystem;

namespace ejecta::app {

using namespace ejecta::coupling;  // the in-situ chain (coupling/)

namespace {

// The file of a run directory's series `sub`/`prefix`NNNN`extension` with the highest index.
fs::path lastOfSeries(const fs::path& input, const std::string& sub, const std::string& prefix,
                      const std::string& extension) {
  const fs::path dir = input / sub;
  std::vector<fs::path> files;
  const std::regex pattern(prefix + R"((\d{4,}))" + extension);
  if (fs::is_directory(dir))
    for (const auto& e : fs::directory_iterator(dir))
      if (std::regex_match(e.path().filename().string(), pattern)) files.push_back(e.path());
  if (files.empty())
    throw std::runtime_error(input.string() + ": no " + sub + "/" + prefix + "NNNN" + extension);
  auto index = [&](const fs::path& f) { return std::stol(f.stem().string().substr(prefix.size())); };
  return *std::max_element(files.begin(), files.end(),
                           [&](const fs::path& a, const fs::path& b) { return index(a) < index(b); });
}

// A run directory's last snapshot, or the path itself.
fs::path snapshotOf(const fs::path& input) {
  if (!fs::is_directory(input)) return input;
  return lastOfSeries(input, "snapshots", "snap_", R"(\.h5)");
}

bool wantsGrids(const RenderArgs& a) {
  return !a.grid.empty() || !a.slice.empty() || !a.iso.empty() || !a.colorBy.empty();
}

// The dimension of a grid's stored units (docs/fields.md), for values given with units.
Dimension dimensionOfUnits(const std::string& units) {
  if (units.empty() || units == "1") return Dimension::None;
  for (const Dimension& d : {Dimension::Length, Dimension::Density, Dimension::Temperature, Dimension::Pressure,
                             Dimension::SpecificEnergy, Dimension::Velocity, Dimension::Time})
    if (siUnit(d) == units) return d;
  throw std::invalid_argument("grid units '" + units + "' are not known: give the value as a plain number");
}

// A plain number (SI, the grid's units) or "<number> <unit>" of the expected dimension.
double parseValue(const std::string& text, Dimension expected, const std::string& option) {
  double v = 0.0;
  const char* end = text.data() + text.size();
  const auto [p, ec] = std::from_chars(text.data(), end, v);
  if (ec == std::errc() && p == end) return v;
  try {
    return parseQuantity(text, expected);
  } catch (const std::exception& e) {
    throw std::invalid_argument(option + " '" + text + "': " + e.what());
  }
}

// "z", "z=2.5", "x=-1 m".
GridSliceImageOptions parseSlice(const std::string& text) {
  GridSliceImageOptions o;
  const std::string letter = text.substr(0, text.find('='));
  if (letter == "x") o.axis = 0;
  else if (letter == "y") o.axis = 1;
  else if (letter == "z") o.axis = 2;
  else throw std::invalid_argument("--slice '" + text + "': expected x, y or z, optionally =VALUE (\"z=2.5 m\")");
  if (text.size() > 1) {
    if (text[1] != '=' || text.size() == 2)
      throw std::invalid_argument("--slice '" + text + "': expected x, y or z, optionally =VALUE (\"z=2.5 m\")");
    o.value = parseValue(text.substr(2), Dimension::Length, "--slice");
  }
  return o;
}

// "x,y,z" (or "x,y" with n = 2): numbers, or quantities of `dimension` ("0, -60 m, 20 m").
std::array<double, 3> parseTriple(const std::string& text, Dimension dimension, const std::string& option,
                                  int n = 3) {
  std::array<double, 3> out{};
  std::size_t start = 0;
  for (int k = 0; k < n; ++k) {
    const std::size_t comma = text.find(',', start);
    if ((k < n - 1) != (comma != std::string::npos))
      throw std::invalid_argument(option + " '" + text + "': expected " +
                                  (n == 3 ? "three components X,Y,Z" : "two components X,Y"));
    std::string part = text.substr(start, k < n - 1 ? comma - start : std::string::npos);
    part.erase(0, part.find_first_not_of(' '));
    part.erase(part.find_last_not_of(' ') + 1);
    out[static_cast<std::size_t>(k)] = parseValue(part, dimension, option);
    start = comma + 1;
  }
  return out;
}

// --camera/--target/--up/--fov as a camera; none without --camera.
std::optional<render::Camera> cameraOf(const RenderArgs& args) {
  if (args.cameraPosition.empty()) {
    if (!args.cameraTarget.empty() || !args.cameraUp.empty())
      throw std::invalid_argument("--target and --up aim a camera: give its position with --camera X,Y,Z");
    return std::nullopt;
  }
  if (args.cameraTarget.empty())
    throw std::invalid_argument("--camera needs --target X,Y,Z: where the camera looks");
  ImageCamera c;
  c.position = parseTriple(args.cameraPosition, Dimension::Length, "--camera");
  c.target = parseTriple(args.cameraTarget, Dimension::Length, "--target");
  if (!args.cameraUp.empty()) c.up = parseTriple(args.cameraUp, Dimension::None, "--up");
  if (!(args.fovDegrees > 0.0 && args.fovDegrees < 180.0))
    throw std::invalid_argument("--fov " + std::to_string(args.fovDegrees) + ": expected 0 to 180 degrees");
  c.fovDegrees = args.fovDegrees;
  return renderCamera(c);
}

std::optional<double> cutAtOf(const RenderArgs& args) {
  if (args.cutAt.empty()) return std::nullopt;
  if (args.cut == "none") throw std::invalid_argument("--cut-at moves the cut, but --cut is none");
  return parseValue(args.cutAt, Dimension::Length, "--cut-at");
}

// " K", " kg/m^3"; nothing for a dimensionless grid ("1").
std::string unitsText(const std::string& units) { return units.empty() || units == "1" ? "" : " " + units; }

int renderGridFile(const RenderArgs& args, const fs::path& file) {
  if (!args.field.empty())
    throw std::invalid_argument("--field names a particle field; for a grid file name the grid with --grid");
  if (!args.view.empty() && args.view != "auto")
    throw std::invalid_argument("--view is for snapshots: a grid's slice is drawn in its plane, an iso-surface in 3D");
  if (!args.slice.empty() && !args.iso.empty()) throw std::invalid_argument("give --slice or --iso, not both");
  if (!args.iso.empty() && !args.grid.empty())
    throw std::invalid_argument("--iso names its own grid (--iso GRID=VALUE); --grid is for slices");
  if (!args.slice.empty() && !args.colorBy.empty())
    throw std::invalid_argument("--color-by colours an iso-surface; a slice is coloured by its own grid");
  if (args.size < 64 || args.size > 8192)
    throw std::invalid_argument("--size " + std::to_string(args.size) + ": expected 64 to 8192 pixels");
  const std::vector<std::string> names = fields::gridNames(file.string());
  const bool hasSurface = std::find(names.begin(), names.end(), "surface") != names.end();
  // No choice made: the material surface when the file has one (3D and RZ runs), else a slice.
  const bool iso = !args.iso.empty() || !args.colorBy.empty() || (args.slice.empty() && args.grid.empty() && hasSurface);
  if (!iso && (!args.cameraPosition.empty() || !args.cutAt.empty()))
    throw std::invalid_argument("--camera and --cut-at are for iso-surfaces and 3D particles; a slice is drawn in its plane");
  render::Renderer renderer({.width = args.size, .height = args.size});

  if (iso) {
    IsoSurfaceImageOptions o;
    const std::size_t eq = args.iso.find('=');
    if (!args.iso.empty()) o.grid = args.iso.substr(0, eq);
    if (o.grid.empty()) throw std::invalid_argument("--iso '" + args.iso + "': expected GRID or GRID=VALUE");
    if (eq != std::string::npos) {
      const fields::GridHeader h = fields::readGridHeader(file.string(), o.grid);
      o.isovalue = parseValue(args.iso.substr(eq + 1), dimensionOfUnits(h.units), "--iso");
    }
    o.colorBy = args.colorBy;
    o.log = args.log;
    if (!args.cut.empty()) o.cut = args.cut;
    o.cutAt = cutAtOf(args);
    o.camera = cameraOf(args);
    const fs::path out = args.out.empty() ? fs::path("iso_" + o.grid + ".png") : fs::path(args.out);
    const GridImageSummary s = writeIsoSurfaceImage(renderer, file, o, out);
    std::printf("ejecta: %s = %.6g%s of %s (t = %.6g s): %zu triangles", s.grid.c_str(), s.isovalue,
                unitsText(s.units).c_str(), file.filename().c_str(), s.time, s.triangles);
    if (s.cutAt) std::printf(", cut at %s = %.6g m", o.cut.c_str(), *s.cutAt);
    if (!o.colorBy.empty())
      std::printf(", coloured by %s (%.6g to %.6g%s)", o.colorBy.c_str(), s.colorMin, s.colorMax,
                  unitsText(s.colorUnits).c_str());
    std::printf("; camera %.6g m from (%.6g, %.6g, %.6g), %.6g px/m there; picture %d x %d px -> %s\n",
                s.cameraDistance, s.target[0], s.target[1], s.target[2], s.pixelsPerMetre, s.plotWidth,
                s.plotHeight, out.c_str());
    return 0;
  }

  GridSliceImageOptions o = args.slice.empty() ? GridSliceImageOptions{} : parseSlice(args.slice);
  o.axes = args.axes;
  if (!args.grid.empty()) o.grid = args.grid;
  o.log = args.log;
  const fs::path out = args.out.empty() ? fs::path("grid_" + o.grid + ".png") : fs::path(args.out);
  const GridImageSummary s = writeGridSliceImage(renderer, file, o, out);
  const char* axis[3] = {"x", "y", "z"};
  std::printf("ejecta: %s on %s = %.6g m of %s (t = %.6g s): %d x %d samples, colours %.6g to %.6g%s%s; "
              "%.6g px/m; picture %d x %d px -> %s\n",
              s.grid.c_str(), axis[s.axis], s.planeValue, file.filename().c_str(), s.time, s.samplesX, s.samplesY,
              s.colorMin, s.colorMax, unitsText(s.colorUnits).c_str(), o.log ? " (log)" : "", s.pixelsPerMetre,
              s.plotWidth, s.plotHeight, out.c_str());
  return 0;
}

}  // namespace

int renderCommand(const RenderArgs& args) {
  const fs::path input(args.input);
  if (input.extension() == ".vdb") return renderGridFile(args, input);
  if (fs::is_directory(input) && wantsGrids(args))
    return renderGridFile(args, lastOfSeries(input, "fields", "fields_", R"(\.vdb)"));
  if (wantsGrids(args))
    throw std::invalid_argument("--grid, --slice, --iso and --color-by are for grid files (.vdb) and run directories");

  const fs::path snapshot = snapshotOf(input);
  SnapshotInfo info;
  const ParticleSet p = readSnapshot(snapshot.string(), info);
  if (!info.sceneSource.empty())
    checkSnapshotMaterials(p, storedScene(info, snapshot.string()).materials.size(), snapshot.string());
  if (p.numReal == 0) throw std::invalid_argument(snapshot.string() + ": the snapshot holds no particles to draw");
  ParticleImageOptions options;
  if (!args.field.empty()) options.field = args.field;
  options.log = args.log;
  options.axes = args.axes;
  if (!args.cut.empty()) options.cut = args.cut;
  options.cutAt = cutAtOf(args).value_or(0.0);
  options.camera = cameraOf(args);
  if (!args.center.empty()) {
    const auto c = parseTriple(args.center, Dimension::Length, "--center", 2);
    options.center = std::array<double, 2>{c[0], c[1]};
  }
  if (!args.width.empty()) options.width = parseValue(args.width, Dimension::Length, "--width");
  if (options.width < 0.0) throw std::invalid_argument("--width: must be positive");
  if (options.center.has_value() != (options.width > 0.0))
    throw std::invalid_argument("--center and --width frame a plane or RZ picture together: give both");
  Geometry geometry = info.geometry;
  if (args.view == "plane") geometry = Geometry::Planar;
  else if (args.view == "rz") geometry = Geometry::Axisymmetric;
  else if (args.view == "3d") geometry = Geometry::Spatial;
  else if (!args.view.empty() && args.view != "auto")
    throw std::invalid_argument("--view '" + args.view + "': expected auto, plane, rz or 3d");
  if (spatialDimension(geometry) == 3 && options.center)
    throw std::invalid_argument("--center and --width frame plane and RZ pictures; a 3D one takes --camera");
  if (spatialDimension(geometry) != 3 && (options.camera || !args.cutAt.empty()))
    throw std::invalid_argument("--camera and --cut-at are for 3D pictures; " + snapshot.filename().string() +
                                " is drawn as a plane section (--view 3d to draw it in 3D)");
  if (!args.plot.empty() && args.plot != "materials" && args.plot != "failure")
    throw std::invalid_argument("--plot '" + args.plot + "': expected materials or failure");
  if (!args.plot.empty() && !args.field.empty())
    throw std::invalid_argument("--plot draws categories, --field a field's values: give one");
  const std::string what = args.plot.empty() ? options.field : args.plot;
  const fs::path out = args.out.empty() ? fs::path(what + ".png") : fs::path(args.out);
  if (args.size < 64 || args.size > 8192)
    throw std::invalid_argument("--size " + std::to_string(args.size) + ": expected 64 to 8192 pixels");
  render::Renderer renderer({.width = args.size, .height = args.size});
  if (!args.plot.empty()) {
    // The material table the snapshot stores (/materials); ids alone for older files.
    MaterialLegend legend;
    for (const SnapshotMaterial& m : info.materials) {
      legend.names.push_back(m.name);
      legend.strength.push_back(m.strength != "none");
    }
    const Categories categories =
        args.plot == "materials" ? materialCategories(p, legend) : failureCategories(p, legend);
    writeCategoryImage(renderer, p, geometry, info.time,
                       info.scene + (args.plot == "materials" ? ": materials" : ": failure status"),
                       categories, options, out);
  } else {
    writeParticleImage(renderer, p, geometry, info.time, info.scene, options, out);
  }
  std::printf("ejecta: %s (%s at t = %.6g s, %zu particles) -> %s\n", what.c_str(),
              snapshot.filename().c_str(), info.time, p.numReal, out.c_str());
  return 0;
}

}  // namespace ejecta::app
