#include "engine/radiance/text_pattern.h"

#include "base/error.h"
#include "engine/radiance/function_patterns.h"
#include "engine/scene.h"

#include <cmath>

namespace candela {

namespace {
// Radiance's FTINY, whose fourth power bounds the squared length of text.c's right vector.
constexpr double kTiny = 1e-6;
// The largest spacing accepted (in character widths): beyond it the integer grid of a line would
// overflow long before the text meant anything.
constexpr double kMaxSpacing = 1000.0;
}  // namespace

TextLine uniformLine(const std::string& chars, const RadFont& font) {
  TextLine l;
  l.chars = chars;
  l.offsets.assign(chars.size() + 1, 0);
  for (size_t k = 0; k < chars.size(); ++k)
    if (font.glyph(static_cast<unsigned char>(chars[k]))) l.width += l.offsets[k + 1] = 255;
  return l;
}

TextLine squeezedLine(const std::string& chars, const RadFont& font, int64_t gap) {
  // font.c's squeeztext: each glyph's box placed `gap` units after the previous one's (half the
  // gap on either side), a glyph without outline (a space) as wide as the font's mean width, a
  // character without a glyph taking no room.
  TextLine l;
  l.chars = chars;
  const size_t n = chars.size();
  std::vector<int64_t>& sp = l.offsets;
  sp.assign(n + 1, 0);
  size_t k = 0, t = 0;
  auto glyphAt = [&](size_t i) { return font.glyph(static_cast<unsigned char>(chars[i])); };
  const RadGlyph* g = nullptr;
  while (t < n && (g = glyphAt(t++)) == nullptr) sp[k++] = 0;
  const int64_t half = gap / 2;
  sp[k] = half;
  int64_t width = 0;
  while (g) {
    if (g->vertices() > 0) {
      sp[k] += half - g->left;
      width += sp[k++];
      sp[k] = g->right + half;
    } else {
      width += sp[k++];
      sp[k] = font.meanWidth;
    }
    g = nullptr;
    while (t < n && (g = glyphAt(t++)) == nullptr) {
      width += sp[k++];
      sp[k] = 0;
    }
  }
  sp[k] += half;
  width += sp[k];
  l.width = width;
  return l;
}

TextLine proportionalLine(const std::string& chars, const RadFont& font, int64_t gap, int indent) {
  // font.c's proptext: squeezed first; then each run of characters (ending after a glyph followed
  // by more than `indent` spaces, or at the end) is stretched or shrunk to (mwidth + gap) units a
  // character with a glyph (the spaces after a glyph counted with it), the difference shared out
  // over the run's offsets in integer parts.
  TextLine l = squeezedLine(chars, font, gap);
  const size_t n = chars.size();
  std::vector<int64_t>& sp = l.offsets;
  auto glyphAt = [&](size_t i) { return font.glyph(static_cast<unsigned char>(chars[i])); };
  size_t si = 0;
  int64_t width = sp[si++];
  for (size_t t = 0; t < n;) {
    int64_t len = 0, alen = 0;
    size_t nsp = si, end = t, tab = t;
    for (end = t; end < n; end = tab) {
      tab = end + 1;
      alen += sp[nsp++];
      if (glyphAt(end)) {
        for (const RadGlyph* g; tab < n && (g = glyphAt(tab)) != nullptr && g->vertices() == 0; ++tab)
          alen += sp[nsp++];
        len += static_cast<int64_t>(tab - end);
      }
      if (indent > 0 && tab - end > static_cast<size_t>(indent)) break;
    }
    len *= font.meanWidth + gap;
    width += len;
    len -= alen;
    while (si < nsp) {
      const int64_t part = len / static_cast<int64_t>(nsp - si);
      sp[si++] += part;
      len -= part;
    }
    t = tab;
  }
  l.width = width;
  return l;
}

RadText::RadText(std::shared_ptr<const RadFont> font, const std::vector<std::string>& lines, const Vec3& origin,
                 const Vec3& right, const Vec3& down, std::optional<double> spacing)
    : font_(std::move(font)), origin_(origin), right_(right), down_(down) {
  // text.c's gettext: the spacing times 255, truncated, picks the layout.
  const int64_t units = spacing ? static_cast<int64_t>(*spacing * 255.0) : 0;
  lines_.reserve(lines.size());
  for (const std::string& s : lines)
    lines_.push_back(units < 0   ? squeezedLine(s, *font_, -units)
                     : units > 0 ? proportionalLine(s, *font_, units, 3)
                                 : uniformLine(s, *font_));
  // A given spacing (even 0) measures R in mean widths plus the spacing (text.c's intext).
  scaleX_ = spacing ? font_->meanWidth + 255.0 * std::abs(*spacing) : 255.0;
}

bool RadText::inside(const Vec3& p) const {
  // text.c's intext: the point's coordinates along R (characters, then grid units) and D (lines).
  const Vec3 v = p - origin_;
  const double x = glm::dot(v, right_) * scaleX_;
  const double y = glm::dot(v, down_);
  if (!(x >= 0.0) || !(y >= 0.0) || y >= static_cast<double>(lines_.size())) return false;
  const size_t line = static_cast<size_t>(y);
  const TextLine& l = lines_[line];
  if (x >= static_cast<double>(l.width)) return false;
  int64_t h = static_cast<int64_t>(x);
  const double fx = x - static_cast<double>(h);
  const double gy = (static_cast<double>(line + 1) - y) * 255.0;  // up from the line's foot
  for (size_t k = 0; k < l.offsets.size() && (h -= l.offsets[k]) >= 0; ++k) {
    if (h >= 255 || k >= l.chars.size()) continue;
    if (insideGlyph(font_->glyph(static_cast<unsigned char>(l.chars[k])), static_cast<double>(h) + fx, gy))
      return true;
  }
  return false;
}

bool isTextPattern(const RadPrimitive& p) {
  return p.type == "brighttext" || p.type == "colortext" || p.type == "mixtext";
}

std::vector<std::string> textFileLines(const std::string& text) {
  constexpr size_t kChunk = 511;  // fgets into Radiance's 512-byte buffer
  std::vector<std::string> lines;
  auto add = [&lines](std::string_view s) { lines.emplace_back(s.substr(0, s.find('\0'))); };
  for (size_t start = 0; start < text.size();) {
    const size_t nl = text.find('\n', start);
    const bool ended = nl != std::string::npos;
    std::string_view line(text.data() + start, (ended ? nl : text.size()) - start);
    for (; line.size() >= kChunk; line.remove_prefix(kChunk)) add(line.substr(0, kChunk));
    if (ended || !line.empty()) add(line);
    start = ended ? nl + 1 : text.size();
  }
  return lines;
}

ScenePattern readTextPattern(const RadPrimitive& p, FunctionFiles& files, const std::filesystem::path& folder,
                             ScenePattern sp) {
  const std::string what = p.type + " '" + p.name + "'";
  const bool mixture = p.type == "mixtext";
  const size_t fontAt = mixture ? 2 : 0, textAt = fontAt + 1;
  const size_t nReals = p.type == "brighttext" ? 11 : p.type == "colortext" ? 15 : 9;
  const char* strings = mixture ? "foreground background fontfile textfile, or fontfile . and the words of one line"
                                : "fontfile textfile, or fontfile . and the words of one line";
  const char* reals = p.type == "brighttext"  ? "Ox Oy Oz Rx Ry Rz Dx Dy Dz foreground background [spacing]"
                      : p.type == "colortext" ? "Ox Oy Oz Rx Ry Rz Dx Dy Dz rf gf bf rb gb bb [spacing]"
                                              : "Ox Oy Oz Rx Ry Rz Dx Dy Dz [spacing]";
  if (p.strings.size() < textAt + 1)
    throw InputError(p.loc, what + " needs " + std::to_string(textAt + 1) + " or more string arguments (" + strings +
                                "), got " + std::to_string(p.strings.size()));
  if (p.reals.size() < nReals)
    throw InputError(p.loc, what + " needs " + std::to_string(nReals) + " or more real arguments (" + reals +
                                "), got " + std::to_string(p.reals.size()));
  for (double r : p.reals)
    if (!std::isfinite(r)) throw InputError(p.loc, what + ": a real argument is not a finite number");
  std::optional<double> spacing;
  if (p.reals.size() > nReals) {
    spacing = p.reals[nReals];
    if (std::abs(*spacing) > kMaxSpacing)
      throw InputError(p.loc, what + ": its spacing " + compactNumber(*spacing) + " is beyond ±" +
                                  compactNumber(kMaxSpacing) + " character widths");
  }
  const Vec3 origin(p.reals[0], p.reals[1], p.reals[2]), r(p.reals[3], p.reals[4], p.reals[5]),
      d(p.reals[6], p.reals[7], p.reals[8]);
  // text.c's gettext: the vectors dual to R and D in their plane (right·R = 1, right·D = 0,
  // down·D = 1, down·R = 0), so a point's coordinates on them count characters and lines.
  const Vec3 dxr = glm::cross(d, r);
  Vec3 right = glm::cross(dxr, d);
  const double rr = glm::dot(right, right);
  if (!(rr > kTiny * kTiny * kTiny * kTiny))
    throw InputError(p.loc, what + ": its right vector R and down vector D must be neither zero nor parallel");
  right *= glm::dot(d, d) / rr;
  Vec3 down = glm::cross(r, dxr);
  down *= glm::dot(r, r) / glm::dot(down, down);

  const std::shared_ptr<const RadFont> font = files.font(p.strings[fontAt], p, folder);
  std::vector<std::string> lines;
  if (p.strings.size() > textAt + 1) {  // one line written inline (the word after the font is not read)
    std::string line;
    for (size_t k = textAt + 1; k < p.strings.size(); ++k) line += (k > textAt + 1 ? " " : "") + p.strings[k];
    lines.push_back(line.substr(0, line.find('\0')));
  } else {
    lines = *files.textLines(p.strings[textAt], p, folder);
  }
  auto text = std::make_shared<RadText>(font, lines, origin, right, down, spacing);
  if (p.type == "brighttext") {
    text->foreground = Rgb(p.reals[9]);
    text->background = Rgb(p.reals[10]);
  } else if (p.type == "colortext") {
    text->foreground = Rgb(p.reals[9], p.reals[10], p.reals[11]);
    text->background = Rgb(p.reals[12], p.reals[13], p.reals[14]);
  }
  sp.text = std::move(text);
  sp.channels = p.type == "colortext" ? 3 : 1;
  return sp;
}

}  // namespace candela
