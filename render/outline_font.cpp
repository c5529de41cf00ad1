// Text through FreeType with DejaVu Sans (render/font.hpp); the bitmap font when either is
// missing. The face is opened once, on first use, and shared: FreeType faces are not safe to
// use from two threads at once, so every use holds its lock.
#include <algorithm>
#include <cmath>
#include <mutex>

#include "render/font.hpp"

#if EJECTA_HAVE_FREETYPE
#include <ft2build.h>
#include FT_FREETYPE_H
#endif

namespace ejecta::render {

namespace {

constexpr int kEmPixels = 11;  // the em at scale 1

#if EJECTA_HAVE_FREETYPE
class OutlineFont {
 public:
  static OutlineFont& instance() {
    static OutlineFont font;
    return font;
  }
  bool ok() const { return face_ != nullptr; }

  int width(std::string_view utf8, int scale) {
    const std::lock_guard<std::mutex> lock(mutex_);
    size(scale);
    long advance = 0;
    for (const char32_t c : decodeUtf8(utf8))
      if (FT_Load_Char(face_, c, FT_LOAD_NO_BITMAP) == 0) advance += face_->glyph->advance.x;
    return static_cast<int>((advance + 63) >> 6);
  }

  int height(int scale) {
    const std::lock_guard<std::mutex> lock(mutex_);
    size(scale);
    return static_cast<int>((face_->size->metrics.ascender - face_->size->metrics.descender + 63) >> 6);
  }

  void draw(Image& image, int x, int y, std::string_view utf8, int scale, Rgba8 ink) {
    const std::lock_guard<std::mutex> lock(mutex_);
    size(scale);
    const long baseline = y + ((face_->size->metrics.ascender + 63) >> 6);
    long pen = static_cast<long>(x) << 6;  // 26.6 fixed point: sub-pixel advances add up
    for (const char32_t c : decodeUtf8(utf8)) {
      // Outlines only (no embedded bitmaps), rendered as 8-bit coverage.
      if (FT_Load_Char(face_, c, FT_LOAD_RENDER | FT_LOAD_NO_BITMAP) != 0) continue;
      const FT_GlyphSlot g = face_->glyph;
      const FT_Bitmap& b = g->bitmap;
      if (b.pixel_mode != FT_PIXEL_MODE_GRAY || b.pitch < 0) {
        pen += g->advance.x;
        continue;
      }
      const long left = (pen >> 6) + g->bitmap_left, top = baseline - g->bitmap_top;
      for (unsigned row = 0; row < b.rows; ++row)
        for (unsigned col = 0; col < b.width; ++col) {
          const int px = static_cast<int>(left + col), py = static_cast<int>(top + row);
          const unsigned coverage = b.buffer[row * static_cast<unsigned>(b.pitch) + col];
          if (coverage == 0 || !image.contains(px, py)) continue;
          image.set(px, py, blend(image.at(px, py), ink, coverage));
        }
      pen += g->advance.x;
    }
  }

 private:
  OutlineFont() {
    if (FT_Init_FreeType(&library_) != 0) {
      library_ = nullptr;
      return;
    }
    if (FT_New_Face(library_, EJECTA_FONT_FILE, 0, &face_) != 0) face_ = nullptr;
  }
  ~OutlineFont() {
    if (face_) FT_Done_Face(face_);
    if (library_) FT_Done_FreeType(library_);
  }
  void size(int scale) {
    if (scale != sized_) FT_Set_Pixel_Sizes(face_, 0, static_cast<FT_UInt>(kEmPixels * std::max(1, scale)));
    sized_ = scale;
  }
  static Rgba8 blend(Rgba8 under, Rgba8 ink, unsigned coverage) {
    const auto mix = [coverage](std::uint8_t a, std::uint8_t b) {
      return static_cast<std::uint8_t>((a * (255u - coverage) + b * coverage + 127u) / 255u);
    };
    return {mix(under.r, ink.r), mix(under.g, ink.g), mix(under.b, ink.b), under.a};
  }

  FT_Library library_ = nullptr;
  FT_Face face_ = nullptr;
  int sized_ = 0;
  std::mutex mutex_;
};
#endif

}  // namespace

bool outlineFontAvailable() {
#if EJECTA_HAVE_FREETYPE
  return OutlineFont::instance().ok();
#else
  return false;
#endif
}

int textWidth(std::string_view utf8, int scale) {
#if EJECTA_HAVE_FREETYPE
  if (OutlineFont::instance().ok()) return OutlineFont::instance().width(utf8, scale);
#endif
  return bitmap::textWidth(utf8, scale);
}

int textHeight(int scale) {
#if EJECTA_HAVE_FREETYPE
  if (OutlineFont::instance().ok()) return OutlineFont::instance().height(scale);
#endif
  return bitmap::textHeight(scale);
}

void drawText(Image& image, int x, int y, std::string_view utf8, int scale, Rgba8 ink) {
#if EJECTA_HAVE_FREETYPE
  if (OutlineFont::instance().ok()) return OutlineFont::instance().draw(image, x, y, utf8, scale, ink);
#endif
  bitmap::drawText(image, x, y, utf8, scale, ink);
}

}  // namespace ejecta::render
