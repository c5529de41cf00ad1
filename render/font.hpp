#pragma once
// Text in images: DejaVu Sans drawn by FreeType, anti-aliased, at a pixel size set by an integer
// scale (scale 1: an 11-pixel em, for 512-pixel images; the renderer picks one scale per 512
// pixels). Where FreeType or the font file is missing (a build without libfreetype-dev, a machine
// without fonts-dejavu-core) the built-in 5 x 7 bitmap font stands in (render/bitmap_font.cpp).
// Text is UTF-8.
#include <string>
#include <string_view>

#include "render/image.hpp"

namespace ejecta::render {

// The code points of `utf8`; a malformed sequence decodes to U+FFFD.
std::u32string decodeUtf8(std::string_view utf8);

// Width in pixels of `utf8` drawn at `scale`; 0 for empty text.
int textWidth(std::string_view utf8, int scale);
// Height in pixels of a line at `scale`: from the font's ascender to its descender, so that
// descenders (g, p, y) and accents fit.
int textHeight(int scale);

// Draws `utf8` with the top-left corner of its line box at (x, y) in `ink`, blended over the
// image by the glyphs' coverage. Pixels outside the image are skipped.
void drawText(Image& image, int x, int y, std::string_view utf8, int scale, Rgba8 ink);

// True when text is drawn with the outline font (FreeType and DejaVu Sans found).
bool outlineFontAvailable();

// The bitmap font itself (the fallback; its own tests). Each font pixel is a scale x scale
// square; 5 x 7 glyphs on a 6-pixel advance.
namespace bitmap {
inline constexpr int kGlyphWidth = 5;
inline constexpr int kGlyphHeight = 7;
inline constexpr int kGlyphAdvance = 6;
int textWidth(std::string_view utf8, int scale);
inline int textHeight(int scale) { return kGlyphHeight * scale; }
void drawText(Image& image, int x, int y, std::string_view utf8, int scale, Rgba8 ink);
}  // namespace bitmap

}  // namespace ejecta::render
