#pragma once
// The renderer's drawing passes, one per kind of layer (internal to render/: includes GL).
// Each owns its shader program and buffers; all share the uniforms of GlobalUniforms.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "render/color_scale.hpp"
#include "render/gl_program.hpp"
#include "render/scene.hpp"
#include "render/view_transform.hpp"

namespace ejecta::render::detail {

// What every pass's vertex shader needs: matrices, the mirror of an axisymmetric view, cuts.
struct DrawState {
  std::array<float, 16> view{}, projection{};
  // Position x -> sign * x + shift: (1, 0), or (-1, -2 origin.x) for the mirror image about the
  // axis x = 0 in world coordinates.
  std::array<float, 2> mirror{1.0f, 0.0f};
  // Clip planes as (n, d - n . origin): keeps n . p <= w for p relative to the origin.
  std::array<std::array<float, 4>, 4> clips{};
  int clipCount = 0;
  bool perspective = false;
  float sizeScale = 0.0f;
};

DrawState makeDrawState(const Framing& framing, std::span<const ClipPlane> clips);

// Uniform locations shared by the three programs' vertex shaders.
struct CommonUniforms {
  GLint view = -1, projection = -1, mirror = -1, clips = -1;
  void find(GLuint program);
  void set(const DrawState& state) const;
};

class ParticlePass {
 public:
  ParticlePass();
  ~ParticlePass();
  // `scale` is null when the layer has no values (then layer.color).
  void draw(const ParticleLayer& layer, const ColorScale* scale, const Framing& framing,
            const DrawState& state);

 private:
  GLuint program_ = 0;
  CommonUniforms common_;
  GLint sizeScale_ = -1, shaded_ = -1;
  gl::StreamBuffer positions_, radii_, colors_;
  std::vector<float> positionData_, radiusData_;
  std::vector<std::uint8_t> colorData_;
};

class MeshPass {
 public:
  MeshPass();
  ~MeshPass();
  void draw(const MeshLayer& layer, const ColorScale* scale, const Framing& framing,
            const DrawState& state);

 private:
  GLuint program_ = 0, lut_ = 0;
  CommonUniforms common_;
  GLint shaded_ = -1, perspective_ = -1, solid_ = -1, useSolid_ = -1, noData_ = -1, lutUnit_ = -1;
  gl::StreamBuffer positions_, normals_, scalars_;
  std::vector<float> positionData_, normalData_, scalarData_;
  std::vector<double> vertexNormals_;
};

class SlicePass {
 public:
  SlicePass();
  ~SlicePass();
  void draw(const SliceLayer& layer, const ColorScale& scale, const Framing& framing,
            const DrawState& state);

 private:
  GLuint program_ = 0, texture_ = 0;
  CommonUniforms common_;
  GLint imageUnit_ = -1;
  gl::StreamBuffer positions_, coordinates_;
  std::vector<std::uint8_t> texels_;
};

}  // namespace ejecta::render::detail
