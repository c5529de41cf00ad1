#include "coupling/grid_images.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "fields/grid_slice.hpp"
#include "fields/surface_mesh.hpp"
#include "render/png_io.hpp"

namespace ejecta::coupling {

namespace {

constexpr const char* kAxisNames[3] = {"x", "y", "z"};

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

std::string withUnits(double v, const std::string& units) {
  return number(v) + (units.empty() || units == "1" ? "" : " " + units);
}

// Temperatures in the black-body map, signed distances in the diverging one, the rest viridis.
render::ColorMapName mapFor(const std::string& grid, bool levelSet) {
  if (grid == "temperature") return render::ColorMapName::Inferno;
  if (levelSet) return render::ColorMapName::CoolWarm;
  return render::ColorMapName::Viridis;
}

constexpr double kFieldOfViewDegrees = 30.0;  // the iso-surface camera's vertical field of view

// The box of the vertices on the kept side (coordinate `axis` <= cut; axis -1: all of them).
struct Box {
  render::Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
};
Box boxOf(const std::vector<std::array<double, 3>>& vertices, int axis, double cut) {
  Box b;
  for (const auto& v : vertices) {
    if (axis >= 0 && v[static_cast<std::size_t>(axis)] > cut) continue;
    for (std::size_t d = 0; d < 3; ++d) {
      b.lo[d] = std::min(b.lo[d], v[d]);
      b.hi[d] = std::max(b.hi[d], v[d]);
    }
  }
  return b;
}

// The cells of a slice for which `keep(k)` holds, as a mesh: the slice's cell corners as
// vertices, two triangles per kept cell.
struct CapMesh {
  std::vector<std::array<double, 3>> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};
template <class Keep>
CapMesh capMesh(const fields::GridSlice& slice, Keep keep) {
  CapMesh m;
  const int cx = slice.nx + 1, cy = slice.ny + 1;
  for (int j = 0; j < cy; ++j)
    for (int i = 0; i < cx; ++i) {
      std::array<double, 3> p = slice.position(i, j);
      p[static_cast<std::size_t>(slice.planeAxes[0])] -= 0.5 * slice.spacing[0];
      p[static_cast<std::size_t>(slice.planeAxes[1])] -= 0.5 * slice.spacing[1];
      m.vertices.push_back(p);
    }
  auto corner = [&](int i, int j) { return static_cast<std::uint32_t>(i + cx * j); };
  for (int j = 0; j < slice.ny; ++j)
    for (int i = 0; i < slice.nx; ++i)
      if (keep(static_cast<std::size_t>(i + slice.nx * j))) {
        m.triangles.push_back({corner(i, j), corner(i + 1, j), corner(i + 1, j + 1)});
        m.triangles.push_back({corner(i, j), corner(i + 1, j + 1), corner(i, j + 1)});
      }
  return m;
}

// -1 for "none"; throws for anything but none, x, y, z.
int cutAxis(const std::string& cut) {
  if (cut == "none") return -1;
  for (int a = 0; a < 3; ++a)
    if (cut == kAxisNames[a]) return a;
  throw std::invalid_argument("cut '" + cut + "': expected none, x, y or z");
}

// Where the camera looks from: the side the cut leaves open, a little from the right and above
// (the particle pictures' direction for the default z cut).
render::Vec3 cameraDirection(int axis) {
  if (axis == 0) return {1.0, 0.35, 0.45};
  if (axis == 1) return {0.35, 1.0, 0.45};
  return {0.45, 0.35, 1.0};
}

// A colour range [lo, hi], or none when it is degenerate. A spread below 0.1% of the values is
// numerical noise (float storage, Shepard normalisation: 293 K +- 1e-5 K all over a body at
// rest), not a field worth a colour ramp: such data is taken as uniform and widened +-50%, as
// render::resolveScale widens equal data, so that it shows as one colour.
std::optional<std::array<double, 2>> colourRange(double lo, double hi) {
  if (!std::isfinite(lo) || !std::isfinite(hi) || hi < lo) return std::nullopt;
  const double size = std::max(std::abs(lo), std::abs(hi));
  if (hi - lo > 1e-3 * size) return std::array<double, 2>{lo, hi};
  if (size == 0.0) return std::nullopt;
  const double mid = 0.5 * (lo + hi);
  return std::array<double, 2>{std::min(0.5 * mid, 1.5 * mid), std::max(0.5 * mid, 1.5 * mid)};
}

void addFraming(GridImageSummary& s, const render::Frame& frame) {
  const render::Framing& f = frame.framing;
  s.plotWidth = f.plotWidth;
  s.plotHeight = f.plotHeight;
  s.pixelsPerMetre = f.pixelsPerMetre;
  if (!frame.colorBars.empty()) {
    s.colorMin = frame.colorBars.front().scale.min();
    s.colorMax = frame.colorBars.front().scale.max();
  }
}

}  // namespace

double defaultIsovalue(const std::filesystem::path& gridFile, const std::string& grid) {
  const std::string path = gridFile.string();
  const fields::GridHeader h = fields::readGridHeader(path, grid);
  if (h.levelSet()) return 0.0;
  if (grid == "temperature") return kMoltenRockTemperature;
  if (grid.rfind("fraction_", 0) == 0) return 0.5;
  if (grid == "density") {
    if (h.targetDensity && *h.targetDensity > 0.0) return 0.5 * *h.targetDensity;
    throw std::runtime_error(path + ": no reference density stored (crater_target_density: the file is not an "
                             "impact run's) for a default iso-surface of 'density'; give the value "
                             "(--iso density=VALUE)");
  }
  throw std::runtime_error(path + ": no default iso-surface level for grid '" + grid + "'; give the value (--iso " +
                           grid + "=VALUE)");
}

GridImageSummary writeGridSliceImage(render::Renderer& renderer, const std::filesystem::path& gridFile,
                                     const GridSliceImageOptions& options, const std::filesystem::path& out) {
  const std::string path = gridFile.string();
  if (options.axis < 0 || options.axis > 2)
    throw std::invalid_argument(path + ": slice axis " + std::to_string(options.axis) + ": expected 0 (x), 1 (y) or 2 (z)");
  fields::GridSliceOptions so;
  so.grid = options.grid;
  so.axis = options.axis;
  if (options.value) {
    so.value = *options.value;
  } else {
    const fields::GridHeader h = fields::readGridHeader(path, options.grid);
    const auto a = static_cast<std::size_t>(options.axis);
    so.value = h.emptyBox() || (h.lo[a] <= 0.0 && h.hi[a] >= 0.0) ? 0.0 : 0.5 * (h.lo[a] + h.hi[a]);
  }
  // About two image pixels per sample: smooth (trilinear) where the voxels are large, and no
  // more samples than the picture can show.
  const int width = renderer.settings().width;
  so.samples = std::max(16, width / 2);
  const fields::GridSlice slice = fields::sampleGridSlice(path, so);
  const fields::GridHeader& h = slice.header;

  render::SliceLayer layer;
  layer.nx = slice.nx;
  layer.ny = slice.ny;
  layer.values = slice.values;
  // The plane's (u, v) become the picture's (x, y): a plane view, with metres on the scale bar.
  layer.origin = {slice.origin[0], slice.origin[1], 0.0};
  layer.spacing = slice.spacing;
  layer.field = h.name;
  layer.units = h.units == "1" ? "" : h.units;
  render::ColorScaleSpec& spec = layer.scale;
  spec.map = mapFor(h.name, h.levelSet());
  const auto range = colourRange(slice.minValue, slice.maxValue);
  if (options.log) {
    // A fog grid tails off to 0 at its edge: its minimum would stretch the scale over many
    // decades of nothing. The lower end is the slice's 1st percentile of positive values.
    spec.kind = render::ScaleKind::Log;
    if (range && (*range)[1] > 0.0) spec.max = (*range)[1];
    spec.lowPercentile = 1.0;
  } else if (range && h.levelSet()) {
    const double m = std::max(std::abs((*range)[0]), std::abs((*range)[1]));
    spec.min = -m;
    spec.max = m;
  } else if (range) {
    spec.min = (*range)[0];
    spec.max = (*range)[1];
  }

  render::Picture scene;
  scene.slices.push_back(layer);
  const std::string axis = kAxisNames[options.axis];
  scene.annotations.title = options.title.empty()
                                ? h.scene + ": " + axis + " = " + number(slice.value) + " m"
                                : options.title;
  scene.annotations.time = h.time;
  // The plane's in-plane axes, in order (fields/grid_slice.hpp): x = 0 -> (y, z), ...
  scene.annotations.axes = options.axes;
  scene.annotations.axisNames = {kAxisNames[options.axis == 0 ? 1 : 0], kAxisNames[options.axis == 2 ? 1 : 2]};
  render::View view;
  view.kind = render::ViewKind::Plane;
  const render::Frame frame = renderer.render(scene, view);
  render::writePng(out, frame.image);

  GridImageSummary s;
  s.grid = h.name;
  s.units = h.units;
  s.scene = h.scene;
  s.time = h.time;
  s.axis = options.axis;
  s.planeValue = slice.value;
  s.samplesX = slice.nx;
  s.samplesY = slice.ny;
  s.colorUnits = h.units;
  addFraming(s, frame);
  return s;
}

GridImageSummary writeIsoSurfaceImage(render::Renderer& renderer, const std::filesystem::path& gridFile,
                                      const IsoSurfaceImageOptions& options, const std::filesystem::path& out) {
  const std::string path = gridFile.string();
  const int axis = cutAxis(options.cut);
  const fields::GridHeader h = fields::readGridHeader(path, options.grid);
  const double iso = options.isovalue ? *options.isovalue : defaultIsovalue(gridFile, options.grid);
  fields::SurfaceMeshOptions mo;
  mo.grid = options.grid;
  mo.isovalue = iso;
  const fields::SurfaceMesh mesh = fields::meshIsoSurfaceFile(path, mo);
  if (mesh.empty())
    throw std::runtime_error(path + ": grid '" + options.grid + "' has no surface at " + options.grid + " = " +
                             withUnits(iso, h.units));

  const Box box = boxOf(mesh.vertices, -1, 0.0);
  const render::Vec3& lo = box.lo;
  const render::Vec3& hi = box.hi;
  std::optional<double> cutAt;
  if (axis >= 0) {
    const auto a = static_cast<std::size_t>(axis);
    cutAt = options.cutAt ? *options.cutAt : lo[a] < 0.0 && hi[a] > 0.0 ? 0.0 : 0.5 * (lo[a] + hi[a]);
  }

  render::MeshLayer surface;
  surface.vertices = mesh.vertices;
  surface.triangles = mesh.triangles;

  // The cut face, on a plane just inside the kept half (a hundredth of a voxel, so that the clip
  // plane keeps it), where the iso grid says "inside" (its stored values: a level set's inside
  // reads negative all through): without it the cut would open a hollow shell.
  std::optional<fields::GridSlice> inside;
  fields::GridSliceOptions so;
  std::array<int, 2> uv{0, 1};
  if (cutAt) {
    so.axis = axis;
    so.value = *cutAt - 0.01 * mesh.voxelSize;
    uv = fields::slicePlaneAxes(axis);
    so.window = std::array<double, 4>{lo[static_cast<std::size_t>(uv[0])], hi[static_cast<std::size_t>(uv[0])],
                                      lo[static_cast<std::size_t>(uv[1])], hi[static_cast<std::size_t>(uv[1])]};
    so.samples = std::max(16, renderer.settings().width / 2);
    so.grid = options.grid;
    so.inactive = fields::InactiveRule::Stored;
    inside = fields::sampleGridSlice(path, so);
  }
  auto isInside = [&](std::size_t k) {
    const double v = inside->values[k];
    return h.levelSet() ? v < iso : v > iso;
  };

  std::vector<double> vertexValues, capValues;
  render::SliceLayer cap;       // coloured: the colour grid's values, flat as on a slice
  CapMesh plainCap;             // plain: the surface's own colour, lit like it
  if (!options.colorBy.empty()) {
    // A surface may lie up to a voxel beyond the colour grid's active voxels (a level set closing
    // where a clipped grid ends): their values, not "no data".
    vertexValues = fields::sampleGridPoints(path, options.colorBy, mesh.vertices, fields::InactiveRule::AllInactive);
    surface.vertexValues = vertexValues;
    std::string colorUnits;
    if (inside) {
      so.grid = options.colorBy;
      so.inactive = fields::InactiveRule::AllInactive;
      const fields::GridSlice colour = fields::sampleGridSlice(path, so);
      capValues = colour.values;
      for (std::size_t k = 0; k < capValues.size(); ++k)
        if (!isInside(k)) capValues[k] = std::nan("");
      cap.nx = colour.nx;
      cap.ny = colour.ny;
      cap.values = capValues;
      cap.origin = colour.position(0, 0);
      cap.spacing = colour.spacing;
      cap.uAxis = {0.0, 0.0, 0.0};
      cap.vAxis = {0.0, 0.0, 0.0};
      cap.uAxis[static_cast<std::size_t>(uv[0])] = 1.0;
      cap.vAxis[static_cast<std::size_t>(uv[1])] = 1.0;
      cap.colorBar = false;
      colorUnits = colour.header.units;
    } else {
      colorUnits = fields::readGridHeader(path, options.colorBy).units;
    }
    // One scale for the surface and the cut face, robust to a few extreme voxels.
    render::ColorScaleSpec spec;
    spec.map = mapFor(options.colorBy, false);
    spec.kind = options.log ? render::ScaleKind::Log : render::ScaleKind::Linear;
    spec.lowPercentile = 0.5;
    spec.highPercentile = 99.5;
    std::vector<double> all = vertexValues;
    all.insert(all.end(), capValues.begin(), capValues.end());
    const render::ColorScale resolved = render::resolveScale(spec, all);
    const auto range = colourRange(resolved.min(), resolved.max());
    spec.min = range ? (*range)[0] : resolved.min();
    spec.max = range ? (*range)[1] : resolved.max();
    surface.scale = spec;
    cap.scale = spec;
    surface.field = options.colorBy;
    surface.units = colorUnits == "1" ? "" : colorUnits;
  } else if (inside) {
    plainCap = capMesh(*inside, isInside);
  }

  render::Picture scene;
  if (cap.nx > 0) scene.slices.push_back(cap);
  scene.meshes.push_back(surface);
  if (!plainCap.triangles.empty()) {
    render::MeshLayer face;
    face.vertices = plainCap.vertices;
    face.triangles = plainCap.triangles;
    face.smoothNormals = false;
    scene.meshes.push_back(face);
  }
  scene.annotations.title =
      options.title.empty()
          ? h.scene + ": " + options.grid + " = " + withUnits(iso, h.units)
          : options.title;
  scene.annotations.time = h.time;
  // The camera frames what the cut keeps (the renderer's auto-fit would frame the whole mesh):
  // it looks at the kept part's centre from the open side, as far as its bounding sphere needs
  // to fit the vertical field of view (the narrower: the strip makes the picture wider than
  // tall), with the renderer's 2% to spare.
  const Box kept = boxOf(mesh.vertices, axis, cutAt.value_or(0.0));
  if (kept.lo[0] > kept.hi[0])
    throw std::invalid_argument(path + ": the cut at " + std::string(kAxisNames[axis]) + " = " +
                                number(*cutAt) + " m keeps none of the surface (it spans " +
                                number(lo[static_cast<std::size_t>(axis)]) + " to " +
                                number(hi[static_cast<std::size_t>(axis)]) + " m)");
  const render::Vec3 centre{0.5 * (kept.lo[0] + kept.hi[0]), 0.5 * (kept.lo[1] + kept.hi[1]),
                            0.5 * (kept.lo[2] + kept.hi[2])};
  double radius = 0.0;
  for (const auto& v : mesh.vertices)
    if (axis < 0 || v[static_cast<std::size_t>(axis)] <= *cutAt)
      radius = std::max(radius, std::hypot(v[0] - centre[0], v[1] - centre[1], v[2] - centre[2]));
  render::View view;
  view.kind = render::ViewKind::Perspective;
  render::Camera camera;
  camera.fovYDegrees = kFieldOfViewDegrees;
  const double distance = std::max(radius, mesh.voxelSize) / std::sin(kFieldOfViewDegrees * std::numbers::pi / 360.0) * 1.02;
  render::Vec3 direction = cameraDirection(axis);
  const double length = std::hypot(direction[0], direction[1], direction[2]);
  for (std::size_t d = 0; d < 3; ++d) {
    direction[d] /= length;
    camera.position[d] = centre[d] + distance * direction[d];
  }
  camera.target = centre;
  view.camera = options.camera ? *options.camera : camera;
  if (cutAt) {
    render::ClipPlane plane;
    plane.normal = {0.0, 0.0, 0.0};
    plane.normal[static_cast<std::size_t>(axis)] = 1.0;
    plane.offset = *cutAt;
    view.clipPlanes.push_back(plane);
  }
  const render::Frame frame = renderer.render(scene, view);
  render::writePng(out, frame.image);

  GridImageSummary s;
  s.grid = options.grid;
  s.units = h.units;
  s.scene = h.scene;
  s.time = h.time;
  s.isovalue = iso;
  s.triangles = mesh.size();
  s.cutAt = cutAt;
  s.colorUnits = surface.units;
  addFraming(s, frame);
  s.cameraDistance = distance;
  s.target = centre;
  if (options.camera) {
    const render::Camera& c = *options.camera;
    s.cameraDistance = std::hypot(c.target[0] - c.position[0], c.target[1] - c.position[1],
                                  c.target[2] - c.position[2]);
    s.target = c.target;
  }
  return s;
}

}  // namespace ejecta::coupling
