#include "reports/plan_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <tuple>

#include "base/atomic_file.h"
#include "reports/falsecolor.h"
#include "reports/plan_section_svg.h"
#include "reports/png_writer.h"

namespace candela {

std::string xmlEscape(const std::string& text) {
  std::string s;
  for (char c : text) {
    switch (c) {
      case '&': s += "&amp;"; break;
      case '<': s += "&lt;"; break;
      case '>': s += "&gt;"; break;
      case '"': s += "&quot;"; break;
      case '\'': s += "&#39;"; break;
      default:
        // Control characters (a case name with ESC or BEL) are written as \xNN, as error
        // messages write them (base/error.h, printable): they reached report.html raw, and XML
        // forbids them. Tab, line feed and carriage return are text.
        if ((static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r') || c == 0x7f) {
          char hex[5];
          std::snprintf(hex, sizeof hex, "\\x%02x", static_cast<unsigned char>(c));
          s += hex;
        } else {
          s += c;
        }
    }
  }
  return s;
}

namespace {

// An edge of the node lattice: horizontal (node (i,j) to (i+1,j)) or vertical ((i,j) to (i,j+1)).
using EdgeKey = std::tuple<int, int, int>;  // (vertical?, i, j)

struct Segment {
  EdgeKey a, b;
};

std::string px(double v) { return svgNumber(v); }

// A 1-2-5 × 10^n length close to `target`, for scale bars.
double niceLength(double target) {
  const double decade = std::pow(10.0, std::floor(std::log10(target)));
  double best = decade;
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * decade <= target) best = m * decade;
  return best;
}

// A regular layout's values on its node lattice (cell centres), NaN where no sensor sits.
struct NodeField {
  const PlanLayout& layout;
  int nx, ny;
  std::vector<double> field;

  double value(int i, int j) const { return field[static_cast<std::size_t>(j) * nx + i]; }
  Vec2 node(int i, int j) const { return layout.originM + (Vec2(i, j) + 0.5) * layout.spacingM; }
  // Where `level` crosses edge e, interpolated linearly between its two nodes.
  Vec2 crossing(const EdgeKey& e, double level) const {
    const auto [vertical, i, j] = e;
    const int i2 = vertical ? i : i + 1, j2 = vertical ? j + 1 : j;
    const double a = value(i, j), b = value(i2, j2);
    const double t = std::clamp((level - a) / (b - a), 0.0, 1.0);
    return node(i, j) + t * (node(i2, j2) - node(i, j));
  }
};

// The field on a lattice of blocks of `f` × `f` cells: a block's value is the mean of its
// sensors' (NaN without any), its node the block's centre (coarse.originM, f × the spacing).
NodeField nodeField(const PlanLayout& layout, const std::vector<double>& values, int f, PlanLayout& coarse) {
  coarse.regular = true;
  coarse.columns = (layout.columns + f - 1) / f;
  coarse.rows = (layout.rows + f - 1) / f;
  coarse.originM = layout.originM;
  coarse.spacingM = layout.spacingM * static_cast<double>(f);
  const int nx = coarse.columns, ny = coarse.rows;
  std::vector<double> sum(static_cast<std::size_t>(nx) * ny, 0.0);
  std::vector<uint32_t> count(sum.size(), 0);
  for (std::size_t k = 0; k < layout.cells.size() && k < values.size(); ++k) {
    const glm::ivec2 c = layout.cells[k];
    if (c.x < 0 || c.y < 0 || c.x >= layout.columns || c.y >= layout.rows) continue;
    const std::size_t at = static_cast<std::size_t>(c.y / f) * nx + static_cast<std::size_t>(c.x / f);
    sum[at] += values[k];
    ++count[at];
  }
  for (std::size_t at = 0; at < sum.size(); ++at)
    sum[at] = count[at] ? sum[at] / count[at] : std::numeric_limits<double>::quiet_NaN();
  return NodeField{coarse, nx, ny, std::move(sum)};
}

// Marching squares: the segments of the `level` line in each lattice cell whose four nodes have values.
std::vector<Segment> levelSegments(const NodeField& f, double level) {
  std::vector<Segment> segments;
  for (int j = 0; j + 1 < f.ny; ++j) {
    for (int i = 0; i + 1 < f.nx; ++i) {
      // Corners counter-clockwise from bottom-left; edge k joins corner k and k+1.
      const double v[4] = {f.value(i, j), f.value(i + 1, j), f.value(i + 1, j + 1), f.value(i, j + 1)};
      if (std::isnan(v[0]) || std::isnan(v[1]) || std::isnan(v[2]) || std::isnan(v[3])) continue;
      const EdgeKey edge[4] = {{0, i, j}, {1, i + 1, j}, {0, i, j + 1}, {1, i, j}};
      bool above[4];
      int count = 0;
      for (int k = 0; k < 4; ++k) count += (above[k] = v[k] >= level);
      if (count == 0 || count == 4) continue;
      if (count == 2 && above[0] == above[2]) {
        // Saddle: the corners on the other side of the centre's value are cut off one by one.
        const bool centreAbove = 0.25 * (v[0] + v[1] + v[2] + v[3]) >= level;
        for (int k = 0; k < 4; ++k)
          if (above[k] != centreAbove) segments.push_back({edge[(k + 3) % 4], edge[k]});
        continue;
      }
      EdgeKey crossed[2];
      int n = 0;
      for (int k = 0; k < 4 && n < 2; ++k)
        if (above[k] != above[(k + 1) % 4]) crossed[n++] = edge[k];
      segments.push_back({crossed[0], crossed[1]});
    }
  }
  return segments;
}

// Join segments sharing an edge crossing into polylines.
std::vector<ContourLine> joinSegments(const std::vector<Segment>& segments, const NodeField& f, double level) {
  std::vector<ContourLine> lines;
  std::map<EdgeKey, std::vector<std::size_t>> byEdge;
  for (std::size_t s = 0; s < segments.size(); ++s) {
    byEdge[segments[s].a].push_back(s);
    byEdge[segments[s].b].push_back(s);
  }
  std::vector<bool> used(segments.size(), false);
  auto other = [&](std::size_t s, const EdgeKey& e) { return segments[s].a == e ? segments[s].b : segments[s].a; };
  auto nextSegment = [&](const EdgeKey& e) -> std::ptrdiff_t {
    for (std::size_t s : byEdge[e])
      if (!used[s]) return static_cast<std::ptrdiff_t>(s);
    return -1;
  };
  for (std::size_t start = 0; start < segments.size(); ++start) {
    if (used[start]) continue;
    used[start] = true;
    std::vector<EdgeKey> chain = {segments[start].a, segments[start].b};
    for (std::ptrdiff_t s; (s = nextSegment(chain.back())) >= 0;) {  // forwards
      used[static_cast<std::size_t>(s)] = true;
      chain.push_back(other(static_cast<std::size_t>(s), chain.back()));
    }
    std::vector<EdgeKey> head;
    for (EdgeKey e = chain.front(); true;) {  // backwards
      const std::ptrdiff_t s = nextSegment(e);
      if (s < 0) break;
      used[static_cast<std::size_t>(s)] = true;
      e = other(static_cast<std::size_t>(s), e);
      head.push_back(e);
    }
    ContourLine line;
    line.level = level;
    for (auto it = head.rbegin(); it != head.rend(); ++it) line.points.push_back(f.crossing(*it, level));
    for (const EdgeKey& e : chain) line.points.push_back(f.crossing(e, level));
    line.closed = chain.size() > 2 && chain.front() == chain.back();
    lines.push_back(std::move(line));
  }
  return lines;
}

}  // namespace

std::vector<ContourLine> isolines(const PlanLayout& layout, const std::vector<double>& values, double level) {
  if (!layout.regular || layout.columns < 2 || layout.rows < 2) return {};
  const int f = (std::max(layout.columns, layout.rows) + kMaxContourNodes - 1) / kMaxContourNodes;
  PlanLayout coarse;
  const NodeField field = nodeField(layout, values, f, coarse);
  return joinSegments(levelSegments(field, level), field, level);
}

std::string svgNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  std::string s = buf;
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

PlanExtent planExtent(const PlanLayout& L) {
  Vec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  auto extend = [&](const Vec2& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  };
  for (const Vec2& p : L.outline) extend(p);
  for (const Vec2& p : L.planPositions) extend(p);
  if (L.regular) {
    extend(L.originM);
    extend(L.originM + Vec2(L.columns, L.rows) * L.spacingM);
  }
  if (!(hi.x >= lo.x)) return {};
  if (hi.x - lo.x < 1e-6) { lo.x -= 0.5; hi.x += 0.5; }
  if (hi.y - lo.y < 1e-6) { lo.y -= 0.5; hi.y += 0.5; }
  return {lo, hi};
}

namespace {

// One plan drawing: what it shows and where (page layout in px, `k` px per m of plan).
struct PlanPage {
  PlanPage(const GridReport& g, const ColorScale& sc, const PlanOptions& o) : grid(g), scale(sc), opt(o) {
    const auto [extLo, extHi] = planExtent(grid.layout);
    lo = extLo;
    hi = extHi;
    ext = hi - lo;
    k = std::min(opt.maxPlanWidthPx / ext.x, opt.maxPlanHeightPx / ext.y);
    planW = ext.x * k;
    planH = ext.y * k;
    // A narrow plan (a corridor) keeps a legend tall enough to read its ticks.
    legendH = std::max(planH, kMinLegendPx);
    width = left + planW + legendGap + legendBar + legendLabels;
    // The key explains a section's lines and the markers with them; markers alone need none.
    if (opt.section) {
      key = sectionKeyItems(*opt.section, frame());
      for (const PlanMarker* m : markersInside()) {
        key.luminaires = key.luminaires || m->kind == PlanMarker::Kind::kLuminaire;
        key.observers = key.observers || m->kind == PlanMarker::Kind::kObserver;
      }
    }
    keyH = planKeyHeight(key, width - left - 8);
    height = top + std::max(planH + 64 + keyH, legendH + 20);
  }
  double X(double u) const { return left + (u - lo.x) * k; }
  double Y(double v) const { return top + (hi.y - v) * k; }
  PlanFrame frame() const { return {lo, hi, k, left, top, planW, planH, opt.idPrefix}; }
  // The options' markers that fall inside the plan's extent.
  std::vector<const PlanMarker*> markersInside() const {
    std::vector<const PlanMarker*> inside;
    for (const PlanMarker& m : opt.markers)
      if (m.positionM.x >= lo.x && m.positionM.x <= hi.x && m.positionM.y >= lo.y && m.positionM.y <= hi.y)
        inside.push_back(&m);
    return inside;
  }

  const GridReport& grid;
  const ColorScale& scale;
  const PlanOptions& opt;
  Vec2 lo, hi, ext;
  double k = 0.0;  // px per m
  double planW = 0.0, planH = 0.0;
  static constexpr double kMinLegendPx = 150;
  double left = 44, top = 30, legendGap = 34, legendBar = 16, legendLabels = 70, legendH = 0.0;
  double width = 0.0, height = 0.0;
  PlanKeyItems key;   // under the scale bar, when the plan shows a section
  double keyH = 0.0;  // px
};

// The <svg> element, the legend's gradient, the clip path of the plan and its background.
void writeSvgOpen(std::ostringstream& s, const PlanPage& p) {
  const std::string& id = p.opt.idPrefix;
  const std::string font = "font-family=\"Helvetica Neue,Helvetica,Arial,sans-serif\"";
  s << "<svg " << (p.opt.standalone ? "xmlns=\"http://www.w3.org/2000/svg\" " : "") << "class=\"plan\" width=\"" << px(p.width) << "\" height=\""
    << px(p.height) << "\" viewBox=\"0 0 " << px(p.width) << " " << px(p.height) << "\" role=\"img\" aria-label=\""
    << xmlEscape(p.grid.quantity + " plan of " + p.grid.name) << "\" " << font << ">\n";
  // Gradient for the legend, sampled from the same colour map.
  s << "<defs><linearGradient id=\"" << id << "-scale\" x1=\"0\" y1=\"1\" x2=\"0\" y2=\"0\">";
  for (int i = 0; i <= 16; ++i) s << "<stop offset=\"" << px(i / 16.0) << "\" stop-color=\"" << hexColor(viridis(i / 16.0)) << "\"/>";
  s << "</linearGradient><clipPath id=\"" << id << "-clip\"><rect x=\"" << px(p.left) << "\" y=\"" << px(p.top)
    << "\" width=\"" << px(p.planW) << "\" height=\"" << px(p.planH) << "\"/></clipPath>"
    << (p.opt.section ? sectionClipPath(p.frame()) : "") << "</defs>\n";
  s << "<rect x=\"" << px(p.left) << "\" y=\"" << px(p.top) << "\" width=\"" << px(p.planW) << "\" height=\"" << px(p.planH)
    << "\" fill=\"#f4f4f2\"/>\n";
}

// The cells of a large regular grid as one picture of the plan at twice its px (sharp when
// printed): each pixel the false colour of the mean of the cells whose centres fall in it, or,
// where cells are larger than pixels, of the cell under its centre; pixels outside every cell
// are transparent (the plan's background shows).
void writeRasterCells(std::ostringstream& s, const PlanPage& p) {
  const GridReport& grid = p.grid;
  const PlanLayout& L = grid.layout;
  constexpr double kPxPerPlanPx = 2.0;
  const int w = std::max(1, static_cast<int>(std::ceil(p.planW * kPxPerPlanPx)));
  const int h = std::max(1, static_cast<int>(std::ceil(p.planH * kPxPerPlanPx)));
  const double k = p.k * kPxPerPlanPx;  // picture px per m
  const std::size_t n = std::min(grid.values.size(), L.cells.size());
  std::vector<double> sum(static_cast<std::size_t>(w) * h, 0.0);
  std::vector<uint32_t> count(sum.size(), 0);
  auto pixelOf = [&](const Vec2& q, int& x, int& y) {
    x = static_cast<int>(std::floor((q.x - p.lo.x) * k));
    y = static_cast<int>(std::floor((p.hi.y - q.y) * k));
    return x >= 0 && y >= 0 && x < w && y < h;
  };
  for (std::size_t i = 0; i < n; ++i) {
    int x = 0, y = 0;
    if (!pixelOf(L.originM + (Vec2(L.cells[i]) + 0.5) * L.spacingM, x, y)) continue;
    sum[static_cast<std::size_t>(y) * w + x] += grid.values[i];
    ++count[static_cast<std::size_t>(y) * w + x];
  }
  // The point of each lattice cell, for pixels that no cell centre fell in.
  std::vector<int32_t> pointOfCell(static_cast<std::size_t>(L.columns) * L.rows, -1);
  for (std::size_t i = 0; i < n; ++i) {
    const glm::ivec2 c = L.cells[i];
    if (c.x >= 0 && c.y >= 0 && c.x < L.columns && c.y < L.rows)
      pointOfCell[static_cast<std::size_t>(c.y) * L.columns + c.x] = static_cast<int32_t>(i);
  }
  Image8 picture(w, h, Rgb8{0xf4, 0xf4, 0xf2});  // the plan's background (writeSvgOpen)
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t at = static_cast<std::size_t>(y) * w + x;
      double v = 0.0;
      if (count[at] > 0) {
        v = sum[at] / count[at];
      } else {
        const Vec2 q(p.lo.x + (x + 0.5) / k, p.hi.y - (y + 0.5) / k);
        const glm::ivec2 c(static_cast<int>(std::floor((q.x - L.originM.x) / L.spacingM.x)),
                           static_cast<int>(std::floor((q.y - L.originM.y) / L.spacingM.y)));
        if (c.x < 0 || c.y < 0 || c.x >= L.columns || c.y >= L.rows) continue;
        const int32_t i = pointOfCell[static_cast<std::size_t>(c.y) * L.columns + c.x];
        if (i < 0) continue;
        v = grid.values[static_cast<std::size_t>(i)];
      }
      picture.set(x, y, falseColor(v, p.scale));
    }
  s << "<image x=\"" << px(p.left) << "\" y=\"" << px(p.top) << "\" width=\"" << px(w / kPxPerPlanPx)
    << "\" height=\"" << px(h / kPxPerPlanPx) << "\" preserveAspectRatio=\"none\" href=\"data:image/png;base64,"
    << base64(encodePng(picture)) << "\"/>\n";
}

// Cells (regular) or dots (points files), and the calculation area's outline. Grids of more
// than kMaxSvgCells cells are drawn as a picture (writeRasterCells): an element a cell would
// make a plan of 10⁶ points a page of 100 MB.
void writeCells(std::ostringstream& s, const PlanPage& p) {
  const GridReport& grid = p.grid;
  const PlanLayout& L = grid.layout;
  s << "<g shape-rendering=\"crispEdges\">\n";
  const bool raster = L.regular && L.cells.size() > kMaxSvgCells;
  if (raster) writeRasterCells(s, p);
  for (std::size_t i = 0; i < grid.values.size() && !raster; ++i) {
    const Rgb8 c = falseColor(grid.values[i], p.scale);
    if (L.regular && i < L.cells.size()) {
      const Vec2 a = L.originM + Vec2(L.cells[i]) * L.spacingM;
      // Half a pixel of overlap hides hairline seams between neighbours.
      s << "<rect x=\"" << px(p.X(a.x)) << "\" y=\"" << px(p.Y(a.y + L.spacingM.y)) << "\" width=\""
        << px(L.spacingM.x * p.k + 0.5) << "\" height=\"" << px(L.spacingM.y * p.k + 0.5) << "\" fill=\"" << hexColor(c)
        << "\"/>\n";
    }
  }
  s << "</g>\n";
  if (!L.regular) {
    for (std::size_t i = 0; i < grid.values.size() && i < L.planPositions.size(); ++i) {
      const Vec2 q = L.planPositions[i];
      s << "<circle cx=\"" << px(p.X(q.x)) << "\" cy=\"" << px(p.Y(q.y)) << "\" r=\"6\" fill=\""
        << hexColor(falseColor(grid.values[i], p.scale)) << "\" stroke=\"#333\" stroke-width=\"0.8\"/>\n";
    }
  }
}

// The calculation area's outline.
void writeOutline(std::ostringstream& s, const PlanPage& p) {
  const PlanLayout& L = p.grid.layout;
  if (L.outline.size() >= 3) {
    s << "<polygon points=\"";
    for (const Vec2& q : L.outline) s << px(p.X(q.x)) << "," << px(p.Y(q.y)) << " ";
    s << "\" fill=\"none\" stroke=\"#222\" stroke-width=\"1.5\"/>\n";
  }
}

// Cell values, when the cells are large enough to hold them.
void writeCellValues(std::ostringstream& s, const PlanPage& p) {
  const GridReport& grid = p.grid;
  const PlanLayout& L = grid.layout;
  const double cellPx = L.regular ? std::min(L.spacingM.x, L.spacingM.y) * p.k : 0.0;
  if (!(p.opt.cellValues && L.regular && cellPx >= 30.0 && grid.values.size() <= 200)) return;
  s << "<g font-size=\"" << px(std::min(11.0, cellPx / 3.2)) << "\" text-anchor=\"middle\" dominant-baseline=\"central\">\n";
  for (std::size_t i = 0; i < grid.values.size() && i < L.cells.size(); ++i) {
    const Vec2 c = L.originM + (Vec2(L.cells[i]) + 0.5) * L.spacingM;
    s << "<text x=\"" << px(p.X(c.x)) << "\" y=\"" << px(p.Y(c.y)) << "\" fill=\""
      << hexColor(contrastingText(falseColor(grid.values[i], p.scale))) << "\" fill-opacity=\"0.75\">"
      << formatNumber(grid.values[i], 3) << "</text>\n";
  }
  s << "</g>\n";
}

// The options' contour levels or, without them, isolux lines at the legend's ticks and halfway
// between them, inside the grid's range.
std::vector<double> contourLevels(const PlanPage& p) {
  std::vector<double> levels = p.opt.contourLevels;
  if (levels.empty()) {
    const std::vector<double> ticks = scaleTicks(p.scale, 6);
    for (std::size_t i = 0; i < ticks.size(); ++i) {
      for (double t : {ticks[i], i + 1 < ticks.size() ? 0.5 * (ticks[i] + ticks[i + 1]) : ticks[i]})
        if (t > p.grid.stats.minimumLux && t < p.grid.stats.maximumLux &&
            (levels.empty() || t > levels.back()))
          levels.push_back(t);
    }
  }
  return levels;
}

// A contour label placed on the plan: its centre (px) and the radius of a disc that holds its
// text at any rotation, so that two labels whose discs do not meet cannot overlap.
struct PlacedLabel {
  Vec2 centre;
  double radius;
};

// The label of a contour line `length` px long, along the line and never upside down: at half
// its length, else at the first of 30 %, 70 %, 15 % and 85 % where it meets no label already
// placed and stays inside the plan; a line not 12 px longer than the label has it upright beside
// its middle; none when every place is taken.
void writeContourLabel(std::ostringstream& labels, const PlanPage& p, const ContourLine& line, double length,
                       double level, std::vector<PlacedLabel>& placed) {
  const std::string text = formatNumber(level, 4);
  // 11 px bold digits are at most 0.62 em wide, plus the 3 px halo on each side.
  const double w = 0.62 * 11.0 * static_cast<double>(text.size()) + 6.0, h = 11.0 + 6.0;
  const double radius = 0.5 * std::hypot(w, h);
  auto fits = [&](const Vec2& c) {
    bool free = c.x - 0.5 * w >= p.left && c.x + 0.5 * w <= p.left + p.planW && c.y - 0.5 * h >= p.top &&
                c.y + 0.5 * h <= p.top + p.planH;
    for (const PlacedLabel& q : placed) free = free && glm::length(q.centre - c) >= q.radius + radius;
    return free;
  };
  auto write = [&](const Vec2& c, std::optional<double> angle) {
    labels << "<text x=\"" << px(c.x) << "\" y=\"" << px(c.y) << "\"";
    if (angle) labels << " transform=\"rotate(" << px(*angle) << " " << px(c.x) << " " << px(c.y) << ")\"";
    labels << " text-anchor=\"middle\" dominant-baseline=\"central\" font-size=\"11\" font-weight=\"600\" "
              "fill=\"#111\" stroke=\"#fff\" stroke-width=\"3\" paint-order=\"stroke\">"
           << text << "</text>\n";
    placed.push_back({c, radius});
  };
  if (length < w + 12.0) {
    // On the line the label would hide it (a corridor's lines cross its width): upright beside
    // its middle instead, right, left, above or below, where it fits.
    if (line.points.empty()) return;
    const Vec2 mid = line.points[line.points.size() / 2];
    const Vec2 m(p.X(mid.x), p.Y(mid.y));
    for (const Vec2& off : {Vec2(0.5 * w + 4.0, 0.0), Vec2(-0.5 * w - 4.0, 0.0), Vec2(0.0, -0.5 * h - 3.0),
                            Vec2(0.0, 0.5 * h + 3.0)})
      if (fits(m + off)) return write(m + off, std::nullopt);
    return;
  }
  for (double at : {0.5, 0.3, 0.7, 0.15, 0.85}) {
    double walked = 0.0;
    for (std::size_t i = 1; i < line.points.size(); ++i) {
      const double d = glm::length(line.points[i] - line.points[i - 1]) * p.k;
      if (walked + d < at * length) {
        walked += d;
        continue;
      }
      const Vec2 a = line.points[i - 1], b = line.points[i];
      const double f = d > 0 ? (at * length - walked) / d : 0.0;
      const Vec2 m = a + f * (b - a);
      const Vec2 c(p.X(m.x), p.Y(m.y));
      if (!fits(c)) break;  // try the next place along the line
      double angle = radToDeg(std::atan2(-(b.y - a.y), b.x - a.x));
      if (angle > 90.0) angle -= 180.0;
      if (angle < -90.0) angle += 180.0;
      return write(c, angle);
    }
  }
}

// Isolines with labels on each long enough line where they meet no other label; the labels are
// drawn last, over every line.
void writeContours(std::ostringstream& s, const PlanPage& p) {
  const PlanLayout& L = p.grid.layout;
  if (!(p.opt.contours && L.regular)) return;
  const std::vector<double> levels = contourLevels(p);
  s << "<g clip-path=\"url(#" << p.opt.idPrefix << "-clip)\">\n";
  std::ostringstream labels;
  std::vector<PlacedLabel> placed;
  for (double level : levels) {
    for (const ContourLine& line : isolines(L, p.grid.values, level)) {
      if (line.points.size() < 2) continue;
      s << "<polyline points=\"";
      double length = 0.0;
      for (std::size_t i = 0; i < line.points.size(); ++i) {
        s << px(p.X(line.points[i].x)) << "," << px(p.Y(line.points[i].y)) << " ";
        if (i) length += glm::length(line.points[i] - line.points[i - 1]) * p.k;
      }
      s << "\" fill=\"none\" stroke=\"#1a1a1a\" stroke-width=\"1.1\" stroke-linejoin=\"round\"/>\n";
      writeContourLabel(labels, p, line, length, level, placed);
    }
  }
  s << labels.str() << "</g>\n";
}

// The plan's frame.
void writeFrame(std::ostringstream& s, const PlanPage& p) {
  s << "<rect x=\"" << px(p.left) << "\" y=\"" << px(p.top) << "\" width=\"" << px(p.planW) << "\" height=\""
    << px(p.planH) << "\" fill=\"none\" stroke=\"#999\" stroke-width=\"0.8\"/>\n";
}

// The plan's frame, unless a section drew it under its walls (which often lie on it), and axis
// ticks in metres along its bottom and left edges.
void writeAxes(std::ostringstream& s, const PlanPage& p) {
  const double left = p.left, top = p.top, planH = p.planH;
  if (!p.opt.section) writeFrame(s, p);
  const double step = niceLength(std::max(p.ext.x, p.ext.y) / 6.0);
  s << "<g font-size=\"10\" fill=\"#555\">\n";
  for (double u = std::ceil(p.lo.x / step - 1e-9) * step; u <= p.hi.x + 1e-9; u += step) {
    s << "<line x1=\"" << px(p.X(u)) << "\" y1=\"" << px(top + planH) << "\" x2=\"" << px(p.X(u)) << "\" y2=\""
      << px(top + planH + 4) << "\" stroke=\"#777\"/><text x=\"" << px(p.X(u)) << "\" y=\"" << px(top + planH + 15)
      << "\" text-anchor=\"middle\">" << formatNumber(u, 4) << "</text>\n";
  }
  for (double v = std::ceil(p.lo.y / step - 1e-9) * step; v <= p.hi.y + 1e-9; v += step) {
    s << "<line x1=\"" << px(left - 4) << "\" y1=\"" << px(p.Y(v)) << "\" x2=\"" << px(left) << "\" y2=\"" << px(p.Y(v))
      << "\" stroke=\"#777\"/><text x=\"" << px(left - 7) << "\" y=\"" << px(p.Y(v))
      << "\" text-anchor=\"end\" dominant-baseline=\"central\">" << formatNumber(v, 4) << "</text>\n";
  }
  s << "</g>\n";
}

// Scale bar under the plan, bottom left, and the north arrow (plans, not elevations), top right
// above the plan, rotated to true north.
void writeScaleBarAndNorth(std::ostringstream& s, const PlanPage& p) {
  {
    const double len = niceLength(p.ext.x / 4.0);
    const double x0 = p.left, y0 = p.top + p.planH + 36, w = len * p.k;
    s << "<g font-size=\"10\" fill=\"#333\"><rect x=\"" << px(x0) << "\" y=\"" << px(y0) << "\" width=\"" << px(w / 2)
      << "\" height=\"5\" fill=\"#333\"/><rect x=\"" << px(x0 + w / 2) << "\" y=\"" << px(y0) << "\" width=\""
      << px(w / 2) << "\" height=\"5\" fill=\"#fff\" stroke=\"#333\" stroke-width=\"0.8\"/><text x=\""
      << px(x0 + w + 6) << "\" y=\"" << px(y0 + 5) << "\">" << formatNumber(len, 3) << " m</text></g>\n";
  }
  if (p.opt.northArrow) {
    const double cx = p.left + p.planW - 12, cy = 15;
    s << "<g transform=\"translate(" << px(cx) << " " << px(cy) << ") rotate(" << px(p.opt.northDeg)
      << ")\"><circle r=\"12\" fill=\"#fff\" stroke=\"#666\" stroke-width=\"0.8\"/>"
         "<path d=\"M0,-10 L5,6 L0,3 L-5,6 Z\" fill=\"#222\"/></g>"
      << "<text x=\"" << px(cx - 18) << "\" y=\"" << px(cy + 4) << "\" font-size=\"11\" font-weight=\"700\" "
      << "text-anchor=\"end\" fill=\"#222\">N</text>\n";
  }
}

// Legend: colour bar with ticks in the grid's unit.
void writeLegend(std::ostringstream& s, const PlanPage& p) {
  const double legendBar = p.legendBar;
  const double lx = p.left + p.planW + p.legendGap, ly = p.top, lh = p.legendH;
  s << "<text x=\"" << px(lx) << "\" y=\"" << px(ly - 10) << "\" font-size=\"11\" font-weight=\"600\" fill=\"#333\">"
    << xmlEscape(p.grid.unit) << "</text>\n";
  s << "<rect x=\"" << px(lx) << "\" y=\"" << px(ly) << "\" width=\"" << px(legendBar) << "\" height=\"" << px(lh)
    << "\" fill=\"url(#" << p.opt.idPrefix << "-scale)\" stroke=\"#666\" stroke-width=\"0.6\"/>\n";
  s << "<g font-size=\"10\" fill=\"#333\">\n";
  for (double t : scaleTicks(p.scale, 6)) {
    const double y = ly + lh * (1.0 - scalePosition(t, p.scale));
    s << "<line x1=\"" << px(lx + legendBar) << "\" y1=\"" << px(y) << "\" x2=\"" << px(lx + legendBar + 4)
      << "\" y2=\"" << px(y) << "\" stroke=\"#555\"/><text x=\"" << px(lx + legendBar + 7) << "\" y=\"" << px(y)
      << "\" dominant-baseline=\"central\">" << formatNumber(t, 4) << "</text>\n";
  }
  s << "</g>\n";
}

}  // namespace

// The markers inside the plan's extent, over the cells and isolines: luminaires as squares with
// a cross, observers as dots with an arrow along their line of sight; their names beside them
// when few enough to read.
void writeMarkers(std::ostringstream& s, const PlanPage& p) {
  const std::vector<const PlanMarker*> inside = p.markersInside();
  if (inside.empty()) return;
  const bool named = inside.size() <= kMaxNamedMarkers;
  s << "<g class=\"markers\" font-size=\"9\" fill=\"#111\">\n";
  for (const PlanMarker* m : inside) {
    const double x = p.X(m->positionM.x), y = p.Y(m->positionM.y);
    if (m->kind == PlanMarker::Kind::kLuminaire) {
      s << "<rect x=\"" << px(x - 4) << "\" y=\"" << px(y - 4) << "\" width=\"8\" height=\"8\" fill=\"#fff\" "
        << "stroke=\"#111\" stroke-width=\"1\"/><path d=\"M" << px(x - 4) << " " << px(y - 4) << "L" << px(x + 4)
        << " " << px(y + 4) << "M" << px(x + 4) << " " << px(y - 4) << "L" << px(x - 4) << " " << px(y + 4)
        << "\" stroke=\"#111\" stroke-width=\"0.8\"/>\n";
    } else {
      const Vec2 d = glm::length(m->direction) > 0.0 ? glm::normalize(m->direction) : Vec2(0.0, 1.0);
      s << "<circle cx=\"" << px(x) << "\" cy=\"" << px(y) << "\" r=\"4\" fill=\"#d0342c\" stroke=\"#fff\" "
        << "stroke-width=\"1\"/><line x1=\"" << px(x) << "\" y1=\"" << px(y) << "\" x2=\"" << px(x + 14 * d.x)
        << "\" y2=\"" << px(y - 14 * d.y) << "\" stroke=\"#d0342c\" stroke-width=\"1.6\"/>\n";
    }
    if (named)
      s << "<text x=\"" << px(x + 6) << "\" y=\"" << px(y - 6) << "\" stroke=\"#fff\" stroke-width=\"2.5\" "
        << "paint-order=\"stroke\">" << xmlEscape(m->name) << "</text>\n";
  }
  s << "</g>\n";
}

std::string planSvg(const GridReport& grid, const ColorScale& scale, const PlanOptions& opt) {
  const PlanPage page(grid, scale, opt);
  std::ostringstream s;
  writeSvgOpen(s, page);
  writeCells(s, page);
  if (opt.section) {
    writeFrame(s, page);
    writeSectionFurniture(s, *opt.section, page.frame());
  }
  writeOutline(s, page);
  if (opt.section) writeSectionCuts(s, *opt.section, page.frame());
  writeCellValues(s, page);
  writeContours(s, page);
  writeMarkers(s, page);
  writeAxes(s, page);
  writeScaleBarAndNorth(s, page);
  writeLegend(s, page);
  writePlanKey(s, page.key, page.left, page.top + page.planH + 52, page.width - page.left - 8);
  s << "</svg>\n";
  return s.str();
}

void writePlanSvg(const std::filesystem::path& path, const GridReport& grid, const ColorScale& scale,
                  const PlanOptions& options) {
  PlanOptions standalone = options;
  standalone.standalone = true;
  writeFileAtomic(path, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" + planSvg(grid, scale, standalone));
}

}  // namespace candela
