#include "study/task_area_report.h"

#include "metrics/targets.h"
#include "study/grids/sensor_grid.h"

#include <algorithm>

namespace candela {

namespace {

const char* areaName(GridSpec::Area a) {
  switch (a) {
    case GridSpec::Area::kTask: return "task area";
    case GridSpec::Area::kSurrounding: return "immediate surrounding";
    case GridSpec::Area::kBackground: return "background";
    case GridSpec::Area::kCylindrical: return "cylindrical";
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

// Whether plan point p stands in task area a, its immediate surrounding or its background (within
// 0.5 + 3 m of it): the observers and luminaires that count for it.
bool inTaskAreaReach(const TaskAreaSpec& a, const Vec2& p) {
  return insidePolygon(a.outline, p) || distanceToOutline(a.outline, p) <= kImmediateSurroundingWidthM + kBackgroundWidthM;
}

// The index of the grid report named `name` in data.grids, -1 when there is none (a band its
// room leaves empty).
int gridReportIndex(const ReportData& data, const std::string& name) {
  const auto g = std::find_if(data.grids.begin(), data.grids.end(), [&](const GridReport& r) { return r.name == name; });
  return g == data.grids.end() ? -1 : static_cast<int>(g - data.grids.begin());
}

// The task area's required Ra against the least Ra of the luminaires over it: those placed (in
// plan) in the task area, its surrounding or its background, else every luminaire of the case.
// Checked when every such luminaire's file states its colour rendering (EULUMDAT), else not
// (those files named).
void checkColourRendering(const CaseFile& c, const TaskAreaSpec& area, const ReportData& data, TaskAreaReport& r) {
  if (!data.installation || data.installation->luminaires.empty()) return;
  const std::vector<LuminaireTypeReport>& types = data.installation->luminaires;
  std::vector<bool> over(types.size(), false);
  for (const LuminairePlacement& p : c.luminaires) {
    if (!inTaskAreaReach(area, Vec2(p.positionM.x, p.positionM.y))) continue;
    const std::size_t e = static_cast<std::size_t>(p.entry);
    const std::string& entry = e < c.luminaireEntries.size() ? c.luminaireEntries[e].name : p.name;
    for (std::size_t t = 0; t < types.size(); ++t)
      if (std::find(types[t].entries.begin(), types[t].entries.end(), entry) != types[t].entries.end()) over[t] = true;
  }
  if (std::none_of(over.begin(), over.end(), [](bool b) { return b; })) over.assign(types.size(), true);
  for (std::size_t i = 0; i < types.size(); ++i) {
    if (!over[i]) continue;
    const LuminaireTypeReport& t = types[i];
    if (!t.leastRa) {
      if (std::find(r.raUnknown.begin(), r.raUnknown.end(), t.file) == r.raUnknown.end()) r.raUnknown.push_back(t.file);
      continue;
    }
    r.leastRa = std::min(r.leastRa.value_or(*t.leastRa), *t.leastRa);
  }
  if (!r.raUnknown.empty()) {
    r.leastRa.reset();
    return;
  }
  r.raVerdict = *r.leastRa >= *r.ra ? Verdict::kPass : Verdict::kFail;
}

}  // namespace

void addTaskAreaReports(const CaseFile& c, ReportData& data) {
  std::vector<TaskAreaReport>& areas = data.taskAreas;
  for (const TaskAreaSpec& a : c.taskAreas) {
    TaskAreaReport r;
    r.name = a.name;
    r.ugrLimit = a.ugrLimit;
    r.ra = a.ra;
    areas.push_back(std::move(r));
  }
  // Each task area's grids: the reports of the grids it made (a band its room leaves empty has
  // none), labelled.
  for (const GridSpec& spec : c.grids) {
    if (spec.area == GridSpec::Area::kNone) continue;
    const int i = gridReportIndex(data, spec.name);
    if (i < 0) continue;
    GridReport& g = data.grids[static_cast<std::size_t>(i)];
    g.taskArea = spec.taskArea;
    g.area = areaName(spec.area);
    TaskAreaReport& r = *std::find_if(areas.begin(), areas.end(),
                                      [&](const TaskAreaReport& a) { return a.name == spec.taskArea; });
    int& slot = spec.area == GridSpec::Area::kTask          ? r.task
                : spec.area == GridSpec::Area::kSurrounding ? r.surrounding
                : spec.area == GridSpec::Area::kBackground  ? r.background
                                                            : r.cylindrical;
    slot = i;
  }
  for (std::size_t ai = 0; ai < c.taskAreas.size(); ++ai) {
    const TaskAreaSpec& a = c.taskAreas[ai];
    TaskAreaReport& r = areas[ai];
    std::vector<Verdict> verdicts;
    for (int i : {r.task, r.surrounding, r.background, r.cylindrical})
      if (i >= 0) verdicts.push_back(data.grids[static_cast<std::size_t>(i)].check.overall);
    if (r.cylindrical >= 0)
      if (const std::optional<ModellingResult>& m = data.grids[static_cast<std::size_t>(r.cylindrical)].modelling)
        verdicts.push_back(m->verdict);
    // The observers standing in the task area, its surrounding or its background.
    for (std::size_t k = 0; k < c.observers.size() && k < data.observers.size(); ++k) {
      const Vec2 p = c.observers[k].positionM;
      if (!inTaskAreaReach(a, p)) continue;
      const ObserverReport& o = data.observers[k];
      r.observers.push_back(o.name);
      if (o.ugr) r.ugr = std::max(r.ugr.value_or(o.ugr.value()), *o.ugr);
    }
    if (r.ugrLimit && !r.observers.empty())
      r.ugrVerdict = !r.ugr || *r.ugr <= *r.ugrLimit ? Verdict::kPass : Verdict::kFail;
    verdicts.push_back(r.ugrVerdict);
    if (r.ra) checkColourRendering(c, a, data, r);
    verdicts.push_back(r.raVerdict);
    r.verdict = combine(verdicts);
  }
}

void addSurfaceGridReports(const CaseFile& c, ReportData& data) {
  for (const SurfaceGridSpec& s : c.surfaceGrids) {
    SurfaceGridReport r;
    r.name = s.name;
    if (s.roomType) r.roomType = roomTypeKey(*s.roomType);
    std::vector<Verdict> verdicts;
    for (const GridSpec& spec : c.grids) {
      if (spec.surfaceGrid != s.name) continue;
      const int i = gridReportIndex(data, spec.name);
      if (i < 0) continue;
      GridReport& g = data.grids[static_cast<std::size_t>(i)];
      g.surfaceGrid = s.name;
      g.roomSurface = roomSurfaceName(spec.roomSurface);
      r.grids.push_back(i);
      verdicts.push_back(g.check.overall);
    }
    r.verdict = combine(verdicts);
    data.surfaceGrids.push_back(std::move(r));
  }
}

}  // namespace candela
