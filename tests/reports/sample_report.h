// A synthetic but physically plausible report for the reports tests (and the screenshot check):
// a 6 m × 4 m office lit by a 3 × 2 array of point sources of 1000 cd, straight down, 2.0 m
// above the work plane; E = I·cos³θ/h² (inverse-square cosine law) summed over the sources.
#pragma once

#include <cmath>
#include <cstdint>

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

// A synthetic year for the annual reports: hour stamps from the month lengths of a non-leap
// year; outdoor horizontal illuminance 100 klx × sin of a day-arc (sunrise 06:00, sunset 18:00)
// scaled by season; a sensor y m from the window wall (y = 0) sees 5 % of it × exp(−y / 1.2 m),
// plus 8 klx of direct sun from 10:00 to 14:00 on two days out of three when y is less than
// 1 m + 1.5 m × winter factor (low winter sun reaches deeper). Metrics over the occupied hours
// 08:00–18:00 are computed here with plain loops (the reports only print what they are given).
// Hour stamps of a year from the month lengths (not from any candela code).
inline std::vector<HourStamp> sampleYearStamps(bool leap = false) {
  const int days[12] = {31, leap ? 29 : 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  std::vector<HourStamp> out;
  for (int m = 1; m <= 12; ++m)
    for (int d = 1; d <= days[m - 1]; ++d)
      for (int h = 1; h <= 24; ++h)
        out.push_back({static_cast<uint8_t>(m), static_cast<uint8_t>(d), static_cast<uint8_t>(h)});
  return out;
}

struct SampleHour {
  double lux = 0.0;
  bool directSun = false;
};

inline SampleHour sampleSensorHour(double yM, int hourIndex) {
  const int day = hourIndex / 24;
  const double mid = hourIndex % 24 + 0.5;  // middle of the hour, h
  const double season = 0.5 * (1.0 + std::cos(2.0 * 3.141592653589793 * (day - 172) / 365.0));  // 1 at midsummer
  const double arc = std::sin(3.141592653589793 * (mid - 6.0) / 12.0);
  const double outdoor = mid > 6.0 && mid < 18.0 ? 100000.0 * arc * (0.4 + 0.6 * season) : 0.0;
  SampleHour s;
  s.directSun = mid > 10.0 && mid < 14.0 && day % 3 != 0 && yM < 1.0 + 1.5 * (1.0 - season);
  s.lux = 0.05 * outdoor * std::exp(-yM / 1.2) + (s.directSun ? 8000.0 : 0.0);
  return s;
}

inline AnnualGridReport sampleAnnual(const GridReport& grid) {
  AnnualGridReport a;
  a.hours = sampleYearStamps();
  const std::size_t n = grid.values.size();
  int occupied = 0;
  double sda = 0.0, ase = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double y = grid.layout.planPositions[i].y;
    double da = 0, cda = 0, fell = 0, sup = 0, aut = 0, exc = 0;
    int aseH = 0, sunH = 0;
    occupied = 0;
    for (std::size_t h = 0; h < a.hours.size(); ++h) {
      const int hourEnding = a.hours[h].hourEnding;
      if (hourEnding <= 8 || hourEnding > 18) continue;  // occupied 08:00-18:00
      ++occupied;
      const SampleHour s = sampleSensorHour(y, static_cast<int>(h));
      da += s.lux >= 300.0;
      cda += std::min(1.0, s.lux / 300.0);
      fell += s.lux < 100.0;
      sup += s.lux >= 100.0 && s.lux < 300.0;
      aut += s.lux >= 300.0 && s.lux <= 3000.0;
      exc += s.lux > 3000.0;
      sunH += s.directSun;  // the sun patch lies within the occupied hours: same as the whole year
      aseH += s.directSun;  // the sun patch is 8 klx >= 1000 lx
    }
    auto pct = [&](double hours) { return 100.0 * hours / occupied; };
    SensorAnnualMetrics m;
    m.da = pct(da);
    m.cda = pct(cda);
    m.udiFellShort = pct(fell);
    m.udiSupplementary = pct(sup);
    m.udiAutonomous = pct(aut);
    m.udiExceeded = pct(exc);
    m.aseHours = aseH;
    m.sunHours = sunH;
    m.sdaPass = m.da >= 50.0;
    m.aseExceeded = aseH > 250;
    a.sensors.push_back(m);
    sda += m.sdaPass;
    ase += m.aseExceeded;
  }
  using M = SensorAnnualMetrics;
  auto mean = [&](auto field) {
    double sum = 0.0;
    for (double x : annualColumn(a, field)) sum += x;
    return sum / static_cast<double>(n);
  };
  a.summary.DA300 = mean(&M::da);
  a.summary.cDA300 = mean(&M::cda);
  a.summary.UDI_fell_short = mean(&M::udiFellShort);
  a.summary.UDI_supplementary = mean(&M::udiSupplementary);
  a.summary.UDI_autonomous = mean(&M::udiAutonomous);
  a.summary.UDI_exceeded = mean(&M::udiExceeded);
  a.summary.sDA300_50 = 100.0 * sda / static_cast<double>(n);
  a.summary.ASE1000_250 = 100.0 * ase / static_cast<double>(n);
  a.summary.sunHoursMean = mean(&M::sunHours);
  a.summary.sensors = static_cast<int>(n);
  a.summary.occupiedHours = occupied;
  // The lead picks the grid's centre sensor; so does the sample.
  const int cx = grid.layout.columns / 2, cy = grid.layout.rows / 2;
  a.chosenSensor = cy * grid.layout.columns + cx;
  const double yc = grid.layout.planPositions[static_cast<std::size_t>(a.chosenSensor)].y;
  for (std::size_t h = 0; h < a.hours.size(); ++h)
    a.chosenSensorLux.push_back(sampleSensorHour(yc, static_cast<int>(h)).lux);
  return a;
}

// The office report plus an annual daylight grid whose plan values are its DA300 (%).
inline ReportData sampleAnnualReport() {
  ReportData d = sampleReport();
  GridReport g = sampleGrid("Daylit office", 0.0, 0.0, 6.0, 4.0, 0.25);
  g.annual = sampleAnnual(g);
  g.quantity = "Daylight autonomy DA300";
  g.unit = "%";
  g.values = annualColumn(*g.annual, &SensorAnnualMetrics::da);
  g.stats = computeGridStats(g.values);
  g.targets = {};
  g.check = checkTargets(g.stats, g.targets);
  d.grids.push_back(g);
  d.run.coefficientsTimeS = 12.5;
  d.run.productTimeS = 0.75;
  d.run.settings.push_back({"sky", "annual, weather = sample.epw"});
  return d;
}

}  // namespace candela::testing_sample
