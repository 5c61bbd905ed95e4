#include "reports/polar_plot_svg.h"
#include "reports/plan_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace candela {

namespace {

constexpr double kDegToRad = 3.14159265358979323846 / 180.0;

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

std::string cdLabel(double v) {
  char buf[32];
  if (v >= 100.0 || v == std::floor(v)) std::snprintf(buf, sizeof buf, "%.0f cd", v);
  else std::snprintf(buf, sizeof buf, "%.3g cd", v);
  return buf;
}

// Characters (code points) of UTF-8 text.
std::size_t codePoints(const std::string& s) {
  std::size_t n = 0;
  for (unsigned char ch : s) n += (ch & 0xC0) != 0x80;
  return n;
}

// The first `n` code points of s (as bytes).
std::size_t bytesOf(const std::string& s, std::size_t n) {
  std::size_t i = 0;
  for (; i < s.size() && n > 0; --n) {
    ++i;
    while (i < s.size() && (static_cast<unsigned char>(s[i]) & 0xC0) == 0x80) ++i;
  }
  return i;
}

// The title in lines of at most maxChars code points: broken at spaces, a word longer than a
// line broken inside.
std::vector<std::string> titleLines(const std::string& title, std::size_t maxChars) {
  std::vector<std::string> lines;
  std::string line;
  std::size_t pos = 0;
  while (pos <= title.size()) {
    const std::size_t space = std::min(title.find(' ', pos), title.size());
    std::string word = title.substr(pos, space - pos);
    pos = space + 1;
    if (word.empty()) continue;
    while (codePoints(word) > maxChars) {  // a word wider than the plot: broken where it must be
      if (!line.empty()) lines.push_back(std::move(line)), line.clear();
      const std::size_t cut = bytesOf(word, maxChars);
      lines.push_back(word.substr(0, cut));
      word.erase(0, cut);
    }
    if (word.empty()) continue;
    if (!line.empty() && codePoints(line) + 1 + codePoints(word) > maxChars) lines.push_back(std::move(line)), line.clear();
    line += (line.empty() ? "" : " ") + word;
  }
  if (!line.empty()) lines.push_back(std::move(line));
  return lines;
}

// The title's font (px) and the width of one of its characters, generously (bold Helvetica's
// capitals are about 0.72 em, its lower case about 0.56 em): a line never overruns the plot.
constexpr double kTitleFontPx = 13.0, kTitleCharPx = 0.64 * kTitleFontPx, kTitleLinePx = 16.0;

}  // namespace

double polarRingStepCd(double maxCd) {
  if (!(maxCd > 0.0)) return 1.0;
  const double raw = maxCd / 5.0;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0})
    if (m * mag >= raw * (1.0 - 1e-12)) return m * mag;
  return 10.0 * mag;
}

std::string polarPlotSvg(const std::vector<PolarCurve>& curves, const PolarPlotOptions& options) {
  const double size = options.sizePx;
  const std::size_t maxChars = std::max<std::size_t>(1, static_cast<std::size_t>((size - 12.0) / kTitleCharPx));
  const std::vector<std::string> title = titleLines(options.title, maxChars);
  const double titleH = title.empty() ? 0.0 : 28.0 + kTitleLinePx * double(title.size() - 1);
  const double legendH = options.legend ? 24.0 * double(std::max<size_t>(curves.size(), 1)) + 12.0 : 0.0;
  const double margin = 36.0;  // room for the angle labels
  const double cx = size / 2.0, cy = titleH + size / 2.0;
  const double radius = size / 2.0 - margin;

  double maxCd = 0.0;
  for (const auto& c : curves)
    for (double v : c.intensityCd) maxCd = std::max(maxCd, v);
  const double step = polarRingStepCd(maxCd);
  const int rings = std::max(1, int(std::ceil(maxCd / step - 1e-9)));
  const double scale = radius / (rings * step);  // px per cd

  static const char* kPalette[] = {"#c0392b", "#1f5fa8", "#2e8b57", "#8e44ad"};
  std::string s;
  s += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + num(size) + "\" height=\"" +
       num(size + titleH + legendH) + "\" viewBox=\"0 0 " + num(size) + " " + num(size + titleH + legendH) +
       "\" font-family=\"Helvetica, Arial, sans-serif\">\n";
  s += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  for (std::size_t k = 0; k < title.size(); ++k)
    s += "<text x=\"" + num(cx) + "\" y=\"" + (k == 0 ? std::string("20") : num(20.0 + kTitleLinePx * double(k))) +
         "\" text-anchor=\"middle\" font-size=\"13\" font-weight=\"bold\">" + xmlEscape(title[k]) + "</text>\n";
  s += "<g transform=\"translate(" + num(cx) + "," + num(cy) + ")\">\n";
  // Radial lines every 30 deg, labelled from nadir (bottom) to zenith (top) on both sides.
  s += "<g stroke=\"#b8b8b8\" stroke-width=\"0.8\">\n";
  for (int a = 0; a < 360; a += 30) {
    const double t = a * kDegToRad;
    s += "<line x1=\"0\" y1=\"0\" x2=\"" + num(radius * std::sin(t)) + "\" y2=\"" + num(radius * std::cos(t)) + "\"/>\n";
  }
  s += "</g>\n<g font-size=\"11\" fill=\"#555\" text-anchor=\"middle\">\n";
  for (int a = 0; a < 360; a += 30) {
    const double t = a * kDegToRad;
    const int shown = a <= 180 ? a : 360 - a;
    s += "<text x=\"" + num((radius + 16) * std::sin(t)) + "\" y=\"" + num((radius + 16) * std::cos(t) + 4) +
         "\">" + std::to_string(shown) + "&#176;</text>\n";
  }
  s += "</g>\n";
  // Intensity rings with labels along the upward axis, each just inside its ring: the outer
  // ring's stays clear of the angle labels outside it.
  s += "<g fill=\"none\" stroke=\"#9a9a9a\" stroke-width=\"0.8\">\n";
  for (int k = 1; k <= rings; ++k)
    s += "<circle class=\"ring\" r=\"" + num(k * step * scale) + "\"" +
         (k == rings ? " stroke=\"#666\" stroke-width=\"1.2\"" : "") + "/>\n";
  s += "</g>\n<g font-size=\"10\" fill=\"#333\">\n";
  for (int k = 1; k <= rings; ++k)
    s += "<text x=\"4\" y=\"" + num(-k * step * scale + 11) + "\">" + cdLabel(k * step) + "</text>\n";
  s += "</g>\n";
  // Curves.
  for (size_t i = 0; i < curves.size(); ++i) {
    const auto& c = curves[i];
    const std::string colour = c.colour.empty() ? kPalette[i % 4] : c.colour;
    std::string d;
    const size_t n = std::min(c.angleDeg.size(), c.intensityCd.size());
    for (size_t k = 0; k < n; ++k) {
      const double t = c.angleDeg[k] * kDegToRad, r = std::max(0.0, c.intensityCd[k]) * scale;
      d += (k == 0 ? "M" : " L") + num(r * std::sin(t)) + " " + num(r * std::cos(t));
    }
    s += "<path class=\"curve\" d=\"" + d + "\" fill=\"none\" stroke=\"" + colour + "\" stroke-width=\"2\"" +
         (c.dashed ? " stroke-dasharray=\"7 4\"" : "") + " stroke-linejoin=\"round\"/>\n";
  }
  s += "</g>\n";
  // Legend.
  double y = titleH + size + 14.0;
  for (size_t i = 0; i < curves.size() && options.legend; ++i, y += 24.0) {
    const auto& c = curves[i];
    const std::string colour = c.colour.empty() ? kPalette[i % 4] : c.colour;
    s += "<line x1=\"" + num(margin) + "\" y1=\"" + num(y) + "\" x2=\"" + num(margin + 34) + "\" y2=\"" + num(y) +
         "\" stroke=\"" + colour + "\" stroke-width=\"2\"" + (c.dashed ? " stroke-dasharray=\"7 4\"" : "") + "/>\n";
    s += "<text x=\"" + num(margin + 44) + "\" y=\"" + num(y + 4) + "\" font-size=\"12\">" + xmlEscape(c.label) +
         "</text>\n";
  }
  s += "</svg>\n";
  return s;
}

}  // namespace candela
