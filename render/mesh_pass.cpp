// Triangle meshes, lit by a headlight (Lambert, both sides, 20% ambient). The scalar travels to
// the fragment shader as its position on the colour scale and is looked up there in the colour
// map, so that colours between vertices follow the map rather than a straight RGB blend.
#include <cmath>
#include <limits>

#include "render/passes.hpp"

namespace ejecta::render::detail {

namespace {

const char* kVertex = R"(#version 330
uniform mat4 u_view;
uniform mat4 u_projection;
uniform vec2 u_mirror;
uniform vec4 u_clip[4];
in vec3 a_position;
in vec3 a_normal;
in float a_scalar;
out vec3 v_normal;
out vec3 v_eye;
out float v_scalar;
out float gl_ClipDistance[4];
void main() {
  vec3 p = vec3(u_mirror.x * a_position.x + u_mirror.y, a_position.yz);
  vec4 eye = u_view * vec4(p, 1.0);
  gl_Position = u_projection * eye;
  for (int i = 0; i < 4; ++i) gl_ClipDistance[i] = u_clip[i].w - dot(u_clip[i].xyz, p);
  v_eye = eye.xyz;
  v_normal = mat3(u_view) * vec3(u_mirror.x * a_normal.x, a_normal.yz);
  v_scalar = a_scalar;
}
)";

// Scalar < 0: no data. The map's 256 entries sit at texel centres, so t maps to
// (255 t + 0.5) / 256 and linear filtering reproduces ColorMap::at.
const char* kFragment = R"(#version 330
uniform sampler1D u_lut;
uniform int u_shaded;
uniform int u_perspective;
uniform int u_useSolid;
uniform vec3 u_solid;
uniform vec3 u_noData;
in vec3 v_normal;
in vec3 v_eye;
in float v_scalar;
out vec4 fragColor;
void main() {
  vec3 base;
  if (u_useSolid != 0) base = u_solid;
  else if (v_scalar < 0.0) base = u_noData;
  else base = texture(u_lut, (clamp(v_scalar, 0.0, 1.0) * 255.0 + 0.5) / 256.0).rgb;
  float shade = 1.0;
  if (u_shaded != 0) {
    vec3 n = normalize(v_normal);
    vec3 l = u_perspective != 0 ? normalize(-v_eye) : vec3(0.0, 0.0, 1.0);
    shade = 0.2 + 0.8 * abs(dot(n, l));
  }
  fragColor = vec4(base * shade, 1.0);
}
)";

Vec3 faceNormal(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

void putUnit(float* out, const double* n) {
  const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  const double inv = length > 0.0 ? 1.0 / length : 0.0;
  for (int k = 0; k < 3; ++k) out[k] = static_cast<float>(n[k] * inv);
}

}  // namespace

MeshPass::MeshPass() {
  program_ =
      gl::buildProgram(kVertex, kFragment, {{0, "a_position"}, {1, "a_normal"}, {2, "a_scalar"}});
  common_.find(program_);
  shaded_ = glGetUniformLocation(program_, "u_shaded");
  perspective_ = glGetUniformLocation(program_, "u_perspective");
  solid_ = glGetUniformLocation(program_, "u_solid");
  useSolid_ = glGetUniformLocation(program_, "u_useSolid");
  noData_ = glGetUniformLocation(program_, "u_noData");
  lutUnit_ = glGetUniformLocation(program_, "u_lut");
  glGenTextures(1, &lut_);
}

MeshPass::~MeshPass() {
  glDeleteTextures(1, &lut_);
  glDeleteProgram(program_);
}

void MeshPass::draw(const MeshLayer& layer, const ColorScale* scale, const Framing& framing,
                    const DrawState& state) {
  const std::size_t nt = layer.triangles.size();
  if (nt == 0) return;
  const bool perTriangle = !layer.triangleValues.empty();
  const bool smooth = layer.smoothNormals && !perTriangle;
  if (smooth) {
    // Area-weighted sums of the faces' normals at each vertex (the cross product's length is
    // twice the area). Serial: vertices are shared between triangles.
    vertexNormals_.assign(layer.vertices.size() * 3, 0.0);
    for (const auto& t : layer.triangles) {
      const Vec3 n = faceNormal(layer.vertices[t[0]], layer.vertices[t[1]], layer.vertices[t[2]]);
      for (std::uint32_t v : t)
        for (int k = 0; k < 3; ++k) vertexNormals_[3 * v + static_cast<std::size_t>(k)] += n[k];
    }
  }
  positionData_.resize(nt * 9);
  normalData_.resize(nt * 9);
  scalarData_.resize(nt * 3);
  const Vec3 o = framing.origin;
  auto onScale = [&](double v) -> float {
    if (!scale) return 0.0f;
    const double t = scale->normalise(v);
    return std::isnan(t) ? -1.0f : static_cast<float>(t);
  };
  const auto count = static_cast<std::ptrdiff_t>(nt);
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t ti = 0; ti < count; ++ti) {
    const auto t = static_cast<std::size_t>(ti);
    const auto& tri = layer.triangles[t];
    const Vec3 face =
        faceNormal(layer.vertices[tri[0]], layer.vertices[tri[1]], layer.vertices[tri[2]]);
    for (std::size_t c = 0; c < 3; ++c) {
      const std::size_t corner = 3 * t + c;
      const Vec3& p = layer.vertices[tri[c]];
      for (std::size_t k = 0; k < 3; ++k)
        positionData_[3 * corner + k] = static_cast<float>(p[k] - o[k]);
      putUnit(&normalData_[3 * corner], smooth ? &vertexNormals_[3 * tri[c]] : face.data());
      scalarData_[corner] = perTriangle                   ? onScale(layer.triangleValues[t])
                            : !layer.vertexValues.empty() ? onScale(layer.vertexValues[tri[c]])
                                                          : 0.0f;
    }
  }
  glUseProgram(program_);
  common_.set(state);
  glUniform1i(shaded_, layer.shaded ? 1 : 0);
  glUniform1i(perspective_, state.perspective ? 1 : 0);
  glUniform1i(useSolid_, scale ? 0 : 1);
  glUniform3f(solid_, layer.color.r, layer.color.g, layer.color.b);
  glUniform3f(noData_, ColorScale::kNoData.r, ColorScale::kNoData.g, ColorScale::kNoData.b);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_1D, lut_);
  if (scale) {
    std::vector<float> table;
    table.reserve(ColorMap::kEntries * 4);
    for (const Rgb& c : scale->map().table()) table.insert(table.end(), {c.r, c.g, c.b, 1.0f});
    glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA32F, ColorMap::kEntries, 0, GL_RGBA, GL_FLOAT,
                 table.data());
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  }
  glUniform1i(lutUnit_, 0);
  positions_.upload(positionData_.data(), positionData_.size() * sizeof(float));
  gl::attribute(0, 3, GL_FLOAT, false);
  normals_.upload(normalData_.data(), normalData_.size() * sizeof(float));
  gl::attribute(1, 3, GL_FLOAT, false);
  scalars_.upload(scalarData_.data(), scalarData_.size() * sizeof(float));
  gl::attribute(2, 1, GL_FLOAT, false);
  const auto vertices = static_cast<GLsizei>(nt * 3);
  glDrawArrays(GL_TRIANGLES, 0, vertices);
  if (framing.mirror) {
    DrawState mirrored = state;
    mirrored.mirror = {-1.0f, static_cast<float>(-2.0 * o[0])};
    common_.set(mirrored);
    glDrawArrays(GL_TRIANGLES, 0, vertices);
  }
  for (GLuint a = 0; a < 3; ++a) glDisableVertexAttribArray(a);
  gl::check("drawing a mesh");
}

}  // namespace ejecta::render::detail
