// The scene's section on a plan (reports/plan_svg.h): furniture outlines, cut walls, windows cut
// and windows above the cut, in the conventions of an architect's plan, and the plan's key.
#pragma once

#include <sstream>
#include <string>

#include "reports/report_data.h"

namespace candela {

// How a plan maps plan coordinates (m) to its px: x → left + (x − lo.x)·k, y → top + (hi.y − y)·k;
// the plan's frame is planW × planH px from (left, top).
struct PlanFrame {
  Vec2 lo{0.0}, hi{1.0};
  double k = 1.0;  // px per m
  double left = 0.0, top = 0.0, planW = 0.0, planH = 0.0;
  std::string idPrefix = "plan";
  double X(double u) const { return left + (u - lo.x) * k; }
  double Y(double v) const { return top + (hi.y - v) * k; }
};

// Geometry is clipped to the plan's frame grown by this (px), so that a wall along the plan's
// edge shows its whole width.
inline constexpr double kSectionClipMarginPx = 4.0;

// The clip path of the section, `<clipPath id="<idPrefix>-geo">`, for the plan's <defs>.
std::string sectionClipPath(const PlanFrame& f);

// The furniture outlines (grey, lightly filled so the grid's colours stay readable), drawn over
// the cells and under the calculation area's outline.
void writeSectionFurniture(std::ostringstream& s, const PlanSection& section, const PlanFrame& f);

// Walls (dark thick lines), windows cut (a light band between two thin blue lines) and windows
// above the cut (a light band with dashed blue edges around the wall cut below them), over the
// outline and under the isolines.
void writeSectionCuts(std::ostringstream& s, const PlanSection& section, const PlanFrame& f);

// What a plan's key lists: each item only when the plan shows it.
struct PlanKeyItems {
  bool walls = false, openings = false, openingsAbove = false, furniture = false;
  bool luminaires = false, observers = false;
  bool any() const { return walls || openings || openingsAbove || furniture || luminaires || observers; }
};
// The section's items that show inside the plan's frame (with the clip's margin).
PlanKeyItems sectionKeyItems(const PlanSection& section, const PlanFrame& f);
// The section's items that meet the plan region [lo, hi] (m).
PlanKeyItems sectionItemsIn(const PlanSection& section, const Vec2& lo, const Vec2& hi);

// The key's height (px) for a width of `width` px: rows of 16 px.
double planKeyHeight(const PlanKeyItems& items, double width);
// The key at (x, y) px, its items wrapped within `width` px.
void writePlanKey(std::ostringstream& s, const PlanKeyItems& items, double x, double y, double width);

// The caption's sentence on the section: where it is cut (and why, for a floor-level grid), what
// the dashed lines are when the plan shows windows above the cut, and what is left out; plain text.
std::string planSectionCaption(const PlanSection& section, const PlanKeyItems& shown);

}  // namespace candela
