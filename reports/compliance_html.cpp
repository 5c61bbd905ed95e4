// The report's compliance section: one part per [[compliance]] entry (docs/compliance.md).
#include "reports/compliance_html.h"

#include "reports/plan_svg.h"
#include "reports/report_data.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace candela {

namespace {

std::string pct(double fraction) { return formatFixed(100.0 * fraction, 1) + " %"; }
std::string lv(En17037Level l) { return std::string(levelWords(l)); }
std::string levelBadge(En17037Level l) {
  return std::string("<span class=\"badge ") + (l == En17037Level::kNone ? "fail" : "pass") + "\">" + lv(l) + "</span>";
}
// A part's level beside its value, muted, in its own cell.
std::string levelCell(En17037Level l) { return "<td class=\"lvl\">" + lv(l) + "</td>"; }
// A figure and whether it meets its requirement: ✓ or ✗, read out by screen readers.
std::string marked(const std::string& value, bool pass) {
  return value + (pass ? " <span class=\"ok\" title=\"meets it\">✓</span>" : " <span class=\"no\" title=\"does not\">✗</span>");
}
std::string xyz(const Vec3& p) {
  return "(" + formatFixed(p.x, 2) + ", " + formatFixed(p.y, 2) + ", " + formatFixed(p.z, 2) + ")";
}
std::string clock(double hours) {
  const int m = static_cast<int>(std::lround(hours * 60.0));
  char buf[16];
  std::snprintf(buf, sizeof buf, "%02d:%02d", m / 60, m % 60);
  return buf;
}
// A signed figure with a real minus sign (U+2212) and an explicit plus.
std::string signedFixed(double v, int decimals) {
  const std::string s = formatFixed(std::fabs(v), decimals);
  if (s.find_first_not_of("0.") == std::string::npos) return s;
  return (v < 0.0 ? "−" : "+") + s;
}

// Eight compass points for a true azimuth (degrees clockwise from north).
std::string compass(double azimuthDeg) {
  static constexpr std::array<const char*, 8> kPoints{"north",  "north-east", "east",  "south-east",
                                                      "south", "south-west", "west", "north-west"};
  const int i = static_cast<int>(std::lround(std::fmod(std::fmod(azimuthDeg, 360.0) + 360.0, 360.0) / 45.0)) % 8;
  return std::string(kPoints[static_cast<std::size_t>(i)]) + " (" + formatFixed(azimuthDeg, 0) + "°)";
}

// "sky+landscape+ground" → "sky, landscape, ground".
std::string layersText(const std::string& layers) {
  std::string out;
  for (char c : layers) out += c == '+' ? std::string(", ") : std::string(1, c);
  return xmlEscape(out);
}

void provisionHtml(std::ostringstream& h, const En17037Report& r) {
  h << "<h3>Daylight provision " << levelBadge(r.provisionLevel) << "</h3>\n<p class=\"sub\">Illuminance method over "
    << r.daylightHours << " daylight hours (the half of the year with the most diffuse light outdoors), graded "
    << (r.sensorFirst ? "sensor first" : "hour first") << "; the other order gives " << lv(r.provisionLevelOther)
    << ". Daylight-factor method (median diffuse illuminance outdoors E<sub>v,d,med</sub> = "
    << formatFixed(r.medianDiffuseLux, 0) << " lx): " << lv(r.daylightFactorLevel) << ".</p>\n"
    << "<table class=\"compliance\">\n<thead><tr><th>Space</th><th>Level</th><th class=\"num\">E<sub>T</sub> / "
       "E<sub>TM</sub></th><th class=\"num\">Hour first: share of the daylight hours<br>(needs 50 % / 50 %)</th>"
       "<th class=\"num\">Sensor first: share of the plane<br>(needs 50 % / 95 %)</th><th class=\"num\">D<sub>T</sub> "
       "/ D<sub>TM</sub></th><th class=\"num\">Share of the plane reaching them<br>(needs 50 % / 95 %)</th></tr>"
       "</thead>\n<tbody>\n";
  for (const ProvisionSpaceReport& s : r.spaces)
    for (std::size_t i = 0; i < s.illuminance.levels.size(); ++i) {
      const ProvisionLevelResult& l = s.illuminance.levels[i];
      h << "<tr><td>" << (i == 0 ? xmlEscape(s.space) : "") << "</td><td>" << lv(l.level.level)
        << "</td><td class=\"num\">" << formatFixed(l.level.targetLux, 0) << " / "
        << formatFixed(l.level.minimumTargetLux, 0) << " lx</td><td class=\"num\">"
        << marked(pct(l.target.hourFirstTimeFraction), l.target.hourFirstPass) << " / "
        << marked(pct(l.minimumTarget.hourFirstTimeFraction), l.minimumTarget.hourFirstPass) << "</td><td class=\"num\">"
        << marked(pct(l.target.sensorFirstPlaneFraction), l.target.sensorFirstPass) << " / "
        << marked(pct(l.minimumTarget.sensorFirstPlaneFraction), l.minimumTarget.sensorFirstPass) << "</td>";
      if (s.daylightFactor) {
        const DaylightFactorLevelResult& d = s.daylightFactor->levels[i];
        h << "<td class=\"num\">" << formatFixed(d.targetPct, 2) << " / " << formatFixed(d.minimumTargetPct, 2)
          << " %</td><td class=\"num\">" << marked(pct(d.targetPlaneFraction), d.targetPlaneFraction >= kTargetPlaneFraction)
          << " / " << marked(pct(d.minimumPlaneFraction), d.minimumPlaneFraction >= kMinimumTargetPlaneFraction)
          << "</td>";
      } else {
        h << "<td colspan=\"2\">not computed</td>";
      }
      h << "</tr>\n";
    }
  h << "</tbody>\n</table>\n<p class=\"sub note\">A level needs its target illuminance E<sub>T</sub> over 50 % of the "
       "reference plane and its minimum target illuminance E<sub>TM</sub> over 95 %, each for half of the daylight "
       "hours. Hour first: an hour counts when the plane's shares are reached, and the level needs half of the hours. "
       "Sensor first: a sensor counts when it reaches the illuminance in half of the hours, and the level needs the "
       "plane's shares. The daylight-factor method asks the same shares of the plane for the daylight factors "
       "D<sub>T</sub> and D<sub>TM</sub> that give E<sub>T</sub> and E<sub>TM</sub> at this site.</p>\n";
}

void sunlightHtml(std::ostringstream& h, const En17037Report& r) {
  En17037Level lowest = En17037Level::kHigh;
  for (const SunlightReportPoint& p : r.sunlight) lowest = std::min(lowest, p.level);
  h << "<h3>Exposure to sunlight " << levelBadge(lowest) << "</h3>\n<p class=\"sub\">" << xmlEscape(dateInWords(r.sunlightDate))
    << ": the sun is above " << formatFixed(r.sunlightMinAltitudeDeg, 1) << "°"
    << (r.sunlightMinAltitudeDefault ? " (candela's default; EN 17037 Annex D gives each country's value, set it with "
                                       "<code>sunlight_min_altitude</code>)"
                                     : "")
    << " for " << formatFixed(r.sunAboveMinHours, 2)
    << " h. Levels: 1.5 h minimum, 3 h medium, 4 h high of possible direct sun.</p>\n"
    << "<table class=\"compliance\">\n<thead><tr><th>Reference point (m)</th><th class=\"num\">Hours of sun</th>"
       "<th>Sunlit (local standard time)</th><th>Level</th></tr></thead>\n<tbody>\n";
  for (const SunlightReportPoint& p : r.sunlight) {
    std::string when;
    for (const auto& [a, b] : p.intervals) when += (when.empty() ? "" : ", ") + clock(a) + "–" + clock(b);
    h << "<tr><td class=\"pos\">" << xyz(p.position) << "</td><td class=\"num\">" << formatFixed(p.hours, 2)
      << " h</td><td>" << (when.empty() ? "never" : when) << "</td><td>" << lv(p.level) << "</td></tr>\n";
  }
  h << "</tbody>\n</table>\n";
}

void viewHtml(std::ostringstream& h, const En17037Report& r) {
  En17037Level lowest = En17037Level::kHigh;
  for (const ViewOutReportPoint& v : r.viewOut) lowest = std::min(lowest, v.level);
  h << "<h3>View out " << levelBadge(lowest) << "</h3>\n<p class=\"sub\">Levels minimum / medium / high: horizontal "
       "sight angle at least 14° / 28° / 54°, distance to the outside obstruction at least 6 / 20 / 50 m, layers "
       "seen: landscape / landscape and one other / sky, landscape and ground. Each position takes the lowest of its "
       "three.</p>\n<table class=\"compliance\">\n<thead><tr><th>Eye (m)</th><th class=\"num\">Horizontal sight "
       "angle</th><th></th><th class=\"num\">Outside distance</th><th></th><th>Layers seen</th><th></th>"
       "<th>Level</th></tr></thead>\n<tbody>\n";
  for (const ViewOutReportPoint& v : r.viewOut)
    h << "<tr><td class=\"pos\">" << xyz(v.eye) << "</td><td class=\"num\">" << formatFixed(v.sightAngleDeg, 1)
      << "°<span class=\"f\">all windows " << formatFixed(v.totalSightAngleDeg, 1) << "°</span></td>"
      << levelCell(v.sightLevel) << "<td class=\"num\">"
      << (std::isinf(v.outsideDistanceM) ? std::string("nothing modelled outside")
                                         : formatFixed(v.outsideDistanceM, 1) + " m")
      << "</td>" << levelCell(v.distanceLevel) << "<td>" << layersText(v.layers) << "</td>"
      << levelCell(v.layersLevel) << "<td>" << lv(v.level) << "</td></tr>\n";
  h << "</tbody>\n</table>\n";
}

void glareHtml(std::ostringstream& h, const En17037Report& r) {
  En17037Level lowest = En17037Level::kHigh;
  for (const GlareViewReport& g : r.glare) lowest = std::min(lowest, g.level);
  h << "<h3>Protection from glare " << levelBadge(lowest) << "</h3>\n<p class=\"sub\">Daylight glare probability (DGP) "
       "at each view for every occupied hour of the year, from the vertical illuminance at the eye and the sun's "
       "direct contribution (the imageless method), with the shading the case describes. A level allows its DGP "
       "(minimum 0.45, medium 0.40, high 0.35) to be exceeded in at most "
    << pct(r.glareExceedance) << " of the occupied hours.</p>\n<table class=\"compliance\">\n<thead><tr><th>View "
       "position (m)</th><th>Looking</th><th class=\"num\">Occupied hours with DGP &gt; 0.35</th><th class=\"num\">"
       "&gt; 0.40</th><th class=\"num\">&gt; 0.45</th><th class=\"num\">Glare autonomy<br>(DGP &lt; 0.40)</th>"
       "<th>Blinds</th><th>Level</th></tr></thead>\n<tbody>\n";
  for (const GlareViewReport& g : r.glare) {
    const std::string blinds =
        g.blinds == "lm83"            ? "LM-83 blinds of " + xmlEscape(g.blindsSpace) + ", closed " +
                                            countOf(g.blindsClosedHours, "occupied hour", "occupied hours")
        : g.blinds == "window_states" ? "window states as " + xmlEscape(g.blindsSpace) + " chooses them, switched " +
                                            countOf(g.blindsClosedHours, "occupied hour", "occupied hours") +
                                            (g.blindsNote.empty() ? "" : " (" + xmlEscape(g.blindsNote) + ")")
                                      : std::string("none");
    h << "<tr><td class=\"pos\">" << xyz(g.position) << "</td><td class=\"pos\">" << compass(g.azimuthDeg) << "</td><td class=\"num\">"
      << pct(g.shareAbove035) << "</td><td class=\"num\">" << pct(g.shareAbove040) << "</td><td class=\"num\">"
      << pct(g.shareAbove045) << "</td><td class=\"num\">" << pct(g.glareAutonomy) << "</td><td>" << blinds
      << "</td><td>" << lv(g.level) << "</td></tr>\n";
  }
  h << "</tbody>\n</table>\n";
  bool checks = false;
  for (const GlareViewReport& g : r.glare) checks = checks || !g.checks.empty();
  if (!checks) return;
  h << "<h4>Imageless against rendered DGP at the check hours</h4>\n<p class=\"sub\">The rendered DGP comes from a "
       "fisheye image of the view, which also sees glare reflected by the room's surfaces. Difference = imageless "
       "− rendered.</p>\n<table class=\"compliance\">\n<thead><tr><th>View position (m)</th><th>Hour (local standard "
       "time)</th><th>Blinds</th><th class=\"num\">DGP imageless</th><th class=\"num\">DGP rendered</th><th "
       "class=\"num\">Difference</th><th class=\"num\">E<sub>v</sub> imageless / rendered</th></tr></thead>\n<tbody>\n";
  for (const GlareViewReport& g : r.glare)
    for (const GlareViewReport::Check& c : g.checks)
      h << "<tr><td class=\"pos\">" << xyz(g.position) << "</td><td>" << xmlEscape(dateInWords(c.time)) << "</td><td>"
        << (g.blinds == "window_states" ? (c.blindsClosed ? "switched" : "first states")
            : c.blindsClosed            ? "closed"
            : g.blinds == "lm83"        ? "open"
                                        : "none")
        << "</td><td class=\"num\">"
        << formatFixed(c.imagelessDgp, 3) << "</td><td class=\"num\">" << formatFixed(c.renderedDgp, 3)
        << "</td><td class=\"num\">" << signedFixed(c.imagelessDgp - c.renderedDgp, 3) << "</td><td class=\"num\">"
        << formatFixed(c.imagelessEvLux, 0) << " / " << formatFixed(c.renderedEvLux, 0) << " lx</td></tr>\n";
  h << "</tbody>\n</table>\n";
}

void leedHtml(std::ostringstream& h, const LeedReport& l) {
  const bool option2 = !l.times.empty();
  h << "<p class=\"sub\">" << countOf(l.points, "point", "points")
    << (option2 ? " (provisional: the thresholds 55 / 75 / 90 % of the area could not be checked against the LEED "
                  "v4.1 text)"
                : std::string(" (the project's estimate; the LEED review awards them)"))
    << "; "
    << (option2 ? "share of the floor area between 300 and 3000 lx, mean over " +
                      countOf(static_cast<long long>(l.times.size()), "clear-sky time", "clear-sky times") + ": "
                : std::string("area-weighted sDA300/50%: "))
    << formatFixed(l.averagePct, 1) << " %"
    << (option2 ? " (standard error " + formatFixed(l.averageStandardErrorPct, 1) + " %)" : std::string())
    << (l.eachSpaceAbove55 ? "; every space reaches 55 %" : "")
    << (!option2 && l.aseExceeds10Percent ? "; ASE above 10 % in a space: document how its glare is addressed" : "")
    << ".</p>\n";
  if (option2)
    h << "<p class=\"sub\">Each time under the CIE clear sky with the sun at the site, the model without luminaires "
         "or blinds. The sky's diffuse horizontal and the sun's direct normal illuminance are the weather year's "
         "means at that hour over the days within 15 days of the equinox (USGBC's guidance for the credit).</p>\n";
  h << "<table class=\"compliance\">\n<thead><tr><th>Space</th><th class=\"num\">Floor area</th>";
  if (option2) {
    h << "<th class=\"num\">Between 300 and 3000 lx, mean<br>(± standard error)</th>";
    for (std::size_t t = 0; t < l.times.size(); ++t) {
      h << "<th class=\"num\">" << xmlEscape(dateInWords(l.times[t]));
      if (t < l.skyByTime.size())
        h << "<span class=\"f\">sky " << formatFixed(l.skyByTime[t].diffuseHorizontalLux, 0) << " lx, sun "
          << formatFixed(l.skyByTime[t].directNormalLux, 0) << " lx normal</span>";
      h << "</th>";
    }
  } else {
    h << "<th class=\"num\">sDA300/50%</th><th class=\"num\">ASE1000,250</th>";
  }
  h << "</tr></thead>\n<tbody>\n";
  for (const LeedSpaceReport& s : l.spaces) {
    h << "<tr><td>" << xmlEscape(s.space) << "</td><td class=\"num\">" << formatFixed(s.areaM2, 1) << " m²</td>";
    if (option2) {
      h << "<td class=\"num\">" << formatFixed(s.inRangePct, 1) << " ± " << formatFixed(s.inRangeStandardErrorPct, 1)
        << " %</td>";
      for (std::size_t i = 0; i < s.inRangeByTimePct.size(); ++i)
        h << "<td class=\"num\">" << formatFixed(s.inRangeByTimePct[i], 1) << " ± "
          << formatFixed(s.inRangeByTimeStandardErrorPct.at(i), 1) << " %"
          << (i < s.meanLuxByTime.size() ? "<span class=\"f\">mean " + formatFixed(s.meanLuxByTime[i], 0) + " lx</span>"
                                         : std::string())
          << "</td>";
    } else {
      h << "<td class=\"num\">" << formatFixed(s.sdaPct, 1) << " %</td><td class=\"num\">" << formatFixed(s.asePct, 1)
        << " %" << (s.aseAbove10 ? " (above 10 %)" : "") << "</td>";
    }
    h << "</tr>\n";
  }
  h << "</tbody>\n</table>\n";
}

}  // namespace

std::string complianceHtml(const std::vector<ComplianceReport>& entries) {
  if (entries.empty()) return "";
  std::ostringstream h;
  for (const ComplianceReport& r : entries) {
    h << "<section class=\"grid\" id=\"compliance-" << xmlEscape(r.name) << "\">\n<h2>Compliance: "
      << xmlEscape(r.section ? r.section->title()
                   : r.standard == "en17037" ? "EN 17037:2018+A1:2023"
                   : r.standard == "leed-v4.1-option1" ? "LEED v4.1 EQ Daylight, option 1"
                                                       : "LEED v4.1 EQ Daylight, option 2")
      << (r.name != r.standard ? " (" + xmlEscape(r.name) + ")" : "") << " <span class=\"badge "
      << (r.verdict == "pass" ? "pass" : "fail") << "\">" << xmlEscape(r.verdict) << "</span></h2>\n<ul>\n";
    for (const std::string& line : r.verdictLines) h << "<li>" << xmlEscape(line) << "</li>\n";
    h << "</ul>\n";
    if (r.en17037) {
      if (!r.en17037->spaces.empty()) provisionHtml(h, *r.en17037);
      if (!r.en17037->viewOut.empty()) viewHtml(h, *r.en17037);
      if (!r.en17037->sunlight.empty()) sunlightHtml(h, *r.en17037);
      if (!r.en17037->glare.empty()) glareHtml(h, *r.en17037);
    }
    if (r.leed) leedHtml(h, *r.leed);
    if (r.section) h << r.section->html();
    h << "</section>\n";
  }
  return h.str();
}

}  // namespace candela
