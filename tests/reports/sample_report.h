// A synthetic but physically plausible report for the reports tests (and the screenshot check):
// a 6 m × 4 m office lit by a 3 × 2 array of point sources of 1000 cd, straight down, 2.0 m
// above the work plane; E = I·cos³θ/h² (inverse-square cosine law) summed over the sources.
#pragma once

#include <cmath>

#include "reports/report_data.h"

namespace candela::testing_sample {

inline double pointSourcesLux(double x, double y) {
  double e = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 2; ++j) {
      const double dx = x - (1.0 + 2.0 * i), dy = y - (1.0 + 2.0 * j), h = 2.0;
      const double d2 = dx * dx + dy * dy + h * h;
      e += 1000.0 * h / (d2 * std::sqrt(d2));  // I cosθ / d² with cosθ = h/d
    }
  return e;
}

// A regular grid over [x0,x1]×[y0,y1] at spacing s (cell centres), values from pointSourcesLux.
inline GridReport sampleGrid(const std::string& name, double x0, double y0, double x1, double y1, double s,
                             std::vector<ReportPoint>* points = nullptr) {
  GridReport g;
  g.name = name;
  g.description = "horizontal work plane at 0.80 m";
  g.layout.regular = true;
  g.layout.columns = static_cast<int>(std::lround((x1 - x0) / s));
  g.layout.rows = static_cast<int>(std::lround((y1 - y0) / s));
  g.layout.originM = Vec2(x0, y0);
  g.layout.spacingM = Vec2(s);
  g.layout.outline = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  for (int j = 0; j < g.layout.rows; ++j)
    for (int i = 0; i < g.layout.columns; ++i) {
      const Vec2 p(x0 + (i + 0.5) * s, y0 + (j + 0.5) * s);
      g.layout.cells.emplace_back(i, j);
      g.layout.planPositions.push_back(p);
      g.values.push_back(pointSourcesLux(p.x, p.y));
      if (points) points->push_back({Vec3(p.x, p.y, 0.8), Vec3(0, 0, 1)});
    }
  g.stats = computeGridStats(g.values);
  return g;
}

inline ReportData sampleReport() {
  ReportData d;
  d.run.caseName = "Open office, level 2";
  d.run.description = "Six 1000 cd downlights over a 6 m × 4 m office; EN 12464-1 writing task.";
  d.run.caseFile = "cases/office/case.toml";
  d.run.version = "0.1.0";
  d.run.startedAt = "2026-03-21 12:00";
  d.run.seed = 7;
  d.run.runTimeS = 3.25;
  d.run.settings = {{"quality", "normal"}, {"method", "cache"}, {"bounces", "2"}, {"samples", "512"},
                    {"threads", "all (8)"}};
  d.northDeg = 20.0;
  GridReport a = sampleGrid("Work plane", 0.5, 0.5, 5.5, 3.5, 0.25);
  a.targets = {500.0, 0.6};
  a.check = checkTargets(a.stats, a.targets);
  GridReport b = sampleGrid("Desk <A&B>", 1.0, 1.0, 3.0, 2.0, 0.25);
  b.targets = {750.0, 0.7};
  b.check = checkTargets(b.stats, b.targets);
  GridReport c = sampleGrid("Circulation", 0.0, 0.0, 6.0, 4.0, 0.5);
  c.targets = {100.0, std::nullopt};
  c.check = checkTargets(c.stats, c.targets);
  d.grids = {a, b, c};
  return d;
}

}  // namespace candela::testing_sample
