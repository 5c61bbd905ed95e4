#include "engine/radiance/font.h"

#include "base/error.h"
#include "engine/radiance/words.h"


namespace candela {

RadFont parseRadianceFont(std::string_view text, const std::string& file) {
  RadFont font;
  RadWords w(text, file, "the font file");
  unsigned long widthSum = 0, counted = 0;
  for (std::string_view word; w.next(word);) {
    const long code = w.integer(word, "a character code");
    if (code < 1 || code > 255) w.fail("character code " + std::to_string(code) + " is outside 1-255");
    if (font.index[static_cast<size_t>(code)] >= 0) w.fail("character " + std::to_string(code) + " is given twice");
    const std::string of = "character " + std::to_string(code);
    const long n = w.integer("the number of vertices of " + of);
    if (n < 0 || n > kMaxGlyphVertices)
      w.fail("the number of vertices of " + of + " is " + std::to_string(n) + ", outside 0-" +
             std::to_string(kMaxGlyphVertices));
    RadGlyph g;
    // Vertices are appended as they are read: a count the file does not back with words
    // allocates nothing.
    for (long k = 0; k < 2 * n; ++k) {
      const bool isX = k % 2 == 0;
      const long v = w.integer(std::string(isX ? "an x" : "a y") + " coordinate of " + of);
      if (v < 0 || v > 255) w.fail("a vertex of " + of + " is " + std::to_string(v) + ", outside 0-255");
      g.xy.push_back(static_cast<int16_t>(v));
      const int iv = static_cast<int>(v);
      if (isX) {
        g.left = std::min(g.left, iv);
        g.right = std::max(g.right, iv);
      } else {
        g.bottom = std::min(g.bottom, iv);
        g.top = std::max(g.top, iv);
      }
    }
    if (g.right != g.left && g.top != g.bottom) {
      ++counted;
      widthSum += static_cast<unsigned long>(g.right - g.left);
    }
    font.index[static_cast<size_t>(code)] = static_cast<int32_t>(font.glyphs.size());
    font.glyphs.push_back(std::move(g));
  }
  if (counted > 0) font.meanWidth = static_cast<int>(widthSum / counted);
  return font;
}

bool insideGlyph(const RadGlyph* g, double x, double y) {
  if (!g) return false;
  const int xc = static_cast<int>(x), yc = static_cast<int>(y);
  if (g->left > xc || g->right <= xc || g->bottom > yc || g->top <= yc) return false;
  // The ray starts at the centre of the point's cell (twice the coordinates plus one, so that no
  // vertex is ever level with it or on it); an edge that straddles its level and lies partly to
  // the right is decided by the side of the edge the point itself is on (text.c's inglyph).
  const int x2 = 2 * xc + 1, y2 = 2 * yc + 1;
  const size_t n = g->vertices();
  int crossings = 0;
  for (size_t k = 0; k < n; ++k) {
    const size_t j = (k + n - 1) % n;  // the edge from the previous vertex (the last for the first)
    const int x0 = g->xy[2 * j], y0 = g->xy[2 * j + 1], x1 = g->xy[2 * k], y1 = g->xy[2 * k + 1];
    if ((2 * y0 > y2) == (2 * y1 > y2)) continue;
    const bool r0 = 2 * x0 > x2, r1 = 2 * x1 > x2;
    if (r0 && r1) {
      ++crossings;
    } else if (r0 || r1) {
      const bool left = (y0 - y) * (x1 - x) > (x0 - x) * (y1 - y);
      crossings += (y1 > y0) != left ? 1 : 0;
    }
  }
  return crossings % 2 == 1;
}

}  // namespace candela
