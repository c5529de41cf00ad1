#pragma once
// The bitmap tables of the built-in font (font_glyphs.cpp), for bitmap_font.cpp.
#include <array>
#include <cstdint>

namespace ejecta::render::glyphs {

// 7 rows from the top; bit 4 of a row is the leftmost of its 5 pixels.
using Glyph = std::array<std::uint8_t, 7>;

struct ExtraGlyph {
  char32_t code;
  Glyph rows;
};

inline constexpr int kAsciiCount = 95;  // U+0020 .. U+007E
inline constexpr int kExtraCount = 6;

extern const std::array<Glyph, kAsciiCount> kAscii;
extern const std::array<ExtraGlyph, kExtraCount> kExtra;
extern const Glyph kMissing;

}  // namespace ejecta::render::glyphs
