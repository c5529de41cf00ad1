// A slice as one textured quad: the cells' colours are computed on the CPU by the colour scale
// into an RGBA texture (alpha 0 where there is no data), sampled without filtering, so each
// cell is one flat colour with sharp edges.
#include <stdexcept>
#include <string>

#include "render/passes.hpp"

namespace ejecta::render::detail {

namespace {

const char* kVertex = R"(#version 330
uniform mat4 u_view;
uniform mat4 u_projection;
uniform vec2 u_mirror;
uniform vec4 u_clip[4];
in vec3 a_position;
in vec2 a_coordinate;
out vec2 v_coordinate;
out float gl_ClipDistance[4];
void main() {
  vec3 p = vec3(u_mirror.x * a_position.x + u_mirror.y, a_position.yz);
  gl_Position = u_projection * (u_view * vec4(p, 1.0));
  for (int i = 0; i < 4; ++i) gl_ClipDistance[i] = u_clip[i].w - dot(u_clip[i].xyz, p);
  v_coordinate = a_coordinate;
}
)";

const char* kFragment = R"(#version 330
uniform sampler2D u_image;
in vec2 v_coordinate;
out vec4 fragColor;
void main() {
  vec4 c = texture(u_image, v_coordinate);
  if (c.a < 0.5) discard;
  fragColor = vec4(c.rgb, 1.0);
}
)";

}  // namespace

SlicePass::SlicePass() {
  program_ = gl::buildProgram(kVertex, kFragment, {{0, "a_position"}, {1, "a_coordinate"}});
  common_.find(program_);
  imageUnit_ = glGetUniformLocation(program_, "u_image");
  glGenTextures(1, &texture_);
}

SlicePass::~SlicePass() {
  glDeleteTextures(1, &texture_);
  glDeleteProgram(program_);
}

void SlicePass::draw(const SliceLayer& layer, const ColorScale& scale, const Framing& framing,
                     const DrawState& state) {
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  if (layer.nx > maxSize || layer.ny > maxSize)
    throw std::invalid_argument("slice of " + std::to_string(layer.nx) + " x " +
                                std::to_string(layer.ny) + " cells exceeds OpenGL's " +
                                std::to_string(maxSize) + " texels per side");
  const std::size_t cells = layer.values.size();
  texels_.resize(cells * 4);
  const auto count = static_cast<std::ptrdiff_t>(cells);
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t i = 0; i < count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const double v = layer.values[k];
    const Rgba8 c = toRgba8(scale.color(v));
    texels_[4 * k] = c.r;
    texels_[4 * k + 1] = c.g;
    texels_[4 * k + 2] = c.b;
    texels_[4 * k + 3] = v == v ? 255 : 0;  // NaN: no data, transparent
  }
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, texture_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, layer.nx, layer.ny, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               texels_.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);

  // Corners in the order of sliceCorners: (lo, lo), (hi, lo), (lo, hi), (hi, hi): a strip.
  const auto corners = sliceCorners(layer);
  const Vec3 o = framing.origin;
  float positions[12];
  for (std::size_t c = 0; c < 4; ++c)
    for (std::size_t k = 0; k < 3; ++k)
      positions[3 * c + k] = static_cast<float>(corners[c][k] - o[k]);
  const float coordinates[8] = {0, 0, 1, 0, 0, 1, 1, 1};
  glUseProgram(program_);
  common_.set(state);
  glUniform1i(imageUnit_, 0);
  positions_.upload(positions, sizeof positions);
  gl::attribute(0, 3, GL_FLOAT, false);
  coordinates_.upload(coordinates, sizeof coordinates);
  gl::attribute(1, 2, GL_FLOAT, false);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  if (framing.mirror) {
    DrawState mirrored = state;
    mirrored.mirror = {-1.0f, static_cast<float>(-2.0 * o[0])};
    common_.set(mirrored);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  }
  for (GLuint a = 0; a < 2; ++a) glDisableVertexAttribArray(a);
  gl::check("drawing a slice");
}

}  // namespace ejecta::render::detail
