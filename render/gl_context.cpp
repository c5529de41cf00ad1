#include "render/gl_context.hpp"

#include <GL/osmesa.h>

#include <cstdio>
#include <stdexcept>
#include <string>

namespace ejecta::render {

OffscreenContext::OffscreenContext(int width, int height) {
  // RGBA, 24-bit depth, no stencil or accumulation buffer, no shared lists.
  context_ = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
  if (!context_) throw std::runtime_error("OSMesa could not create an off-screen GL context");
  try {
    resize(width, height);
    const auto text = [](GLenum name) {
      const auto* s = reinterpret_cast<const char*>(glGetString(name));
      return std::string(s ? s : "");
    };
    renderer_ = text(GL_RENDERER);
    version_ = text(GL_VERSION);
    int major = 0, minor = 0;
    if (std::sscanf(version_.c_str(), "%d.%d", &major, &minor) != 2 || major * 10 + minor < 33)
      throw std::runtime_error("OSMesa gives OpenGL '" + version_ + "'; ejecta needs 3.3");
  } catch (...) {
    OSMesaDestroyContext(context_);
    throw;
  }
}

OffscreenContext::~OffscreenContext() { OSMesaDestroyContext(context_); }

void OffscreenContext::makeCurrent() {
  if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_))
    throw std::runtime_error("OSMesa could not make the context current");
  // Rows from the top, as images and PNG files store them: no flip afterwards.
  OSMesaPixelStore(OSMESA_Y_UP, 0);
}

void OffscreenContext::resize(int width, int height) {
  if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
    throw std::invalid_argument("image size " + std::to_string(width) + " x " +
                                std::to_string(height) + " is outside 1..16384");
  width_ = width;
  height_ = height;
  buffer_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4, 0);
  makeCurrent();
}

}  // namespace ejecta::render
