// Particles as point sprites: one vertex per particle, its size in pixels set by the vertex
// shader from the particle's radius and depth, the disc cut out and lit in the fragment shader
// (gl_PointCoord). llvmpipe caps a point at 255 pixels across: nearer particles stop growing.
#include <cmath>

#include "render/passes.hpp"

namespace ejecta::render::detail {

namespace {

const char* kVertex = R"(#version 330
uniform mat4 u_view;
uniform mat4 u_projection;
uniform vec2 u_mirror;
uniform vec4 u_clip[4];
uniform float u_sizeScale;
in vec3 a_position;
in float a_radius;
in vec4 a_color;
flat out vec4 v_color;
out float gl_ClipDistance[4];
void main() {
  vec3 p = vec3(u_mirror.x * a_position.x + u_mirror.y, a_position.yz);
  vec4 clip = u_projection * (u_view * vec4(p, 1.0));
  gl_Position = clip;
  gl_PointSize = max(2.0 * a_radius * u_sizeScale / clip.w, 1.0);
  for (int i = 0; i < 4; ++i) gl_ClipDistance[i] = u_clip[i].w - dot(u_clip[i].xyz, p);
  v_color = a_color;
}
)";

// Shaded: the disc is a sphere lit by a headlight, so brightness is the normal's component
// towards the viewer, sqrt(1 - r^2), over a 25% ambient floor.
const char* kFragment = R"(#version 330
uniform int u_shaded;
flat in vec4 v_color;
out vec4 fragColor;
void main() {
  vec2 d = gl_PointCoord * 2.0 - 1.0;
  float r2 = dot(d, d);
  if (r2 > 1.0) discard;
  float shade = u_shaded != 0 ? 0.25 + 0.75 * sqrt(1.0 - r2) : 1.0;
  fragColor = vec4(v_color.rgb * shade, 1.0);
}
)";

std::uint8_t byte(float v) { return static_cast<std::uint8_t>(std::lround(v * 255.0f)); }

}  // namespace

ParticlePass::ParticlePass() {
  program_ =
      gl::buildProgram(kVertex, kFragment, {{0, "a_position"}, {1, "a_radius"}, {2, "a_color"}});
  common_.find(program_);
  sizeScale_ = glGetUniformLocation(program_, "u_sizeScale");
  shaded_ = glGetUniformLocation(program_, "u_shaded");
}

ParticlePass::~ParticlePass() { glDeleteProgram(program_); }

void ParticlePass::draw(const ParticleLayer& layer, const ColorScale* scale, const Framing& framing,
                        const DrawState& state) {
  const auto n = static_cast<std::ptrdiff_t>(layer.x.size());
  if (n == 0) return;
  positionData_.resize(static_cast<std::size_t>(n) * 3);
  radiusData_.resize(static_cast<std::size_t>(n));
  colorData_.resize(static_cast<std::size_t>(n) * 4);
  const Vec3 o = framing.origin;
  const bool hasZ = !layer.z.empty();
  const Rgba8 solid = toRgba8(layer.color);
  // Single precision relative to the framing's origin; colours from the scale on the CPU, so
  // that the picture's colours are exactly ColorScale::color.
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    positionData_[3 * k] = static_cast<float>(layer.x[k] - o[0]);
    positionData_[3 * k + 1] = static_cast<float>(layer.y[k] - o[1]);
    positionData_[3 * k + 2] = static_cast<float>((hasZ ? layer.z[k] : 0.0) - o[2]);
    radiusData_[k] = static_cast<float>(layer.discRadius(k));
    if (scale) {
      const Rgb c = scale->color(layer.values[k]);
      colorData_[4 * k] = byte(c.r);
      colorData_[4 * k + 1] = byte(c.g);
      colorData_[4 * k + 2] = byte(c.b);
    } else {
      colorData_[4 * k] = solid.r;
      colorData_[4 * k + 1] = solid.g;
      colorData_[4 * k + 2] = solid.b;
    }
    colorData_[4 * k + 3] = 255;
  }
  glUseProgram(program_);
  common_.set(state);
  glUniform1f(sizeScale_, state.sizeScale);
  glUniform1i(shaded_, layer.style == ParticleStyle::Shaded ? 1 : 0);
  positions_.upload(positionData_.data(), positionData_.size() * sizeof(float));
  gl::attribute(0, 3, GL_FLOAT, false);
  radii_.upload(radiusData_.data(), radiusData_.size() * sizeof(float));
  gl::attribute(1, 1, GL_FLOAT, false);
  colors_.upload(colorData_.data(), colorData_.size());
  gl::attribute(2, 4, GL_UNSIGNED_BYTE, true);
  glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(n));
  if (framing.mirror) {
    DrawState mirrored = state;
    mirrored.mirror = {-1.0f, static_cast<float>(-2.0 * o[0])};
    common_.set(mirrored);
    glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(n));
  }
  for (GLuint a = 0; a < 3; ++a) glDisableVertexAttribArray(a);
  gl::check("drawing particles");
}

}  // namespace ejecta::render::detail
