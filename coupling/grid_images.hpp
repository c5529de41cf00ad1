#pragma once
// Pictures of a run's grid files (render/ over fields/): a slice through any grid on an
// axis-aligned plane, and an iso-surface of one grid in perspective, optionally coloured by
// another grid, cut open to show the crater. Used by `ejecta render FILE.vdb` and by the frames
// `ejecta run` draws for the [images] keys `grids` and `surface`. docs/render.md.
#include <array>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

#include "render/renderer.hpp"

namespace ejecta::coupling {

// The seed's molten-rock cut [K]: thesis chapter 4.5, "temperatures below 1500 K were omitted as
// molten rock temperatures are above 1500 K" (also fields/grid_voxels.hpp's default threshold).
inline constexpr double kMoltenRockTemperature = 1500.0;

struct GridSliceImageOptions {
  std::string grid = "density";
  int axis = 2;                  // the plane x (0), y (1) or z (2) = value
  // [m]; none: 0 when the grid's active box spans it (the axis of an RZ run, a 3D impact's
  // symmetry plane), else the middle of the box.
  std::optional<double> value;
  bool log = false;
  std::string title;             // default "<scene>: z = 0 m" (the colour bar names the grid)
  bool axes = false;             // distance axes along the edges
};

struct IsoSurfaceImageOptions {
  std::string grid = "surface";
  std::optional<double> isovalue;  // in the grid's units; none: defaultIsovalue
  // A grid sampled at the vertices (fields/grid_slice.hpp's rule) and on the cut face; empty:
  // one plain colour.
  std::string colorBy;
  bool log = false;              // colorBy on a log scale
  // Keep the half x, y or z <= c of the picture, c = cutAt when given, else 0 when the surface
  // spans it, else its middle; "none": the whole surface.
  std::string cut = "z";
  std::optional<double> cutAt;    // [m]
  // The camera; none: one that looks at what the cut keeps from its open side and frames it.
  std::optional<render::Camera> camera;
  std::string title;             // default "<scene>: <grid> = <isovalue> <units>"
};

// What a picture shows, for the command's report and for tests.
struct GridImageSummary {
  std::string grid, units, scene;
  double time = 0.0;             // [s], the grid's metadata
  double colorMin = 0.0, colorMax = 0.0;  // the colour bar's ends (none: both 0)
  std::string colorUnits;        // theirs: the grid's, or the colour grid's of an iso-surface
  // A slice: the plane and its samples.
  int axis = 2;
  double planeValue = 0.0;
  int samplesX = 0, samplesY = 0;
  // An iso-surface: its level, its triangles, the cut's position.
  double isovalue = 0.0;
  std::size_t triangles = 0;
  std::optional<double> cutAt;
  // The framing: the picture's pixels (without the strip), its scale at the camera's target
  // (exact in a slice's orthographic view) and, in perspective, the camera's distance from
  // that target and the target itself.
  int plotWidth = 0, plotHeight = 0;
  double pixelsPerMetre = 0.0;
  double cameraDistance = 0.0;   // [m]; 0 for a slice
  std::array<double, 3> target{};
};

// The default level of an iso-surface of `grid`: 0 for a level set (the surface itself), half
// the target's reference density for "density" (a plain SPH sum falls from the body's density to
// 0 across its surface; the reference is the file's crater_target_density), 0.5 for a plain
// fraction grid (its surface: docs/fields.md), 1500 K for "temperature" (the molten-rock cut).
// Throws std::runtime_error naming the file and grid when there is none (another grid, or a
// density grid of a file without the crater metadata: give the value).
double defaultIsovalue(const std::filesystem::path& gridFile, const std::string& grid);

// Draws a slice of `options.grid` of `gridFile` (a plane view, u right and v up as
// fields::slicePlaneAxes names them) with a colour bar of the grid's name and units over the
// grid's whole range (log: its maximum and the 1st percentile of the slice's positive values),
// the time of the file and a scale bar, and writes the PNG atomically. Throws as
// fields::sampleGridSlice does, and std::invalid_argument for an axis outside 0-2.
GridImageSummary writeGridSliceImage(render::Renderer& renderer, const std::filesystem::path& gridFile,
                                     const GridSliceImageOptions& options, const std::filesystem::path& out);

// Draws the iso-surface `options.grid` = isovalue of `gridFile` in perspective (a camera fitted
// to it, looking from the side the cut keeps open) and writes the PNG atomically. With colorBy,
// the cut face is filled with a slice of that grid inside the surface, on the same scale as the
// vertices (0.5 to 99.5 percentiles of both). Throws std::runtime_error naming the file and grid
// when the surface is empty, and as fields::meshIsoSurfaceFile does; std::invalid_argument for
// an unknown cut.
GridImageSummary writeIsoSurfaceImage(render::Renderer& renderer, const std::filesystem::path& gridFile,
                                      const IsoSurfaceImageOptions& options, const std::filesystem::path& out);

}  // namespace ejecta::coupling
