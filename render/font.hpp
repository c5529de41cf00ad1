#pragma once
// Text in images: a built-in 5 x 7 pixel font (no font files, no FreeType), drawn into an Image
// at an integer scale. Covers printable ASCII and the unit characters ° µ ² ³ · ×; any other
// character is drawn as a box. Text is UTF-8.
#include <string>
#include <string_view>

#include "render/image.hpp"

namespace ejecta::render {

inline constexpr int kGlyphWidth = 5;  // pixels at scale 1
inline constexpr int kGlyphHeight = 7;
inline constexpr int kGlyphAdvance = 6;  // glyph plus one column of space

// The code points of `utf8`; a malformed sequence decodes to U+FFFD.
std::u32string decodeUtf8(std::string_view utf8);

// Width in pixels of `utf8` drawn at `scale` (no trailing space column); 0 for empty text.
int textWidth(std::string_view utf8, int scale);
inline int textHeight(int scale) { return kGlyphHeight * scale; }

// Draws `utf8` with its top-left corner at (x, y), each font pixel a scale x scale square in
// `ink`. Pixels outside the image are skipped.
void drawText(Image& image, int x, int y, std::string_view utf8, int scale, Rgba8 ink);

}  // namespace ejecta::render
