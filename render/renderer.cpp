#include "render/renderer.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>

#include "render/distance_axes.hpp"
#include "render/gl_context.hpp"
#include "render/labels.hpp"
#include "render/passes.hpp"

namespace ejecta::render {

struct Renderer::Impl {
  // Declared first so that it is destroyed last: the passes free GL objects in it.
  OffscreenContext context;
  detail::SlicePass slices;
  detail::MeshPass meshes;
  detail::ParticlePass particles;
  Impl(int width, int height) : context(width, height) {}
};

namespace {

std::optional<ColorScale> scaleOf(std::span<const double> values, const ColorScaleSpec& spec) {
  if (values.empty()) return std::nullopt;
  return resolveScale(spec, values);
}

std::string barLabel(const std::string& field, const std::string& units) {
  return fieldLabel(field.empty() ? "value" : field, units);
}

// The colour bar of a layer: its label, scale, and whether any finite value lies beyond either
// end (a log scale's non-positive values lie below it).
ColorBarEntry barOf(const std::string& field, const std::string& units, const ColorScale& scale,
                    std::span<const double> values) {
  ColorBarEntry entry{barLabel(field, units), scale};
  const double tolerance = 1e-9 * (std::abs(scale.min()) + std::abs(scale.max()));
  for (const double v : values) {
    if (!std::isfinite(v)) continue;
    if (v < scale.min() - tolerance) entry.clippedLow = true;
    if (v > scale.max() + tolerance) entry.clippedHigh = true;
  }
  return entry;
}

}  // namespace

Rgb contrastingInk(const Rgb& background) {
  const float luma = 0.2126f * background.r + 0.7152f * background.g + 0.0722f * background.b;
  return luma > 0.5f ? Rgb{0.0f, 0.0f, 0.0f} : Rgb{1.0f, 1.0f, 1.0f};
}

Renderer::Renderer(RenderSettings settings)
    : settings_(settings),
      impl_(std::make_unique<Impl>(std::max(settings.width, 1), std::max(settings.height, 1))) {}

Renderer::~Renderer() = default;

std::string Renderer::glRenderer() const { return impl_->context.rendererName(); }

Frame Renderer::render(const Picture& scene, const View& view) {
  validatePicture(scene, view);
  const int width = settings_.width, height = settings_.height;
  if (width <= 0 || height <= 0)
    throw std::invalid_argument("image size must be positive, got " + std::to_string(width) +
                                " x " + std::to_string(height));

  // Colour scales of every coloured layer, and the colour bars asked for.
  Frame frame;
  std::vector<std::optional<ColorScale>> sliceScales, meshScales, particleScales;
  const bool bars = scene.annotations.colorBars;
  for (const SliceLayer& s : scene.slices) {
    sliceScales.push_back(resolveScale(s.scale, s.values));
    if (bars && s.colorBar)
      frame.colorBars.push_back(barOf(s.field, s.units, *sliceScales.back(), s.values));
  }
  for (const MeshLayer& m : scene.meshes) {
    meshScales.push_back(
        scaleOf(m.triangleValues.empty() ? m.vertexValues : m.triangleValues, m.scale));
    if (bars && m.colorBar && meshScales.back())
      frame.colorBars.push_back(barOf(m.field, m.units, *meshScales.back(),
                                      m.triangleValues.empty() ? m.vertexValues : m.triangleValues));
  }
  for (const ParticleLayer& p : scene.particles) {
    particleScales.push_back(scaleOf(p.values, p.scale));
    if (bars && p.colorBar && particleScales.back())
      frame.colorBars.push_back(barOf(p.field, p.units, *particleScales.back(), p.values));
  }

  const int textScale =
      settings_.textScale > 0 ? settings_.textScale : std::max(1, std::min(width, height) / 512);
  const int strip = stripHeight(scene.annotations, frame.colorBars.size(), textScale);
  const int plotHeight = height - strip;
  if (plotHeight < std::max(16, height / 4))
    throw std::invalid_argument("image of " + std::to_string(width) + " x " +
                                std::to_string(height) + " pixels is too small for its " +
                                std::to_string(strip) + "-pixel annotation strip");
  const bool mirror = view.kind == ViewKind::Axisymmetric;
  frame.framing = frameView(view, measurePicture(scene, mirror), width, plotHeight);

  OffscreenContext& context = impl_->context;
  if (context.width() != width || context.height() != height)
    context.resize(width, height);
  else
    context.makeCurrent();
  const Rgb& bg = settings_.background;
  glClearColor(bg.r, bg.g, bg.b, 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  // OpenGL counts rows from the bottom: the picture sits above the strip.
  glViewport(0, strip, width, plotHeight);
  glEnable(GL_DEPTH_TEST);
  // Equal depths (everything of a 2D view lies at z = 0): what is drawn later is on top.
  glDepthFunc(GL_LEQUAL);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glEnable(GL_PROGRAM_POINT_SIZE);
  glEnable(GL_POINT_SPRITE);  // compatibility profile: gl_PointCoord needs it
  for (int c = 0; c < 4; ++c) {
    if (c < static_cast<int>(view.clipPlanes.size()))
      glEnable(GL_CLIP_DISTANCE0 + c);
    else
      glDisable(GL_CLIP_DISTANCE0 + c);
  }
  const detail::DrawState state = detail::makeDrawState(frame.framing, view.clipPlanes);
  for (std::size_t i = 0; i < scene.slices.size(); ++i)
    impl_->slices.draw(scene.slices[i], *sliceScales[i], frame.framing, state);
  for (std::size_t i = 0; i < scene.meshes.size(); ++i)
    impl_->meshes.draw(scene.meshes[i], meshScales[i] ? &*meshScales[i] : nullptr, frame.framing,
                       state);
  for (std::size_t i = 0; i < scene.particles.size(); ++i)
    impl_->particles.draw(scene.particles[i], particleScales[i] ? &*particleScales[i] : nullptr,
                          frame.framing, state);
  glFinish();
  gl::check("finishing the frame");

  frame.image = Image(width, height);
  std::memcpy(frame.image.bytes().data(), context.pixels().data(), context.pixels().size());
  if (scene.annotations.axes)
    drawDistanceAxes(frame.image, frame.framing,
                     {scene.annotations.axisNames[0], scene.annotations.axisNames[1]}, textScale,
                     toRgba8(settings_.ink.value_or(contrastingInk(bg))));
  if (strip > 0) {
    frame.strip = layoutStrip(scene.annotations, frame.colorBars, width, plotHeight, textScale,
                              frame.framing.pixelsPerMetre);
    drawStrip(frame.image, frame.strip, frame.colorBars,
              toRgba8(settings_.ink.value_or(contrastingInk(bg))));
  }
  return frame;
}

}  // namespace ejecta::render
