#pragma once
// An off-screen OpenGL context (OSMesa, Mesa's llvmpipe rasteriser: no display, no GPU) that
// draws into a buffer in memory. llvmpipe reads LP_NUM_THREADS (its rasteriser threads) once,
// when the process creates its first context: set it before that.
#include <cstdint>
#include <string>
#include <vector>

struct osmesa_context;  // OSMesa's handle type, kept out of this header

namespace ejecta::render {

class OffscreenContext {
 public:
  // An RGBA context with a 24-bit depth buffer, OpenGL 3.3 or later (llvmpipe gives 4.5
  // compatibility). Throws std::runtime_error when OSMesa cannot create it or the GL version is
  // too old.
  OffscreenContext(int width, int height);
  ~OffscreenContext();
  OffscreenContext(const OffscreenContext&) = delete;
  OffscreenContext& operator=(const OffscreenContext&) = delete;

  // Binds the context to the calling thread (a context is current on one thread at a time).
  void makeCurrent();
  // A new size; the buffer's contents are lost. The context is current afterwards.
  void resize(int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }
  // RGBA bytes of the last finished drawing (after glFinish), top row first.
  const std::vector<std::uint8_t>& pixels() const { return buffer_; }
  // "llvmpipe (LLVM 15.0.6, 256 bits)" and "4.5 (Compatibility Profile) Mesa 22.3.6".
  const std::string& rendererName() const { return renderer_; }
  const std::string& version() const { return version_; }

 private:
  osmesa_context* context_ = nullptr;
  std::vector<std::uint8_t> buffer_;
  int width_ = 0, height_ = 0;
  std::string renderer_, version_;
};

}  // namespace ejecta::render
