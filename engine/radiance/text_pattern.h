// Radiance's text patterns and mixture (reference manual, "Brighttext", "Colortext", "Mixtext";
// src/rt/text.c for their semantics, src/common/font.c for the spacing of a line), written anew
// for candela:
//   mod brighttext id 2 fontfile textfile 0 11+ Ox Oy Oz Rx Ry Rz Dx Dy Dz fore back [spacing]
//   mod brighttext id 2+N fontfile . word1 … wordN 0 11+ …          (one line, written inline)
//   mod colortext  id 2(+N) … 0 15+ O R D rf gf bf rb gb bb [spacing]
//   void mixtext   id 4(+N) foreground background fontfile textfile|. … 0 9+ O R D [spacing]
// The text starts at the upper left corner O; R is one character to the right and D one line
// down. A point is taken into the text's plane along the normal of that plane (its coordinates
// on R and D, as text.c's dual vectors), so the pattern extends through space in that direction.
#pragma once

#include "base/units.h"
#include "engine/radiance/font.h"
#include "engine/radiance/parse.h"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace candela {

class FunctionFiles;
struct ScenePattern;

// One line of text laid out: its characters, the offsets of their cells (character k's cell
// starts at the sum of offsets 0..k on the font's 256-unit grid; one more offset closes the line)
// and its width (the sum of all offsets).
struct TextLine {
  std::string chars;
  std::vector<int64_t> offsets;
  int64_t width = 0;
};

// Radiance's three layouts of a line (font.c): every character with a glyph 255 wide
// (uniftext); glyphs squeezed to their boxes with `gap` units between them (squeeztext, for a
// negative spacing); squeezed, then each run of characters up to a gap of more than `indent`
// spaces stretched to mwidth + gap a character (proptext, for a positive spacing).
TextLine uniformLine(const std::string& chars, const RadFont& font);
TextLine squeezedLine(const std::string& chars, const RadFont& font, int64_t gap);
TextLine proportionalLine(const std::string& chars, const RadFont& font, int64_t gap, int indent = 3);

// A text pattern as evaluated: which points of space are in a glyph.
class RadText {
 public:
  // The layout of `lines` in `font` with text.c's spacing: none given (`spacing` empty) or 0 uniform,
  // negative squeezed, positive proportional.
  RadText(std::shared_ptr<const RadFont> font, const std::vector<std::string>& lines, const Vec3& origin,
          const Vec3& right, const Vec3& down, std::optional<double> spacing);
  // Whether world point x is inside a glyph of the text (text.c's intext).
  bool inside(const Vec3& x) const;
  // The colour a brighttext or colortext multiplies by at x.
  Rgb colour(const Vec3& x) const { return inside(x) ? foreground : background; }

  Rgb foreground{1.0}, background{1.0};
  // Read-only views for tests.
  const std::vector<TextLine>& lines() const { return lines_; }
  // Units of the glyph grid per length of R (255, or mwidth + 255·|spacing| when a spacing is given).
  double unitsPerCharacter() const { return scaleX_; }

 private:
  std::shared_ptr<const RadFont> font_;
  std::vector<TextLine> lines_;
  Vec3 origin_, right_, down_;  // right_, down_: the dual vectors of R and D in their plane
  double scaleX_ = 255.0;
};

// Whether p is a text pattern or mixture (brighttext, colortext, mixtext).
bool isTextPattern(const RadPrimitive& p);

// The lines of a text file as Radiance's gettext reads them (fgets into 512 bytes): a line
// longer than 511 characters continues as further lines, and a NUL ends a line's text.
std::vector<std::string> textFileLines(const std::string& text);

// Reads text pattern p into sp (kind, args and name already set by the caller): its font and text
// file through files (found, read and listed once), its vectors and colours checked. InputError
// at p's line otherwise (or at the font file's line for bad font content).
ScenePattern readTextPattern(const RadPrimitive& p, FunctionFiles& files, const std::filesystem::path& folder,
                             ScenePattern sp);

}  // namespace candela
