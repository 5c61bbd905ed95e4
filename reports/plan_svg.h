// False-colour plan of a grid as SVG: cells coloured by value, labelled isolux contours
// (marching squares), legend, scale bar and north arrow. Self-contained, for inlining in HTML.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "reports/falsecolor.h"
#include "reports/report_data.h"

namespace candela {

// Regular grids with more cells than this are drawn as one picture instead of an element a cell.
inline constexpr std::size_t kMaxSvgCells = 20000;
// Isolines are traced on at most this many nodes along each side of the lattice (isolines).
inline constexpr int kMaxContourNodes = 256;

struct PlanOptions {
  double maxPlanWidthPx = 480.0;      // the plan is scaled to fit these, aspect kept
  double maxPlanHeightPx = 380.0;
  std::vector<double> contourLevels;  // empty: legend ticks and midpoints inside (min, max)
  bool contours = true;
  bool cellValues = true;             // print values in cells when cells are >= 30 px, <= 200 cells
  double northDeg = 0.0;              // true north, degrees clockwise from plan +Y
  bool northArrow = true;             // false for an elevation (a wall's grid)
  std::string idPrefix = "plan";      // makes element ids unique when several plans share a page
  bool standalone = false;            // add the SVG namespace (files); HTML5 inline SVG needs none
  // Luminaires (a square with a cross) and observers (a dot with their line of sight) drawn over
  // the plan where they fall inside it, named when there are at most kMaxNamedMarkers of them.
  std::vector<PlanMarker> markers;
  // The scene's section at the plan's cut (reports/plan_section_svg.h), drawn over the cells and
  // under the markers, with a key under the plan; not owned, null: none.
  const PlanSection* section = nullptr;
};
inline constexpr std::size_t kMaxNamedMarkers = 40;

// What a plan of `layout` shows, in plan coordinates (m): its outline, lattice and points, from
// lo to hi; at least 1 m wide in each direction where they are not (a single row, a point).
struct PlanExtent {
  Vec2 lo{0.0}, hi{1.0};
};
PlanExtent planExtent(const PlanLayout& layout);

// One isoline: the polyline where the interpolated field equals `level` (plan coordinates, m).
struct ContourLine {
  double level = 0.0;
  std::vector<Vec2> points;
  bool closed = false;
};

// Marching squares (Lorensen & Cline's cube cases in 2-D) over the lattice of cell centres of a
// regular layout, linear interpolation along cell edges, saddles resolved by the mean of the
// four corners. Squares with a missing corner (cells outside a polygon) are skipped. A lattice of
// more than kMaxContourNodes nodes along a side is first averaged over square blocks of cells
// (the mean of the block's sensors, at the block's centre) down to at most that many: lines
// finer than that are below a plan's resolution, and a dense grid's sampling noise would
// otherwise draw millions of tiny loops (the time and memory a 10⁶-point grid's plan takes stay
// bounded).
std::vector<ContourLine> isolines(const PlanLayout& layout, const std::vector<double>& values, double level);

// The whole plan, `<svg ...>...</svg>`. The colour scale is the caller's so that plans and
// images of one report share it.
std::string planSvg(const GridReport& grid, const ColorScale& scale, const PlanOptions& options = {});

// Writes a standalone SVG file (with XML declaration), atomically.
void writePlanSvg(const std::filesystem::path& path, const GridReport& grid, const ColorScale& scale,
                  const PlanOptions& options = {});

// An SVG coordinate or length: two decimals, trailing zeros dropped ("12.5", "3", never "-0").
std::string svgNumber(double v);

// Escapes & < > " ' for XML/HTML text and attributes.
std::string xmlEscape(const std::string& text);

}  // namespace candela
