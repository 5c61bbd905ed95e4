#include "study/task_area_report.h"

#include "metrics/targets.h"
#include "study/sensor_grid.h"

#include <algorithm>

namespace candela {

namespace {

const char* areaName(GridSpec::Area a) {
  switch (a) {
    case GridSpec::Area::kTask: return "task area";
    case GridSpec::Area::kSurrounding: return "immediate surrounding";
    case GridSpec::Area::kBackground: return "background";
    case GridSpec::Area::kNone: break;
  }
  return "";
}

// Fail when any checked verdict fails, pass when at least one is checked and all pass.
Verdict combine(const std::vector<Verdict>& verdicts) {
  Verdict out = Verdict::kNotChecked;
  for (Verdict v : verdicts) {
    if (v == Verdict::kFail) return Verdict::kFail;
    if (v == Verdict::kPass) out = Verdict::kPass;
  }
  return out;
}

}  // namespace

void addTaskAreaReports(const CaseFile& c, ReportData& data) {
  for (const GridSpec& spec : c.grids) {
    if (spec.area == GridSpec::Area::kNone) continue;
    for (GridReport& g : data.grids)
      if (g.name == spec.name) {
        g.taskArea = spec.taskArea;
        g.area = areaName(spec.area);
      }
  }
  for (const TaskAreaSpec& a : c.taskAreas) {
    TaskAreaReport r;
    r.name = a.name;
    r.ugrLimit = a.ugrLimit;
    r.ra = a.ra;
    std::vector<Verdict> verdicts;
    for (std::size_t i = 0; i < data.grids.size(); ++i) {
      const GridReport& g = data.grids[i];
      if (g.taskArea != a.name) continue;
      int& slot = g.area == "task area" ? r.task : g.area == "immediate surrounding" ? r.surrounding : r.background;
      slot = static_cast<int>(i);
      verdicts.push_back(g.check.overall);
    }
    // The observers standing in the task area, its surrounding or its background.
    const double reach = kImmediateSurroundingWidthM + kBackgroundWidthM;
    for (std::size_t k = 0; k < c.observers.size() && k < data.observers.size(); ++k) {
      const Vec2 p = c.observers[k].positionM;
      if (!insidePolygon(a.outline, p) && distanceToOutline(a.outline, p) > reach) continue;
      const ObserverReport& o = data.observers[k];
      r.observers.push_back(o.name);
      if (o.ugr) r.ugr = std::max(r.ugr.value_or(o.ugr.value()), *o.ugr);
    }
    if (r.ugrLimit && !r.observers.empty())
      r.ugrVerdict = !r.ugr || *r.ugr <= *r.ugrLimit ? Verdict::kPass : Verdict::kFail;
    verdicts.push_back(r.ugrVerdict);
    r.verdict = combine(verdicts);
    data.taskAreas.push_back(std::move(r));
  }
}

}  // namespace candela
