#include "reports/plan_section_svg.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "reports/plan_svg.h"

namespace candela {

namespace {

std::string px(double v) { return svgNumber(v); }

// The section's colours and widths (px): walls near black and thick, as a plan's cut walls are;
// glazing a light blue that reads against both the violet and the yellow of the colour scale.
constexpr const char* kWallColour = "#222";
constexpr double kWallWidthPx = 2.8;
constexpr const char* kGlassColour = "#2f86c9";
constexpr const char* kGlassBand = "#d6ebf9";
constexpr double kOpeningHalfWidthPx = 2.6;   // the blue lines' offset from the glazing
constexpr double kAboveHalfWidthPx = 3.6;     // beside a 2.8 px wall, clear of it
constexpr const char* kFurnitureStroke = "#4d4d4d";

// " M x y L x y" of a segment offset by `offsetPx` to its left in px.
void lineTo(std::ostringstream& d, const PlanFrame& f, const PlanSegment& seg, double offsetPx) {
  const Vec2 a(f.X(seg.a.x), f.Y(seg.a.y)), b(f.X(seg.b.x), f.Y(seg.b.y));
  const Vec2 t = b - a;
  const double len = glm::length(t);
  if (len <= 0.0) return;
  const Vec2 n = Vec2(-t.y, t.x) / len * offsetPx;
  d << "M" << px(a.x + n.x) << " " << px(a.y + n.y) << "L" << px(b.x + n.x) << " " << px(b.y + n.y);
}

// One <path> of all the segments, each offset by every one of `offsetsPx`.
void segmentsPath(std::ostringstream& s, const PlanFrame& f, const std::vector<PlanSegment>& segments,
                  std::initializer_list<double> offsetsPx, const std::string& cls, const std::string& style) {
  if (segments.empty()) return;
  std::ostringstream d;
  for (const PlanSegment& seg : segments)
    for (double o : offsetsPx) lineTo(d, f, seg, o);
  s << "<path class=\"" << cls << "\" d=\"" << d.str() << "\" fill=\"none\" " << style << "/>\n";
}

// stroke="colour" stroke-width="w" and any more attributes.
std::string stroke(const char* colour, double widthPx, const char* more = "") {
  std::ostringstream a;
  a << "stroke=\"" << colour << "\" stroke-width=\"" << px(widthPx) << "\"" << more;
  return a.str();
}

// The key's items: label and width (px) at font size 10 (0.55 em a character, plus the swatch).
struct KeyItem {
  const char* label;
  int kind;  // 0 wall, 1 window, 2 window above, 3 furniture, 4 luminaire, 5 observer
};

std::vector<KeyItem> keyItems(const PlanKeyItems& k) {
  std::vector<KeyItem> items;
  if (k.walls) items.push_back({"wall, partition (cut)", 0});
  if (k.openings) items.push_back({"window", 1});
  if (k.openingsAbove) items.push_back({"window above the cut", 2});
  if (k.furniture) items.push_back({"furniture", 3});
  if (k.luminaires) items.push_back({"luminaire", 4});
  if (k.observers) items.push_back({"observer", 5});
  return items;
}

double keyItemWidth(const KeyItem& item) {
  return 22.0 + 5.5 * static_cast<double>(std::string(item.label).size()) + 14.0;
}

// A key item's swatch, 16 × 8 px from (x, y − 4).
void keySwatch(std::ostringstream& s, int kind, double x, double y) {
  switch (kind) {
    case 0:
      s << "<line x1=\"" << px(x) << "\" y1=\"" << px(y) << "\" x2=\"" << px(x + 16) << "\" y2=\"" << px(y)
        << "\" stroke=\"" << kWallColour << "\" stroke-width=\"" << px(kWallWidthPx) << "\"/>";
      break;
    case 1:
      s << "<rect x=\"" << px(x) << "\" y=\"" << px(y - kOpeningHalfWidthPx) << "\" width=\"16\" height=\""
        << px(2 * kOpeningHalfWidthPx) << "\" fill=\"" << kGlassBand << "\"/><path d=\"M" << px(x) << " "
        << px(y - kOpeningHalfWidthPx) << "h16M" << px(x) << " " << px(y + kOpeningHalfWidthPx) << "h16\" stroke=\""
        << kGlassColour << "\" stroke-width=\"1\"/>";
      break;
    case 2:
      s << "<rect x=\"" << px(x) << "\" y=\"" << px(y - kAboveHalfWidthPx) << "\" width=\"16\" height=\""
        << px(2 * kAboveHalfWidthPx) << "\" fill=\"" << kGlassBand << "\"/><line x1=\"" << px(x) << "\" y1=\"" << px(y) << "\" x2=\"" << px(x + 16) << "\" y2=\"" << px(y)
        << "\" stroke=\"" << kWallColour << "\" stroke-width=\"" << px(kWallWidthPx) << "\"/><path d=\"M" << px(x)
        << " " << px(y - kAboveHalfWidthPx) << "h16M" << px(x) << " " << px(y + kAboveHalfWidthPx) << "h16\" stroke=\""
        << kGlassColour << "\" stroke-width=\"1\" stroke-dasharray=\"3 2\"/>";
      break;
    case 3:
      s << "<rect x=\"" << px(x) << "\" y=\"" << px(y - 4) << "\" width=\"16\" height=\"8\" fill=\"#fff\" "
        << "fill-opacity=\"0.18\" stroke=\"" << kFurnitureStroke << "\" stroke-width=\"0.8\"/>";
      break;
    case 4:
      s << "<rect x=\"" << px(x + 4) << "\" y=\"" << px(y - 4) << "\" width=\"8\" height=\"8\" fill=\"#fff\" "
        << "stroke=\"#111\"/><path d=\"M" << px(x + 4) << " " << px(y - 4) << "l8 8m0 -8l-8 8\" stroke=\"#111\" "
        << "stroke-width=\"0.8\"/>";
      break;
    default:
      s << "<circle cx=\"" << px(x + 8) << "\" cy=\"" << px(y) << "\" r=\"4\" fill=\"#d0342c\"/>";
  }
}

}  // namespace

std::string sectionClipPath(const PlanFrame& f) {
  const double m = kSectionClipMarginPx;
  std::ostringstream s;
  s << "<clipPath id=\"" << f.idPrefix << "-geo\"><rect x=\"" << px(f.left - m) << "\" y=\"" << px(f.top - m)
    << "\" width=\"" << px(f.planW + 2 * m) << "\" height=\"" << px(f.planH + 2 * m) << "\"/></clipPath>";
  return s.str();
}

void writeSectionFurniture(std::ostringstream& s, const PlanSection& section, const PlanFrame& f) {
  if (section.furniture.empty()) return;
  // Outlined footprints in one path, mesh triangles (whose edges are not the object's) in another
  // without a stroke.
  std::ostringstream outlined, filled;
  for (const PlanFootprint& fp : section.furniture) {
    std::ostringstream& d = fp.outlined ? outlined : filled;
    for (std::size_t i = 0; i < fp.outline.size(); ++i)
      d << (i ? "L" : "M") << px(f.X(fp.outline[i].x)) << " " << px(f.Y(fp.outline[i].y));
    d << "Z";
  }
  s << "<g class=\"furniture\" clip-path=\"url(#" << f.idPrefix << "-geo)\">\n";
  if (!filled.str().empty())
    s << "<path d=\"" << filled.str() << "\" fill=\"#555\" fill-opacity=\"0.2\" stroke=\"none\"/>\n";
  if (!outlined.str().empty())
    s << "<path d=\"" << outlined.str() << "\" fill=\"#fff\" fill-opacity=\"0.18\" stroke=\"" << kFurnitureStroke
      << "\" stroke-width=\"0.8\" stroke-linejoin=\"round\"/>\n";
  s << "</g>\n";
}

void writeSectionCuts(std::ostringstream& s, const PlanSection& section, const PlanFrame& f) {
  if (section.walls.empty() && section.openings.empty() && section.openingsAbove.empty()) return;
  s << "<g class=\"section\" clip-path=\"url(#" << f.idPrefix << "-geo)\">\n";
  // A window above the cut (its sill higher than the plane): a light band with dashed edges
  // around the wall that is cut below it, as an architect draws what lies above the plan's cut.
  segmentsPath(s, f, section.openingsAbove, {0.0}, "openings-above-band", stroke(kGlassBand, 2 * kAboveHalfWidthPx));
  // Square caps close the corners where two walls' segments meet.
  segmentsPath(s, f, section.walls, {0.0}, "walls", stroke(kWallColour, kWallWidthPx, " stroke-linecap=\"square\""));
  // A window cut: the band hides any wall behind it (a sill drawn to the same line), the two thin
  // lines are the glazing's faces.
  segmentsPath(s, f, section.openings, {0.0}, "opening-band", stroke(kGlassBand, 2 * kOpeningHalfWidthPx));
  segmentsPath(s, f, section.openings, {-kOpeningHalfWidthPx, kOpeningHalfWidthPx}, "openings",
               stroke(kGlassColour, 1.0));
  segmentsPath(s, f, section.openingsAbove, {-kAboveHalfWidthPx, kAboveHalfWidthPx}, "openings-above",
               stroke(kGlassColour, 1.0, " stroke-dasharray=\"3 2\""));
  s << "</g>\n";
}

PlanKeyItems sectionKeyItems(const PlanSection& section, const PlanFrame& f) {
  // What shows inside the clip: the plan's extent grown by the clip's margin.
  return sectionItemsIn(section, f.lo - Vec2(kSectionClipMarginPx / f.k), f.hi + Vec2(kSectionClipMarginPx / f.k));
}

PlanKeyItems sectionItemsIn(const PlanSection& section, const Vec2& lo, const Vec2& hi) {
  auto shows = [&](const Vec2& a, const Vec2& b) {
    return std::min(a.x, b.x) <= hi.x && std::max(a.x, b.x) >= lo.x && std::min(a.y, b.y) <= hi.y &&
           std::max(a.y, b.y) >= lo.y;
  };
  auto anyShows = [&](const std::vector<PlanSegment>& segments) {
    return std::any_of(segments.begin(), segments.end(), [&](const PlanSegment& g) { return shows(g.a, g.b); });
  };
  PlanKeyItems k;
  k.walls = anyShows(section.walls);
  k.openings = anyShows(section.openings);
  k.openingsAbove = anyShows(section.openingsAbove);
  for (const PlanFootprint& fp : section.furniture) {
    Vec2 a(fp.outline[0]), b(fp.outline[0]);
    for (const Vec2& p : fp.outline) a = glm::min(a, p), b = glm::max(b, p);
    k.furniture = k.furniture || shows(a, b);
  }
  return k;
}

double planKeyHeight(const PlanKeyItems& items, double width) {
  const std::vector<KeyItem> list = keyItems(items);
  if (list.empty()) return 0.0;
  int rows = 1;
  double x = 0.0;
  for (const KeyItem& item : list) {
    const double w = keyItemWidth(item);
    if (x > 0.0 && x + w > width) ++rows, x = 0.0;
    x += w;
  }
  return 16.0 * rows;
}

void writePlanKey(std::ostringstream& s, const PlanKeyItems& items, double x0, double y0, double width) {
  const std::vector<KeyItem> list = keyItems(items);
  if (list.empty()) return;
  s << "<g class=\"key\" font-size=\"10\" fill=\"#333\">\n";
  double x = 0.0, y = y0 + 8.0;
  for (const KeyItem& item : list) {
    const double w = keyItemWidth(item);
    if (x > 0.0 && x + w > width) y += 16.0, x = 0.0;
    keySwatch(s, item.kind, x0 + x, y);
    s << "<text x=\"" << px(x0 + x + 22) << "\" y=\"" << px(y) << "\" dominant-baseline=\"central\">" << item.label
      << "</text>\n";
    x += w;
  }
  s << "</g>\n";
}

std::string planSectionCaption(const PlanSection& section, const PlanKeyItems& shown) {
  std::ostringstream t;
  t << "Walls, windows and furniture cut at " << formatFixed(section.cutHeightM, 2) << " m";
  if (section.raisedAboveFloor)
    t << ", " << formatFixed(section.cutHeightM - section.floorLevelM, 2) << " m above the floor at "
      << formatFixed(section.floorLevelM, 2) << " m (the grid lies at floor level: an architect's plan cut).";
  else
    t << " (the grid's height).";
  if (shown.openingsAbove) t << " Dashed: windows above the cut.";
  if (section.droppedSegments > 0) t << " " << section.droppedSegments << " cut lines beyond the plan's limit not drawn.";
  if (section.droppedFootprints > 0)
    t << " " << section.droppedFootprints << " furniture outlines beyond the plan's limit not drawn.";
  if (section.skippedCurved > 0)
    t << " " << section.skippedCurved << " spheres, cones or rings crossing the cut not drawn.";
  return t.str();
}

}  // namespace candela
