#include "reports/html_report.h"

#include <cctype>
#include <cmath>
#include <sstream>

#include "base/atomic_file.h"
#include "reports/annual_charts.h"
#include "reports/falsecolor.h"
#include "reports/compliance_html.h"
#include "reports/installation_html.h"
#include "reports/plan_section_svg.h"
#include "reports/plan_svg.h"

namespace candela {

namespace {



constexpr const char* kCss = R"css(
:root { --ink:#1d2327; --muted:#5f6b73; --line:#d9dee2; --band:#f5f7f8; --accent:#2c5f7c;
        --pass:#1e7b34; --pass-bg:#e3f4e6; --fail:#b3261e; --fail-bg:#fbe5e3; }
* { box-sizing: border-box; }
body { margin:0; background:#eef1f3; color:var(--ink);
       font:14px/1.45 "Helvetica Neue", Helvetica, Arial, sans-serif; }
.page { max-width:1100px; margin:24px auto; background:#fff; box-shadow:0 1px 4px rgba(0,0,0,.12); }
header { padding:28px 36px 22px; border-bottom:4px solid var(--accent); }
header .kicker { text-transform:uppercase; letter-spacing:.12em; font-size:11px; color:var(--accent); font-weight:700; }
header h1 { margin:4px 0 6px; font-size:28px; font-weight:600; }
header p.desc { margin:0 0 12px; color:var(--muted); }
dl.meta { display:flex; flex-wrap:wrap; gap:6px 28px; margin:0; font-size:12px; }
dl.meta div { display:flex; gap:6px; } dl.meta dt { color:var(--muted); } dl.meta dd { margin:0; font-weight:600; }
section { padding:22px 36px; border-bottom:1px solid var(--line); }
.views { display:flex; gap:16px; flex-wrap:wrap; margin:8px 0 12px; }
.views figure { margin:0; } .views img { max-width:520px; width:100%; border:1px solid var(--line); }
.views figcaption { font-size:12px; color:#555; margin-top:4px; }
h2 { font-size:18px; margin:0 0 4px; font-weight:600; }
h2 .n { color:var(--accent); margin-right:8px; }
p.sub { margin:0 0 14px; color:var(--muted); font-size:13px; }
table { border-collapse:collapse; width:100%; font-size:13px; }
th, td { padding:6px 10px; border-bottom:1px solid var(--line); text-align:left; }
th { background:var(--band); font-weight:600; color:#3a444a; font-size:12px; }
td.num, th.num { text-align:right; font-variant-numeric:tabular-nums; }
.badge { display:inline-block; min-width:52px; text-align:center; padding:2px 8px; border-radius:10px;
         font-size:11px; font-weight:700; letter-spacing:.05em; text-transform:uppercase; }
.badge.pass { color:var(--pass); background:var(--pass-bg); border:1px solid #a8d5b1; }
.badge.fail { color:var(--fail); background:var(--fail-bg); border:1px solid #eeb1ab; }
.badge.na { color:var(--muted); background:var(--band); border:1px solid var(--line); }
.grid-body { display:flex; flex-wrap:wrap; gap:24px; align-items:flex-start; }
.grid-body figure { margin:0; flex:0 0 auto; }
.grid-body figcaption { font-size:11px; color:var(--muted); margin-top:4px; max-width:560px; }
.grid-body .metrics { flex:1 1 340px; min-width:340px; }
.metrics td.num { white-space:nowrap; }
.metrics td .f { display:block; color:var(--muted); font-size:11px; }
table.kv { max-width:560px; }
.kv td:first-child { color:var(--muted); width:40%; }
h3 { font-size:14px; margin:18px 0 6px; font-weight:600; }
.multiples { display:flex; flex-wrap:wrap; gap:14px; }
.multiples figure, .temporal { margin:0; }
.multiples figcaption, .temporal figcaption { font-size:11px; color:var(--muted); margin-top:2px; max-width:560px; }
.temporal img { max-width:100%; }
td code { font-size:12px; }
.schedule td, .surfaces td, .energy td { vertical-align:top; }
.schedule td .f, .surfaces td .f { display:block; color:var(--muted); font-size:11px; }
.schedule td.num, .schedule th.num { white-space:nowrap; }
.schedule td.lum { overflow-wrap:anywhere; }
table.compliance td.num, table.compliance td.pos { white-space:nowrap; }
table.compliance td.lvl { color:var(--muted); font-size:12px; padding-left:0; }
table.compliance td .f, table.compliance th .f { display:block; color:var(--muted); font-size:11px; font-weight:400; }
table.compliance .ok { color:var(--pass); font-weight:700; } table.compliance .no { color:var(--fail); font-weight:700; }
p.note { margin-top:10px; }
h4 { font-size:13px; margin:16px 0 4px; font-weight:600; }
.schedule td.polar { width:216px; padding:4px 8px 4px 0; }
.schedule td.polar svg { display:block; }
table.kv.energy { max-width:none; }
.energy td:first-child { width:26%; }
section.warnings { background:#fff4e0; border-left:6px solid #d98c00; }
section.warnings h2 { color:#8a5300; }
section.warnings li { margin:4px 0; } section.warnings code { font-size:12px; color:var(--muted); }
footer { padding:14px 36px 22px; font-size:11px; color:var(--muted); }
@page { size:A4; margin:12mm 11mm; }
@media print {
  body { background:#fff; font-size:12px; -webkit-print-color-adjust:exact; print-color-adjust:exact; }
  .page { box-shadow:none; margin:0; max-width:none; }
  header { padding:0 0 10px; } section { padding:12px 0; border-bottom:none; } footer { padding:10px 0 0; }
  section.grid, section.settings { break-before:page; }
  h2, h3 { break-after:avoid; }
  /* A grid's plan and its metrics table each stay whole; a page may fall between them (a plan
     with its key and a modelling table do not fit one page under the section's heading). */
  tr, figure, svg, img, .metrics { break-inside:avoid; }
  thead { display:table-header-group; }
  .schedule td.polar { width:136px; } .schedule td.polar svg { width:128px; height:auto; }
  .schedule td.lum { min-width:52mm; } .schedule th { font-size:10px; }
  svg { max-width:100%; height:auto; }
  .views img { max-width:100%; }
  a { color:inherit; text-decoration:none; }
}
)css";

std::string badge(Verdict v) {
  const char* cls = v == Verdict::kPass ? "pass" : v == Verdict::kFail ? "fail" : "na";
  return std::string("<span class=\"badge ") + cls + "\">" + verdictName(v) + "</span>";
}

// Decimals that suit a value in lux (or %) in a table: 0 above 100, 1 above 10, else 2.
std::string valueText(double v) {
  const double a = std::abs(v);
  return formatFixed(v, a >= 100.0 ? 0 : a >= 10.0 ? 1 : 2);
}

std::string unitText(const std::string& unit) { return unit == "%" ? "%" : " " + xmlEscape(unit); }

// A quantity's name with its symbol's index as a subscript: "Cylindrical illuminance Ē_z" →
// "Cylindrical illuminance Ē<sub>z</sub>" (the text escaped).
std::string quantityHtml(const std::string& name) {
  const std::size_t u = name.rfind('_');
  if (u == std::string::npos || u + 1 == name.size()) return xmlEscape(name);
  return xmlEscape(name.substr(0, u)) + "<sub>" + xmlEscape(name.substr(u + 1)) + "</sub>";
}

// The modelling rows of a grid (EN 12464-1:2021: Ē_z/Ē_h within 0.30–0.60).
void modellingTable(std::ostringstream& h, const ModellingResult& m) {
  h << "<table class=\"modelling\">\n<thead><tr><th>Modelling</th><th class=\"num\">Calculated</th>"
       "<th class=\"num\">Target</th><th>Result</th></tr></thead>\n<tbody>\n";
  h << "<tr><td>Average cylindrical illuminance Ē<sub>z</sub></td><td class=\"num\">" << valueText(m.cylindricalAverageLux)
    << " lx</td><td class=\"num\">—</td><td></td></tr>\n";
  h << "<tr><td>Average horizontal illuminance Ē<sub>h</sub></td><td class=\"num\">" << valueText(m.horizontalAverageLux)
    << " lx</td><td class=\"num\">—</td><td></td></tr>\n";
  h << "<tr><td>Modelling ratio<span class=\"f\">Ē<sub>z</sub> / Ē<sub>h</sub></span></td><td class=\"num\">"
    << formatFixed(m.ratio, 2) << "</td><td class=\"num\">" << formatFixed(kModellingRatioMin, 2) << "–"
    << formatFixed(kModellingRatioMax, 2) << "</td><td>" << badge(m.verdict) << "</td></tr>\n";
  h << "</tbody>\n</table>\n";
}

// Percent in tables: one decimal.
std::string pctText(double v) { return formatFixed(v, 1) + " %"; }

// "a, b and c".
std::string joinedList(const std::vector<std::string>& items) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i)
    out += (i == 0 ? "" : i + 1 == items.size() ? " and " : ", ") + xmlEscape(items[i]);
  return out;
}

// A plan of one per-sensor annual metric (0–100 %) with the grid's layout.
std::string metricPlan(const GridReport& g, const std::string& quantity, const std::vector<double>& values,
                       const PlanOptions& options) {
  GridReport m;
  m.name = g.name;
  m.quantity = quantity;
  m.unit = "%";
  m.values = values;
  m.stats = computeGridStats(values);
  m.layout = g.layout;
  return planSvg(m, ColorScale{0.0, 100.0, false}, options);
}

// What an annual grid's section draws from: the grid, its place in the report and the run.
struct AnnualPage {
  const GridReport& grid;
  std::size_t index;  // of the grid in the report, 0-based
  const RunInfo& run;
  double northDeg;

  const AnnualGridReport& annual() const { return *grid.annual; }
  const GridAnnualSummary& summary() const { return grid.annual->summary; }
  std::string id() const { return "annual" + std::to_string(index + 1); }
};

// The section's heading, its introduction and the DA300 plan.
void annualIntro(std::ostringstream& h, const AnnualPage& page) {
  const GridReport& g = page.grid;
  const AnnualGridReport& a = page.annual();
  const GridAnnualSummary& s = page.summary();
  using M = SensorAnnualMetrics;
  const std::size_t index = page.index;
  h << "<section class=\"grid annual\" id=\"annual-" << index + 1 << "\">\n<h2><span class=\"n\">" << index + 1
    << "</span>Annual daylight: " << xmlEscape(g.name) << "</h2>\n<p class=\"sub\">Climate-based daylight over "
    << s.occupiedHours << " occupied hours of the weather year, " << s.sensors
    << " sensors. Percentages of occupied hours are means over the sensors; sDA and ASE are shares of "
       "sensors (IES LM-83-12). UDI bins after Nabil &amp; Mardaljevic (2005): fell short &lt; 100 lx, "
       "supplementary 100–300 lx, autonomous 300–3000 lx, exceeded &gt; 3000 lx.</p>\n<div class=\"grid-body\">\n";
  if (!a.sensors.empty()) {
    PlanOptions opt;
    opt.northDeg = page.northDeg;
    opt.idPrefix = page.id() + "-da";
    opt.contourLevels = {25.0, 50.0, 75.0};
    h << "<figure>\n" << metricPlan(g, "Daylight autonomy DA300", annualColumn(a, &M::da), opt)
      << "<figcaption>DA300 per sensor: share of occupied hours with at least 300 lx from daylight, 0–100 %; "
         "lines at 25, 50 and 75 %.</figcaption>\n</figure>\n";
  }
}

// The table of the grid's annual metrics (means and shares over its sensors) and the run's timing.
void annualSummaryTable(std::ostringstream& h, const AnnualPage& page) {
  const GridAnnualSummary& s = page.summary();
  const RunInfo& run = page.run;
  h << "<div class=\"metrics\">\n<table>\n<thead><tr><th>Metric</th><th class=\"num\">Value</th><th>Meaning</th></tr>"
       "</thead>\n<tbody>\n";
  auto row = [&](const char* name, const std::string& value, const std::string& meaning) {
    h << "<tr><td>" << name << "</td><td class=\"num\">" << value << "</td><td>" << meaning << "</td></tr>\n";
  };
  row("Daylight autonomy DA<sub>300</sub>", pctText(s.DA300), "occupied hours with E ≥ 300 lx (mean over sensors)");
  row("Continuous daylight autonomy cDA<sub>300</sub>", pctText(s.cDA300),
      "as DA<sub>300</sub> with partial credit E/300 below 300 lx");
  row("Useful daylight illuminance, fell short (UDI-f)", pctText(s.UDI_fell_short), "occupied hours with E &lt; 100 lx");
  row("UDI supplementary (UDI-s)", pctText(s.UDI_supplementary), "100 ≤ E &lt; 300 lx");
  row("UDI autonomous (UDI-a)", pctText(s.UDI_autonomous), "300 ≤ E ≤ 3000 lx");
  row("UDI exceeded (UDI-e)", pctText(s.UDI_exceeded), "E &gt; 3000 lx");
  // LEED v4.1 EQ Daylight, option 1 (USGBC): 1, 2 or 3 points from an sDA300/50% of 40, 55 or
  // 75 %; an ASE1000,250 above 10 % is to be reported and its glare addressed.
  const int points = s.sDA300_50 >= 75.0 ? 3 : s.sDA300_50 >= 55.0 ? 2 : s.sDA300_50 >= 40.0 ? 1 : 0;
  row("Spatial daylight autonomy sDA<sub>300/50%</sub>", pctText(s.sDA300_50),
      ("sensors with DA<sub>300</sub> ≥ 50 %; LEED v4.1 option 1: " + std::to_string(points) +
       " point" + (points == 1 ? "" : "s") + " (1 from 40 %, 2 from 55 %, 3 from 75 %)"));
  row("Annual sunlight exposure ASE<sub>1000,250</sub>", pctText(s.ASE1000_250),
      s.ASE1000_250 > 10.0 ? "sensors with more than 250 h of direct sun ≥ 1000 lx; above LEED v4.1's 10 %: glare "
                             "to be addressed"
                           : "sensors with more than 250 h of direct sun ≥ 1000 lx; within LEED v4.1's 10 %");
  row("Sun hours", formatFixed(s.sunHoursMean, 0) + " h", "hours of the year with direct sun on the sensor (mean over sensors)");
  row("Occupied hours", std::to_string(s.occupiedHours), "hours counted in the percentages");
  if (!page.annual().windowGroups.empty()) {
    std::string hours;
    for (const AnnualGridReport::WindowGroupHours& w : page.annual().windowGroups)
      hours += (hours.empty() ? "" : "; ") + xmlEscape(w.name) + " " + std::to_string(w.blindsClosedHours) + " h";
    row("Window groups (LM-83 blinds)", std::to_string(page.annual().windowGroups.size()),
        "occupied hours with the group's blinds closed: " + hours);
  }
  if (!page.annual().windowStates.empty()) {
    std::string text;
    for (const AnnualGridReport::WindowStateResult& w : page.annual().windowStates)
      text += (text.empty() ? "" : "; ") + xmlEscape(w.group) + " " + xmlEscape(w.state) + ": " +
              std::to_string(w.occupiedHours) + " h, sDA " + pctText(w.summary.sDA300_50) + ", ASE " +
              pctText(w.summary.ASE1000_250);
    row("Window states", std::to_string(page.annual().windowStates.size()),
        "occupied hours of the switched year in each state; sDA and ASE with the group in that state all year: " + text);
  }
  if (run.coefficientsTimeS) row("Daylight-coefficient time", formatFixed(*run.coefficientsTimeS, 2) + " s", "daylight-coefficient step");
  if (run.productTimeS) row("Hourly product time", formatFixed(*run.productTimeS, 2) + " s", "hourly product over the year");
  h << "</tbody>\n</table>\n</div>\n</div>\n";
}

// The four UDI bins as small multiples.
void udiMultiples(std::ostringstream& h, const AnnualPage& page) {
  const GridReport& g = page.grid;
  const AnnualGridReport& a = page.annual();
  const GridAnnualSummary& s = page.summary();
  using M = SensorAnnualMetrics;
  const std::string id = page.id();
  struct Bin {
    const char* name;   // element ids
    const char* label;  // what the reader sees
    double M::*perSensor;
    double meanPct;
  };
  const Bin bins[] = {{"UDI_fell_short", "UDI-f, fell short (E &lt; 100 lx)", &M::udiFellShort, s.UDI_fell_short},
                      {"UDI_supplementary", "UDI-s, supplementary (100–300 lx)", &M::udiSupplementary,
                       s.UDI_supplementary},
                      {"UDI_autonomous", "UDI-a, autonomous (300–3000 lx)", &M::udiAutonomous, s.UDI_autonomous},
                      {"UDI_exceeded", "UDI-e, exceeded (E &gt; 3000 lx)", &M::udiExceeded, s.UDI_exceeded}};
  h << "<h3>Useful daylight illuminance</h3>\n<div class=\"multiples\">\n";
  for (const auto& [name, label, perSensor, meanPct] : bins) {
    if (a.sensors.empty()) continue;
    PlanOptions opt;
    opt.northDeg = page.northDeg;
    opt.idPrefix = id + "-" + name;
    opt.maxPlanWidthPx = 230.0;
    opt.maxPlanHeightPx = 170.0;
    opt.contours = false;
    opt.cellValues = false;
    h << "<figure>\n" << metricPlan(g, std::string(label).substr(0, 5), annualColumn(a, perSensor), opt) << "<figcaption>" << label << ", % of occupied hours ("
      << pctText(meanPct) << " mean)</figcaption>\n</figure>\n";
  }
  h << "</div>\n";
}

// The sDA/ASE plan, and the temporal map of the chosen sensor.
void sdaAseAndTemporalMap(std::ostringstream& h, const AnnualPage& page) {
  const GridReport& g = page.grid;
  const AnnualGridReport& a = page.annual();
  const GridAnnualSummary& s = page.summary();
  const std::vector<bool> pass = sdaPassPerSensor(a), ase = aseExceededPerSensor(a);
  if (!pass.empty()) {
    PlanOptions opt;
    opt.idPrefix = page.id() + "-sda";
    h << "<h3>Spatial daylight autonomy and annual sunlight exposure</h3>\n<figure class=\"temporal\">\n"
      << sdaAsePlanSvg(g.layout, pass, ase, opt) << "<figcaption>sDA<sub>300/50%</sub> = " << pctText(s.sDA300_50)
      << " of sensors, ASE<sub>1000,250</sub> = " << pctText(s.ASE1000_250) << " of sensors.</figcaption>\n</figure>\n";
  }

  if (a.chosenSensor >= 0 && !a.chosenSensorLux.empty()) {
    const TemporalMap map = temporalMap(a.chosenSensorLux, a.hours);
    std::string where;
    const std::size_t k = static_cast<std::size_t>(a.chosenSensor);
    if (k < g.layout.planPositions.size())
      where = " at (" + formatFixed(g.layout.planPositions[k].x, 2) + ", " + formatFixed(g.layout.planPositions[k].y, 2) +
              ") m";
    h << "<h3>Hourly illuminance of sensor " << a.chosenSensor << where << "</h3>\n<figure class=\"temporal\">"
      << "<img alt=\"temporal map of sensor " << a.chosenSensor << "\" width=\"" << map.image.width << "\" height=\""
      << map.image.height << "\" src=\"data:image/png;base64," << base64(encodePng(map.image))
      << "\"><figcaption>Temporal map: days of the year from left (1 January; month numbers below) to right, hours "
         "of the day from midnight (top) to midnight (bottom); illuminance in lx on a log scale from 10 to "
         "100 000 lx, values outside clamped.</figcaption></figure>\n";
  }
}

// "Annual daylight" section of an annual grid: DA300 plan and the summary table, UDI plans as
// small multiples, the sDA/ASE plan and the temporal map of the chosen sensor.
void annualSection(std::ostringstream& h, const AnnualPage& page) {
  annualIntro(h, page);
  annualSummaryTable(h, page);
  udiMultiples(h, page);
  sdaAseAndTemporalMap(h, page);
  h << "</section>\n";
}

// The page's head, its inline style and the report's header (case, time, software).
void pageHeader(std::ostringstream& h, const ReportData& data) {
  const RunInfo& run = data.run;
  h << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
    << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
    << "<title>" << xmlEscape(run.caseName) << " — lighting report</title>\n<style>" << kCss << "</style>\n</head>\n"
    << "<body>\n<div class=\"page\">\n<header>\n<div class=\"kicker\">Lighting calculation report</div>\n"
    << "<h1>" << xmlEscape(run.caseName) << "</h1>\n";
  if (!run.description.empty()) h << "<p class=\"desc\">" << xmlEscape(run.description) << "</p>\n";
  h << "<dl class=\"meta\">";
  auto meta = [&](const char* k, const std::string& v) {
    if (!v.empty()) h << "<div><dt>" << k << "</dt><dd>" << xmlEscape(v) << "</dd></div>";
  };
  meta("Case file", run.caseFile);
  meta("Calculated", run.startedAt);
  meta("Grids", std::to_string(data.grids.size()));
  meta("Software", "candela " + run.version);
  h << "</dl>\n</header>\n";
}

// The run's warnings, first thing under the header: a reader must see them before the numbers.
void warningsSection(std::ostringstream& h, const std::vector<Warning>& warnings) {
  if (warnings.empty()) return;
  h << "<section class=\"warnings\">\n<h2>Warnings (" << warnings.size()
    << ")</h2>\n<p class=\"sub\">The input is valid, but these results are probably not what was meant "
       "(docs/warnings.md).</p>\n<ul>\n";
  for (const Warning& w : warnings)
    h << "<li><strong>" << xmlEscape(printable(w.loc.str())) << "</strong>: " << xmlEscape(printable(w.message)) << " <code>["
      << xmlEscape(w.code) << "]</code></li>\n";
  h << "</ul>\n</section>\n";
}

// Summary of every grid.
void summarySection(std::ostringstream& h, const ReportData& data) {
  // The EN 12464-1 sentence and its symbols for illuminance grids; daylight factors (%) and annual
  // grids are said what they are.
  bool lux = false, df = false, annual = false;
  for (const GridReport& g : data.grids) (g.annual ? annual : g.unit == "%" ? df : lux) = true;
  h << "<section class=\"summary\">\n<h2>Summary</h2>\n<p class=\"sub\">Calculated values on each calculation "
       "grid against its design targets";
  if (lux)
    h << " (EN 12464-1: maintained illuminance Ē<sub>m</sub> and uniformity U<sub>0</sub> = E<sub>min</sub>/Ē must "
         "not fall below the requirement)";
  if (df) h << (lux ? "; daylight" : ". Daylight") << " factors in % of the outside horizontal illuminance under the CIE overcast sky";
  if (annual)
    h << (lux || df ? "; annual" : ". Annual") << " grids by their daylight autonomy DA in % of the occupied hours "
      << "(mean over the sensors; sDA, ASE and UDI in their own sections)";
  h << ".</p>\n";
  const bool mixed = lux + df + annual > 1;
  const std::string e = lux ? "E" : df ? "D" : "DA", mean = lux ? "Ē" : df ? "D̄" : "mean DA";
  h << "<table>\n<thead><tr><th>Grid</th><th class=\"num\">Points</th><th class=\"num\">" << (mixed ? "Average" : mean)
    << "</th><th class=\"num\">" << (mixed ? "Minimum" : e + "<sub>min</sub>") << "</th><th class=\"num\">"
    << (mixed ? "Maximum" : e + "<sub>max</sub>")
    << "</th><th class=\"num\">U<sub>0</sub></th><th class=\"num\">Target " << (lux ? "Ē<sub>m</sub>" : mean)
    << "</th><th class=\"num\">Target U<sub>0</sub></th><th>Result</th></tr></thead>\n<tbody>\n";
  for (std::size_t i = 0; i < data.grids.size(); ++i) {
    const GridReport& g = data.grids[i];
    const std::string u = unitText(g.unit);
    h << "<tr><td><a href=\"#" << (g.annual ? "annual-" : "grid-") << i + 1 << "\">" << xmlEscape(g.name) << "</a></td><td class=\"num\">"
      << g.stats.count << "</td><td class=\"num\">" << valueText(g.stats.averageLux) << u << "</td><td class=\"num\">"
      << valueText(g.stats.minimumLux) << u << "</td><td class=\"num\">" << valueText(g.stats.maximumLux) << u
      << "</td><td class=\"num\">" << formatFixed(g.stats.u0, 2) << "</td><td class=\"num\">"
      << (g.targets.averageLux ? valueText(*g.targets.averageLux) + u : "—") << "</td><td class=\"num\">"
      << (g.targets.uniformity ? formatFixed(*g.targets.uniformity, 2) : "—") << "</td><td>"
      << badge(g.check.overall) << "</td></tr>\n";
  }
  h << "</tbody>\n</table>\n";
  int checked = 0, failed = 0;
  const Verdict overall = overallVerdict(data, &checked, &failed);
  if (overall != Verdict::kNotChecked)
    h << "<p class=\"overall\">Overall result " << badge(overall) << ": "
      << (failed ? std::to_string(failed) + " of " + std::to_string(checked) + " checked lines fail"
                 : "all " + std::to_string(checked) + " checked lines pass")
      << " (" << joinedList(checkedCategories(data)) << ").</p>\n";
  for (std::size_t i = 0; i < data.grids.size(); ++i)
    if (const std::optional<ModellingResult>& m = data.grids[i].modelling)
      h << "<p>Modelling on <a href=\"#grid-" << i + 1 << "\">" << xmlEscape(data.grids[i].name)
        << "</a>: Ē<sub>z</sub> / Ē<sub>h</sub> = " << formatFixed(m->cylindricalAverageLux, 0) << " lx / "
        << formatFixed(m->horizontalAverageLux, 0) << " lx = " << formatFixed(m->ratio, 2) << " (EN 12464-1:2021: "
        << formatFixed(kModellingRatioMin, 2) << "–" << formatFixed(kModellingRatioMax, 2) << ") " << badge(m->verdict)
        << "</p>\n";
  std::size_t rated = 0, passed = 0;
  for (const ObserverReport& o : data.observers)
    if (const std::optional<bool> pass = o.pass()) {
      ++rated;
      passed += *pass;
    }
  if (rated > 0)
    h << "<p>Discomfort glare: " << passed << " of " << rated << " observer" << (rated > 1 ? "s" : "")
      << " within the limit UGR<sub>L</sub> (<a href=\"#observers\">observer positions</a>).</p>\n";
  h << "</section>\n";
}

// The head of a table of areas' required against achieved Ē and U0, with `first` naming them.
void requiredAchievedHead(std::ostringstream& h, const char* first) {
  h << "<table>\n<thead><tr><th>" << first << "</th><th class=\"num\">Points</th><th class=\"num\">Required "
       "Ē<sub>m</sub></th><th class=\"num\">Ē</th><th class=\"num\">Required U<sub>0</sub></th><th "
       "class=\"num\">U<sub>0</sub></th><th>Result</th></tr></thead>\n<tbody>\n";
}

// One row of such a table: grid i, linked to its section; `label` is HTML.
void requiredAchievedRow(std::ostringstream& h, const std::string& label, const ReportData& data, int i) {
  const GridReport& g = data.grids[static_cast<std::size_t>(i)];
  h << "<tr><td><a href=\"#grid-" << i + 1 << "\">" << label << "</a></td><td class=\"num\">" << g.stats.count
    << "</td><td class=\"num\">" << (g.targets.averageLux ? valueText(*g.targets.averageLux) + " lx" : "—")
    << "</td><td class=\"num\">" << valueText(g.stats.averageLux) << " lx</td><td class=\"num\">"
    << (g.targets.uniformity ? formatFixed(*g.targets.uniformity, 2) : "—") << "</td><td class=\"num\">"
    << formatFixed(g.stats.u0, 2) << "</td><td>" << badge(g.check.overall) << "</td></tr>\n";
}

// EN 12464-1:2021 per task area: the task area, its immediate surrounding and its background,
// required against achieved Ē and U0, the UGR at the observers standing there, Ra as required.
void taskAreasSection(std::ostringstream& h, const ReportData& data) {
  if (data.taskAreas.empty()) return;
  h << "<section class=\"grid\" id=\"task-areas\">\n<h2>Task areas (EN 12464-1:2021)</h2>\n<p class=\"sub\">Each "
       "task area with its immediate surrounding (a band 0.5 m wide) and its background (a band 3 m wide beyond it, "
       "within the room). The surrounding needs the maintained illuminance the standard relates to the task "
       "area's (750 lx or more: 500 lx; 500: 300; 300: 200; 200: 150; 150 or less: the task's) and U<sub>0</sub> "
       "≥ 0.40; the background a third of the surrounding's and U<sub>0</sub> ≥ 0.10. UGR is the highest "
       "at the observers standing in these areas.</p>\n";
  for (const TaskAreaReport& a : data.taskAreas) {
    h << "<h3>" << xmlEscape(a.name) << " " << badge(a.verdict) << "</h3>\n";
    requiredAchievedHead(h, "Area");
    const std::pair<const char*, int> rows[] = {
        {"Task area", a.task}, {"Immediate surrounding", a.surrounding}, {"Background", a.background}};
    for (const auto& [label, i] : rows) {
      if (i < 0) {
        h << "<tr><td>" << label << "</td><td colspan=\"6\">none: the task area and its surrounding fill the room"
          << "</td></tr>\n";
        continue;
      }
      requiredAchievedRow(h, label, data, i);
    }
    if (a.cylindrical >= 0) {
      const GridReport& z = data.grids[static_cast<std::size_t>(a.cylindrical)];
      if (z.targets.averageLux) requiredAchievedRow(h, "Cylindrical Ē<sub>z</sub>", data, a.cylindrical);
      if (const std::optional<ModellingResult>& m = z.modelling)
        h << "<tr><td><a href=\"#grid-" << a.cylindrical + 1 << "\">Modelling</a></td><td colspan=\"5\">Ē<sub>z</sub> / "
             "Ē<sub>h</sub> = " << formatFixed(m->ratio, 2) << " (required " << formatFixed(kModellingRatioMin, 2) << "–"
          << formatFixed(kModellingRatioMax, 2) << ")</td><td>" << badge(m->verdict) << "</td></tr>\n";
    }
    h << "<tr><td>Discomfort glare</td><td colspan=\"2\">" << a.observers.size() << " observer"
      << (a.observers.size() == 1 ? "" : "s") << "</td><td class=\"num\" colspan=\"2\">UGR<sub>L</sub> "
      << (a.ugrLimit ? formatFixed(*a.ugrLimit, 0) : "—") << "</td><td class=\"num\">UGR "
      << (a.ugr ? formatFixed(*a.ugr, 1) : a.observers.empty() ? "no observer" : "no luminaire in view") << "</td><td>"
      << badge(a.ugrVerdict) << "</td></tr>\n";
    if (a.ra) {
      h << "<tr><td>Colour rendering</td><td colspan=\"5\">R<sub>a</sub> ≥ " << formatFixed(*a.ra, 0) << " required; ";
      if (a.leastRa) {
        h << "the luminaires' lamps: R<sub>a</sub> ≥ " << formatFixed(*a.leastRa, 0) << " (their files' colour rendering)";
      } else if (!a.raUnknown.empty()) {
        std::string files;
        for (const std::string& f : a.raUnknown) files += (files.empty() ? "" : ", ") + f;
        h << "to be checked on the lamps' data: " << xmlEscape(files) << " state" << (a.raUnknown.size() == 1 ? "s" : "")
          << " no colour rendering (IES files do not)";
      } else {
        h << "no luminaire in the case";
      }
      h << "</td><td>" << badge(a.raVerdict) << "</td></tr>\n";
    }
    h << "</tbody>\n</table>\n";
  }
  h << "</section>\n";
}

// EN 12464-1:2021 walls and ceilings: each [[surface_grid]]'s grids, one per plane of the
// surfaces it names, required against achieved Ē and U0.
void surfaceGridsSection(std::ostringstream& h, const ReportData& data) {
  if (data.surfaceGrids.empty()) return;
  h << "<section class=\"grid\" id=\"walls-ceilings\">\n<h2>Walls and ceiling (EN 12464-1:2021)</h2>\n<p "
       "class=\"sub\">Illuminance on the room's surfaces, a grid for each plane, sensors facing the room. The standard "
       "asks, in any work place, for walls Ē<sub>m</sub> ≥ 50 lx and ceilings Ē<sub>m</sub> ≥ 30 lx; in offices, "
       "education and health care for walls ≥ 75 lx and ceilings ≥ 50 lx; U<sub>0</sub> ≥ 0.10 for all.</p>\n";
  for (const SurfaceGridReport& s : data.surfaceGrids) {
    h << "<h3>" << xmlEscape(s.name) << " " << badge(s.verdict) << "</h3>\n";
    if (!s.roomType.empty()) h << "<p>Requirements of the room type: " << xmlEscape(s.roomType) << ".</p>\n";
    requiredAchievedHead(h, "Surface");
    for (int i : s.grids) {
      const GridReport& g = data.grids[static_cast<std::size_t>(i)];
      std::string label = g.name.substr(std::min(g.name.size(), s.name.size() + 2));  // without "<name>: "
      label += " (" + g.roomSurface + ")";
      requiredAchievedRow(h, xmlEscape(label), data, i);
    }
    h << "</tbody>\n</table>\n";
  }
  h << "</section>\n";
}

// The metrics table of a point-in-time grid: calculated values against their targets.
void gridMetricsTable(std::ostringstream& h, const GridReport& g) {
  const std::string u = unitText(g.unit);
  h << "<div class=\"metrics\">\n<table>\n<thead><tr><th>Quantity</th><th class=\"num\">Calculated</th>"
       "<th class=\"num\">Target</th><th>Result</th></tr></thead>\n<tbody>\n";
  std::string quantity = g.quantity;
  for (char& ch : quantity) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  // A named quantity carries its own symbol ("cylindrical illuminance Ē_z").
  // Daylight-factor grids (%) in the daylight factor's symbols: D̄, D_min, D_max.
  const bool df = g.unit == "%";
  const std::string e = df ? "D" : "E", mean = df ? "D̄" : "Ē";
  const std::string label = df ? "daylight factor D̄"
                               : g.quantityKey.empty() ? xmlEscape(quantity) + " Ē" : quantityHtml(quantity);
  h << "<tr><td>Average " << label << "</td><td class=\"num\">" << valueText(g.stats.averageLux) << u << "</td><td class=\"num\">"
    << (g.targets.averageLux ? "≥ " + valueText(*g.targets.averageLux) + u : "—") << "</td><td>"
    << badge(g.check.average) << "</td></tr>\n";
  h << "<tr><td>Uniformity U<sub>0</sub><span class=\"f\">" << e << "<sub>min</sub> / " << mean
    << "</span></td><td class=\"num\">" << formatFixed(g.stats.u0, 2)
    << "</td><td class=\"num\">" << (g.targets.uniformity ? "≥ " + formatFixed(*g.targets.uniformity, 2) : "—")
    << "</td><td>" << badge(g.check.uniformity) << "</td></tr>\n";
  h << "<tr><td>Minimum " << e << "<sub>min</sub></td><td class=\"num\">" << valueText(g.stats.minimumLux) << u
    << "</td><td class=\"num\">—</td><td></td></tr>\n";
  h << "<tr><td>Maximum " << e << "<sub>max</sub></td><td class=\"num\">" << valueText(g.stats.maximumLux) << u
    << "</td><td class=\"num\">—</td><td></td></tr>\n";
  h << "<tr><td>Median" << (df ? " daylight factor (EN 17037's D)" : "") << "</td><td class=\"num\">"
    << valueText(g.stats.medianLux) << u
    << "</td><td class=\"num\">—</td><td></td></tr>\n";
  h << "<tr><td>Diversity U<sub>d</sub><span class=\"f\">" << e << "<sub>min</sub> / " << e
    << "<sub>max</sub></span></td><td class=\"num\">"
    << formatFixed(g.stats.ud, 2) << "</td><td class=\"num\">—</td><td></td></tr>\n";
  h << "<tr><td>Calculation points</td><td class=\"num\">" << g.stats.count << "</td><td class=\"num\">—</td><td></td></tr>\n";
  if (g.layout.regular)
    h << "<tr><td>Grid spacing</td><td class=\"num\">" << formatFixed(g.layout.spacingM.x, 3) << " × "
      << formatFixed(g.layout.spacingM.y, 3) << " m</td><td class=\"num\">—</td><td></td></tr>\n";
  h << "<tr><th>Overall</th><th></th><th></th><th>" << badge(g.check.overall) << "</th></tr>\n";
  h << "</tbody>\n</table>\n";
  if (g.modelling) modellingTable(h, *g.modelling);
  h << "</div>\n";
}

// The section of point-in-time grid `i` (0-based): its plan and metrics.
void gridSection(std::ostringstream& h, const GridReport& g, std::size_t i, const ReportData& data) {
  h << "<section class=\"grid\" id=\"grid-" << i + 1 << "\">\n<h2><span class=\"n\">" << i + 1 << "</span>"
    << xmlEscape(g.name) << "</h2>\n<p class=\"sub\">" << quantityHtml(g.quantity) << " in " << xmlEscape(g.unit);
  if (!g.description.empty()) h << " · " << xmlEscape(g.description);
  h << "</p>\n<div class=\"grid-body\">\n";
  if (!g.values.empty()) {
    PlanOptions opt;
    opt.northDeg = data.northDeg;
    opt.idPrefix = "plan" + std::to_string(i + 1);
    if (g.planIsXY) opt.markers = data.planMarkers;
    opt.northArrow = g.planIsXY;
    if (g.planIsXY && g.planSection >= 0 && static_cast<std::size_t>(g.planSection) < data.planSections.size())
      opt.section = &data.planSections[static_cast<std::size_t>(g.planSection)];
    const ColorScale scale = niceRange(g.stats.minimumLux, g.stats.maximumLux);
    // A wall's grid is drawn as an elevation seen from the room, a grid in another plane as that
    // plane: only a horizontal grid's is a plan.
    const char* drawing = g.planIsXY ? "plan" : g.roomSurface == "wall" ? "elevation, seen from the room," : "view";
    h << "<figure>\n" << planSvg(g, scale, opt) << "<figcaption>False-colour " << drawing << " of " << xmlEscape(g.name)
      << " with iso-" << (g.unit == "lx" ? "lux" : "value") << " lines; scale " << formatNumber(scale.minValue, 4)
      << "–" << formatNumber(scale.maxValue, 4) << unitText(g.unit) << ".";
    if (opt.section) {
      const PlanExtent e = planExtent(g.layout);
      h << " " << xmlEscape(planSectionCaption(*opt.section, sectionItemsIn(*opt.section, e.lo, e.hi)));
    }
    h << "</figcaption>\n</figure>\n";
  }
  gridMetricsTable(h, g);
  h << "</div>\n</section>\n";
}

// The section of view `i` (0-based). The pictures are embedded as data URIs, so the page stays
// one self-contained file.
void viewSection(std::ostringstream& h, const ViewReport& v, std::size_t i) {
  h << "<section class=\"grid\" id=\"view-" << i + 1 << "\">\n<h2>View: " << xmlEscape(v.name) << "</h2>\n<p class=\"sub\">"
    << xmlEscape(v.description) << "</p>\n<div class=\"views\">\n";
  if (!v.previewPng.empty())
    h << "<figure><img alt=\"tone-mapped view " << xmlEscape(v.name) << "\" src=\"data:image/png;base64,"
      << base64(v.previewPng) << "\"><figcaption>Tone-mapped luminance</figcaption></figure>\n";
  if (!v.falseColorPng.empty())
    h << "<figure><img alt=\"false-colour luminance of " << xmlEscape(v.name) << "\" src=\"data:image/png;base64,"
      << base64(v.falseColorPng) << "\"><figcaption>Luminance, cd/m²</figcaption></figure>\n";
  h << "</div>\n<table>\n<tbody>\n";
  for (const auto& [k, val] : v.metrics)
    h << "<tr><td>" << xmlEscape(k) << "</td><td class=\"num\">" << xmlEscape(val) << "</td></tr>\n";
  h << "</tbody>\n</table>\n</section>\n";
}

// Glare at the [[observer]] positions: UGR against EN 12464-1's UGR_L, one row each.
void observersSection(std::ostringstream& h, const std::vector<ObserverReport>& observers) {
  if (observers.empty()) return;
  h << "<section class=\"grid\" id=\"observers\">\n<h2>Discomfort glare at the observer positions</h2>\n"
       "<p class=\"sub\">Unified glare rating (CIE 117) from the luminaires in view along a horizontal line of "
       "sight, against the limit UGR<sub>L</sub> of EN 12464-1; no CIE 147 small- or large-source "
       "correction.</p>\n<table>\n<thead><tr><th>Observer</th><th>Eye position (m)</th><th>Line of sight</th>"
       "<th>Luminaires in view</th><th>Vertical illuminance at the eye (lx)</th><th>UGR</th><th>Limit UGR<sub>L</sub></th>"
       "<th>Verdict</th></tr></thead>\n<tbody>\n";
  for (const ObserverReport& o : observers) {
    const std::optional<bool> pass = o.pass();
    h << "<tr><td>" << xmlEscape(o.name) << "</td><td class=\"num\">(" << formatFixed(o.eyeM.x, 2) << ", "
      << formatFixed(o.eyeM.y, 2) << ", " << formatFixed(o.eyeM.z, 2) << ")</td><td class=\"num\">("
      << formatFixed(o.direction.x, 2) << ", " << formatFixed(o.direction.y, 2) << ")</td><td class=\"num\">"
      << o.luminairesInView << "</td><td class=\"num\">" << formatFixed(o.verticalLux, 0) << "</td><td class=\"num\">"
      << (o.ugr ? formatFixed(*o.ugr, 1) : std::string("none in view")) << "</td><td class=\"num\">"
      << (o.ugrLimit ? formatFixed(*o.ugrLimit, 0) : std::string("—")) << "</td><td>"
      << (pass ? (*pass ? "<span class=\"badge pass\">PASS</span>" : "<span class=\"badge fail\">FAIL</span>") : "—")
      << "</td></tr>\n";
  }
  h << "</tbody>\n</table>\n</section>\n";
}

// Calculation settings and timing, and the page's footer.
void settingsAndFooter(std::ostringstream& h, const RunInfo& run) {
  h << "<section class=\"settings\">\n<h2>Calculation</h2>\n<p class=\"sub\">Settings of this run; with the same "
       "seed and settings candela reproduces these numbers exactly, on any number of threads.</p>\n"
    << "<table class=\"kv\">\n<tbody>\n";
  auto row = [&](const std::string& k, const std::string& v) {
    h << "<tr><td>" << xmlEscape(k) << "</td><td>" << xmlEscape(v) << "</td></tr>\n";
  };
  for (const auto& [k, v] : run.settings) row(k, v);
  row("seed", std::to_string(run.seed));
  row("run time", formatFixed(run.runTimeS, run.runTimeS < 10 ? 2 : 1) + " s");
  if (run.coefficientsTimeS) row("daylight coefficients time", formatFixed(*run.coefficientsTimeS, 2) + " s");
  if (run.productTimeS) row("hourly product time", formatFixed(*run.productTimeS, 2) + " s");
  row("software", "candela " + run.version);
  h << "</tbody>\n</table>\n</section>\n";
  h << "<footer>Generated by candela " << xmlEscape(run.version)
    << ". Values are calculated at the points listed in each grid's CSV file. This report is self-contained "
       "and can be archived as a single file.</footer>\n"
    << "</div>\n</body>\n</html>\n";
}

}  // namespace

std::string htmlReport(const ReportData& data) {
  std::ostringstream h;
  pageHeader(h, data);
  warningsSection(h, data.warnings);
  summarySection(h, data);
  taskAreasSection(h, data);
  surfaceGridsSection(h, data);
  h << complianceHtml(data.compliance);
  if (data.installation)
    h << luminaireScheduleHtml(*data.installation) << energyHtml(*data.installation) << surfacesHtml(*data.installation);
  // One section per grid: plan and metrics.
  for (std::size_t i = 0; i < data.grids.size(); ++i) {
    const GridReport& g = data.grids[i];
    if (g.annual) {
      // Annual grids: their own section carries the DA plan and every metric (an illuminance
      // table of Emin, U0, ... would name the wrong quantities).
      annualSection(h, AnnualPage{g, i, data.run, data.northDeg});
      continue;
    }
    gridSection(h, g, i, data);
  }
  for (std::size_t i = 0; i < data.views.size(); ++i) viewSection(h, data.views[i], i);
  observersSection(h, data.observers);
  settingsAndFooter(h, data.run);
  return h.str();
}

void writeHtmlReport(const std::filesystem::path& path, const ReportData& data) {
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  writeFileAtomic(path, htmlReport(data));
}

}  // namespace candela
