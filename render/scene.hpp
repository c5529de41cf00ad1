#pragma once
// What an image shows (layers of plain arrays: particles, triangle meshes, scalar slices) and
// from where (a View). The renderer reads the arrays during Renderer::render only: the spans
// must stay valid for that call, no longer.
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "render/color_scale.hpp"
#include "render/image.hpp"

namespace ejecta::render {

using Vec3 = std::array<double, 3>;

// Particles as discs of radius radiusInH * h facing the viewer: Shaded as lit spheres (a
// headlight, Lambert), Flat as uniform discs.
enum class ParticleStyle { Shaded, Flat };

struct ParticleLayer {
  // Positions [m]. 2D and RZ runs: x, y (RZ: x = r >= 0, y = z), z empty. 3D: x, y, z.
  std::span<const double> x{}, y{}, z{};
  std::span<const double> h{};       // smoothing lengths [m], one per particle
  std::span<const double> values{};  // the field to colour by, one per particle; empty: `color`
  ColorScaleSpec scale{};
  Rgb color{0.6f, 0.6f, 0.6f};
  // Disc radius in smoothing lengths (when `radius` is empty): 0.5 gives a disc of diameter h.
  double radiusInH = 0.5;
  // Disc radii [m], one per particle (coupling/ sizes them to each particle's own spacing, so
  // neighbours' discs close the gaps of a lattice: no moire); empty: radiusInH * h.
  std::span<const double> radius{};
  double discRadius(std::size_t k) const { return std::abs(radius.empty() ? radiusInH * h[k] : radius[k]); }
  ParticleStyle style = ParticleStyle::Shaded;
  // The colour bar: shown when `values` is not empty and `colorBar` is set.
  std::string field{}, units{};
  bool colorBar = true;
};

// A triangle mesh: an iso-surface from a grid, a crater surface, a spacecraft. Coloured by a
// scalar per vertex (interpolated) or per triangle (flat), or one colour; lit by a headlight
// from the camera (Lambert, both sides).
struct MeshLayer {
  std::span<const Vec3> vertices{};                           // [m]
  std::span<const std::array<std::uint32_t, 3>> triangles{};  // vertex indices
  std::span<const double> vertexValues{};                     // empty, or one per vertex
  std::span<const double> triangleValues{};                   // empty, or one per triangle
  ColorScaleSpec scale{};
  Rgb color{0.75f, 0.75f, 0.75f};
  bool shaded = true;
  // Normals averaged at shared vertices (a smooth iso-surface) rather than one per triangle
  // (facets; always so with triangleValues).
  bool smoothNormals = true;
  std::string field{}, units{};
  bool colorBar = true;
};

// A 2D array of scalars drawn as coloured cells: a slice through a grid. Sample (i, j) is
// values[i + nx * j], centred at origin + i * spacing[0] * uAxis + j * spacing[1] * vAxis, and
// covers a cell of spacing[0] x spacing[1] around that point. NaN samples are transparent.
struct SliceLayer {
  int nx = 0, ny = 0;
  std::span<const double> values{};
  Vec3 origin{};                    // centre of sample (0, 0) [m]
  std::array<double, 2> spacing{};  // [m]
  Vec3 uAxis{1.0, 0.0, 0.0};        // unit directions of i and j
  Vec3 vAxis{0.0, 1.0, 0.0};
  ColorScaleSpec scale{};
  std::string field{}, units{};
  bool colorBar = true;
};

// Keeps the side n . x <= offset (a cut: normal (0, 0, 1), offset 0 keeps z <= 0).
struct ClipPlane {
  Vec3 normal{0.0, 0.0, 1.0};
  double offset = 0.0;
};

struct Camera {
  Vec3 position{};
  Vec3 target{};
  Vec3 up{0.0, 1.0, 0.0};
  double fovYDegrees = 30.0;  // vertical field of view
};

enum class ViewKind {
  Plane,         // the x-y plane, +x right, +y up, orthographic
  Axisymmetric,  // RZ: r right, z up, mirrored about the axis (r -> -r) for a full section
  Perspective,   // 3D through a Camera
};

struct View {
  ViewKind kind = ViewKind::Plane;
  // Plane and Axisymmetric: the centre of the picture and the width it shows [m]. Not given
  // (width 0): fit everything drawn, with a small margin.
  std::optional<std::array<double, 2>> center{};
  double width = 0.0;
  // Perspective: the camera; none: looking at the centre of everything drawn from
  // `autoDirection`, far enough for all of it to fit.
  std::optional<Camera> camera{};
  Vec3 autoDirection{0.45, 0.35, 1.0};
  double autoFovYDegrees = 30.0;
  // Up to 4 cuts, applied to every layer.
  std::vector<ClipPlane> clipPlanes{};
};

// One category of a categorical picture (a material, a failure state) in the strip's legend.
struct LegendEntry {
  std::string label;
  Rgb color;
};

// The strip of text and bars under the picture. Shown when anything in it is asked for.
struct Annotations {
  std::string title{};
  std::optional<double> time{};  // [s]: "t = 1.25 ms"
  bool scaleBar = true;          // a round length about 1/5 of the view (Perspective: at the
                                 // target's distance)
  bool colorBars = true;         // one per layer that asks for it
  // Swatches with their names, three to a row, right of the title (below any colour bars).
  std::vector<LegendEntry> legend{};
  // Distance axes along the plot's bottom and left edges (plane and RZ views;
  // render/distance_axes.hpp), named axisNames[0] and [1] ("x", "y"; RZ "r", "z").
  bool axes = false;
  std::array<std::string, 2> axisNames{"x", "y"};
};

// What one image draws: its layers and the strip under it. (Not a scene file: that is
// ejecta::Scene, sim/setup/scene.hpp.)
struct Picture {
  std::vector<SliceLayer> slices{};        // drawn first,
  std::vector<MeshLayer> meshes{};         // then meshes,
  std::vector<ParticleLayer> particles{};  // then particles (depth-tested in 3D)
  Annotations annotations{};
};

struct RenderSettings {
  int width = 1024, height = 1024;  // pixels, the whole image including the strip
  Rgb background{1.0f, 1.0f, 1.0f};
  // Text and bar outlines; default: black or white, whichever contrasts with the background.
  std::optional<Rgb> ink{};
  // Pixels per font pixel; 0: one per 512 pixels of the smaller image side (2 at 1024).
  int textScale = 0;
};

}  // namespace ejecta::render

namespace ejecta::render {

// Throws std::invalid_argument naming the layer (kind and index), the array and the reason:
// arrays of unequal lengths, a triangle index beyond the vertices, a slice whose value count
// is not nx * ny or whose spacing is not positive, more than 4 clip planes or a zero normal.
void validatePicture(const Picture& scene, const View& view);

}  // namespace ejecta::render
