// Radiance's polygonal fonts (lib/helvet.fnt and its kin), as the text patterns brighttext,
// colortext and mixtext use them. The format, as Radiance's src/common/font.c (getfont) reads it:
// white-space separated integers, '#' starting a comment to the end of the line (fgetval), a
// glyph at a time: its character code (1–255, each at most once), its number of vertices
// (0–32000; 0 is a glyph with no outline, a space) and that many x y pairs on a 256 × 256 grid
// (0–255, y up). A glyph is one outline (holes are joined to it by seams); a point is inside it by
// the even-odd rule (src/rt/text.c, inglyph). Written anew for candela from that format.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace candela {

// One glyph: its outline and the box font.c keeps of it. The box starts at 128 on all four sides
// and widens to the vertices (font.c), so it always holds x = y = 128: the spacing of text
// (squeezed and proportional) and the font's mean width use this box as Radiance does.
struct RadGlyph {
  std::vector<int16_t> xy;  // x0 y0 x1 y1 ... (0..255)
  int left = 128, right = 128, bottom = 128, top = 128;
  size_t vertices() const { return xy.size() / 2; }
};

struct RadFont {
  std::array<int32_t, 256> index{};  // into glyphs, -1 for a character without a glyph
  std::vector<RadGlyph> glyphs;
  // The mean width (right − left) of the glyphs whose box has width and height, in integer
  // division as font.c's mwidth; 0 when there is none.
  int meanWidth = 0;

  RadFont() { index.fill(-1); }
  const RadGlyph* glyph(unsigned char c) const { return index[c] < 0 ? nullptr : &glyphs[static_cast<size_t>(index[c])]; }
};

// The most vertices a glyph may have (font.c's limit).
inline constexpr int kMaxGlyphVertices = 32000;
// The largest font file candela reads (bytes): Radiance's own fonts are below 100 kB.
inline constexpr std::uintmax_t kMaxFontFileBytes = std::uintmax_t(4) << 20;

// Parses a font file's text (`file` names it in errors). InputError at the offending word's line
// for a word that is not an integer, a character code outside 1–255 or given twice, a vertex
// count outside 0–32000 or a vertex outside 0–255, and a file that ends inside a glyph. Memory
// grows with the words read, never with a count the file states.
RadFont parseRadianceFont(std::string_view text, const std::string& file);

// Whether (x, y), real coordinates on the glyph's grid (0 ≤ x, y < 256), is inside glyph g (none:
// never): Radiance's inglyph, its box tested on the integer cell of the point, then the crossings
// of a ray from the cell's centre along +x counted (odd: inside), a crossing near the point
// decided by the point itself.
bool insideGlyph(const RadGlyph* g, double x, double y);

}  // namespace candela
