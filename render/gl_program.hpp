#pragma once
// OpenGL helpers for the renderer's passes (internal: includes the GL headers, which the
// library's public headers keep out).
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <initializer_list>
#include <utility>

namespace ejecta::render::gl {

// Compiles and links a program, binding the named attributes to the given locations and the
// fragment output `fragColor` to 0. Throws std::runtime_error with the driver's log.
GLuint buildProgram(const char* vertexSource, const char* fragmentSource,
                    std::initializer_list<std::pair<GLuint, const char*>> attributes);

// A buffer object that is refilled every frame.
class StreamBuffer {
 public:
  StreamBuffer() = default;
  ~StreamBuffer();
  StreamBuffer(const StreamBuffer&) = delete;
  StreamBuffer& operator=(const StreamBuffer&) = delete;
  // Uploads `bytes` bytes and leaves the buffer bound to GL_ARRAY_BUFFER.
  void upload(const void* data, std::size_t bytes);

 private:
  GLuint id_ = 0;
};

// Binds the bound GL_ARRAY_BUFFER as attribute `location` of `components` values of `type`.
void attribute(GLuint location, int components, GLenum type, bool normalized);

// Throws std::runtime_error naming `where` if OpenGL reports an error.
void check(const char* where);

}  // namespace ejecta::render::gl
