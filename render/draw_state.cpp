#include <cstddef>

#include "render/passes.hpp"

namespace ejecta::render::detail {

DrawState makeDrawState(const Framing& framing, std::span<const ClipPlane> clips) {
  DrawState s;
  for (std::size_t i = 0; i < 16; ++i) {
    s.view[i] = static_cast<float>(framing.view[i]);
    s.projection[i] = static_cast<float>(framing.projection[i]);
  }
  s.clipCount = static_cast<int>(clips.size());
  for (std::size_t c = 0; c < clips.size() && c < 4; ++c) {
    const Vec3& n = clips[c].normal;
    const Vec3& o = framing.origin;
    s.clips[c] = {static_cast<float>(n[0]), static_cast<float>(n[1]), static_cast<float>(n[2]),
                  static_cast<float>(clips[c].offset - (n[0] * o[0] + n[1] * o[1] + n[2] * o[2]))};
  }
  s.perspective = framing.perspective;
  s.sizeScale = static_cast<float>(framing.sizeScale);
  return s;
}

void CommonUniforms::find(GLuint program) {
  view = glGetUniformLocation(program, "u_view");
  projection = glGetUniformLocation(program, "u_projection");
  mirror = glGetUniformLocation(program, "u_mirror");
  clips = glGetUniformLocation(program, "u_clip");
}

void CommonUniforms::set(const DrawState& state) const {
  glUniformMatrix4fv(view, 1, GL_FALSE, state.view.data());
  glUniformMatrix4fv(projection, 1, GL_FALSE, state.projection.data());
  glUniform2f(mirror, state.mirror[0], state.mirror[1]);
  glUniform4fv(clips, 4, state.clips[0].data());
}

}  // namespace ejecta::render::detail
