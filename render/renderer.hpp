#pragma once
// Off-screen images of a Picture: particles, meshes and slices drawn with OpenGL by OSMesa
// (llvmpipe, no display needed), then the annotation strip drawn underneath on the CPU.
// docs/render.md.
//
//   ejecta::render::Renderer renderer({.width = 1024, .height = 1024});
//   Picture scene;
//   scene.particles.push_back({.x = x, .y = y, .h = h, .values = rho, .field = "density",
//                              .units = "kg/m^3"});
//   scene.annotations.time = 1.2e-3;
//   writePng("images/density_0012.png", renderer.render(scene, View{}).image);
#include <memory>
#include <string>
#include <vector>

#include "render/annotations.hpp"
#include "render/image.hpp"
#include "render/scene.hpp"
#include "render/view_transform.hpp"

namespace ejecta::render {

struct Frame {
  Image image;
  // The picture is image rows [0, framing.plotHeight); the strip is below it.
  Framing framing;
  StripLayout strip;
  std::vector<ColorBarEntry> colorBars;  // in layer order: slices, meshes, particles
};

class Renderer {
 public:
  // Creates the OpenGL context and compiles the shaders (the "time to first frame"). Throws
  // std::runtime_error when OSMesa cannot give a context.
  explicit Renderer(RenderSettings settings = {});
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  const RenderSettings& settings() const { return settings_; }
  void setSettings(const RenderSettings& settings) { settings_ = settings; }

  // Draws the scene. Throws std::invalid_argument for an invalid scene or view (validatePicture,
  // frameView) and an image too small for its annotation strip. Not thread safe: one renderer
  // draws on one thread at a time (use one renderer per thread).
  Frame render(const Picture& scene, const View& view);

  // The OpenGL implementation, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
  std::string glRenderer() const;

 private:
  struct Impl;
  RenderSettings settings_;
  std::unique_ptr<Impl> impl_;
};

// Black or white, whichever stands out against `background` (its Rec. 709 luma vs 0.5).
Rgb contrastingInk(const Rgb& background);

}  // namespace ejecta::render
