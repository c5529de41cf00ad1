// The built-in 5 x 7 bitmap font: the fallback when the outline font is missing
// (render/font.hpp), and the UTF-8 decoder both use.
#include "render/font.hpp"

#include <algorithm>

#include "render/font_glyphs.hpp"

namespace ejecta::render {

namespace {

const glyphs::Glyph& glyphFor(char32_t c) {
  if (c >= 0x20 && c < 0x20 + glyphs::kAsciiCount) return glyphs::kAscii[c - 0x20];
  for (const auto& extra : glyphs::kExtra)
    if (extra.code == c) return extra.rows;
  return glyphs::kMissing;
}

}  // namespace

std::u32string decodeUtf8(std::string_view utf8) {
  std::u32string out;
  constexpr char32_t kReplacement = 0xFFFD;
  for (std::size_t i = 0; i < utf8.size();) {
    const auto lead = static_cast<unsigned char>(utf8[i]);
    int extra = 0;
    char32_t code = 0;
    if (lead < 0x80) {
      code = lead;
    } else if ((lead & 0xE0) == 0xC0) {
      extra = 1;
      code = lead & 0x1F;
    } else if ((lead & 0xF0) == 0xE0) {
      extra = 2;
      code = lead & 0x0F;
    } else if ((lead & 0xF8) == 0xF0) {
      extra = 3;
      code = lead & 0x07;
    } else {
      out.push_back(kReplacement);
      ++i;
      continue;
    }
    bool valid = i + static_cast<std::size_t>(extra) < utf8.size();
    for (int k = 1; valid && k <= extra; ++k) {
      const auto next = static_cast<unsigned char>(utf8[i + static_cast<std::size_t>(k)]);
      if ((next & 0xC0) != 0x80)
        valid = false;
      else
        code = (code << 6) | (next & 0x3F);
    }
    if (!valid) {
      out.push_back(kReplacement);
      ++i;
      continue;
    }
    out.push_back(code);
    i += static_cast<std::size_t>(extra) + 1;
  }
  return out;
}

namespace bitmap {

int textWidth(std::string_view utf8, int scale) {
  const auto count = static_cast<int>(decodeUtf8(utf8).size());
  return count == 0 ? 0 : (count * kGlyphAdvance - 1) * scale;
}

void drawText(Image& image, int x, int y, std::string_view utf8, int scale, Rgba8 ink) {
  int penX = x;
  for (char32_t c : decodeUtf8(utf8)) {
    const glyphs::Glyph& g = glyphFor(c);
    for (int row = 0; row < kGlyphHeight; ++row)
      for (int col = 0; col < kGlyphWidth; ++col)
        if (g[static_cast<std::size_t>(row)] & (0x10 >> col))
          image.fillRect(penX + col * scale, y + row * scale, penX + (col + 1) * scale,
                         y + (row + 1) * scale, ink);
    penX += kGlyphAdvance * scale;
  }
}

}  // namespace bitmap

}  // namespace ejecta::render
