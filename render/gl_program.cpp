#include "render/gl_program.hpp"

#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace ejecta::render::gl {

namespace {

std::string shaderLog(GLuint shader) {
  GLint length = 0;
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> text(static_cast<std::size_t>(length) + 1, '\0');
  glGetShaderInfoLog(shader, length, nullptr, text.data());
  return text.data();
}

GLuint compile(GLenum kind, const char* source) {
  const GLuint shader = glCreateShader(kind);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    const std::string log = shaderLog(shader);
    glDeleteShader(shader);
    throw std::runtime_error(std::string("GL ") +
                             (kind == GL_VERTEX_SHADER ? "vertex" : "fragment") +
                             " shader does not compile: " + log);
  }
  return shader;
}

}  // namespace

GLuint buildProgram(const char* vertexSource, const char* fragmentSource,
                    std::initializer_list<std::pair<GLuint, const char*>> attributes) {
  const GLuint vs = compile(GL_VERTEX_SHADER, vertexSource);
  GLuint fs = 0;
  try {
    fs = compile(GL_FRAGMENT_SHADER, fragmentSource);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  const GLuint program = glCreateProgram();
  glAttachShader(program, vs);
  glAttachShader(program, fs);
  for (const auto& [location, name] : attributes) glBindAttribLocation(program, location, name);
  glBindFragDataLocation(program, 0, "fragColor");
  glLinkProgram(program);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> text(static_cast<std::size_t>(length) + 1, '\0');
    glGetProgramInfoLog(program, length, nullptr, text.data());
    glDeleteProgram(program);
    throw std::runtime_error(std::string("GL program does not link: ") + text.data());
  }
  return program;
}

StreamBuffer::~StreamBuffer() {
  if (id_) glDeleteBuffers(1, &id_);
}

void StreamBuffer::upload(const void* data, std::size_t bytes) {
  if (!id_) glGenBuffers(1, &id_);
  glBindBuffer(GL_ARRAY_BUFFER, id_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(bytes), data, GL_STREAM_DRAW);
}

void attribute(GLuint location, int components, GLenum type, bool normalized) {
  glEnableVertexAttribArray(location);
  glVertexAttribPointer(location, components, type, normalized ? GL_TRUE : GL_FALSE, 0, nullptr);
}

void check(const char* where) {
  const GLenum error = glGetError();
  if (error == GL_NO_ERROR) return;
  char code[16];
  std::snprintf(code, sizeof code, "0x%04x", static_cast<unsigned>(error));
  throw std::runtime_error(std::string("OpenGL error ") + code + " in " + where);
}

}  // namespace ejecta::render::gl
