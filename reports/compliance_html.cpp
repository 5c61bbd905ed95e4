// The report's compliance section: one part per [[compliance]] entry (docs/compliance.md).
#include "reports/compliance_html.h"

#include "reports/plan_svg.h"
#include "reports/report_data.h"

#include <cmath>
#include <sstream>

namespace candela {

namespace {

std::string pct(double fraction) { return formatFixed(100.0 * fraction, 1) + " %"; }
std::string lv(En17037Level l) { return std::string(levelName(l)); }
std::string levelBadge(En17037Level l) {
  return std::string("<span class=\"badge ") + (l == En17037Level::kNone ? "fail" : "pass") + "\">" + lv(l) + "</span>";
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

void provisionHtml(std::ostringstream& h, const En17037Report& r) {
  h << "<h3>Daylight provision " << levelBadge(r.provisionLevel) << "</h3>\n<p class=\"sub\">Illuminance method over "
    << r.daylightHours << " daylight hours (the half of the year with the most diffuse light outdoors), graded "
    << (r.sensorFirst ? "sensor first" : "hour first") << "; the other order gives "
    << lv(r.provisionLevelOther) << ". Daylight-factor method (E<sub>v,d,med</sub> = "
    << formatFixed(r.medianDiffuseLux, 0) << " lx): " << lv(r.daylightFactorLevel) << ".</p>\n"
    << "<table>\n<thead><tr><th>Space</th><th>Level</th><th>E<sub>T</sub> / E<sub>TM</sub></th><th>hour first: "
       "share of daylight hours</th><th>sensor first: share of the plane</th><th>D<sub>T</sub> / D<sub>TM</sub>"
       "</th><th>share of the plane</th></tr></thead>\n<tbody>\n";
  for (const ProvisionSpaceReport& s : r.spaces)
    for (std::size_t i = 0; i < s.illuminance.levels.size(); ++i) {
      const ProvisionLevelResult& l = s.illuminance.levels[i];
      h << "<tr><td>" << (i == 0 ? xmlEscape(s.space) : "") << "</td><td>" << lv(l.level.level) << "</td><td>"
        << formatFixed(l.level.targetLux, 0) << " / " << formatFixed(l.level.minimumTargetLux, 0) << " lx</td><td>"
        << pct(l.target.hourFirstTimeFraction) << " / " << pct(l.minimumTarget.hourFirstTimeFraction) << "</td><td>"
        << pct(l.target.sensorFirstPlaneFraction) << " / " << pct(l.minimumTarget.sensorFirstPlaneFraction) << "</td>";
      if (s.daylightFactor) {
        const DaylightFactorLevelResult& d = s.daylightFactor->levels[i];
        h << "<td>" << formatFixed(d.targetPct, 2) << " / " << formatFixed(d.minimumTargetPct, 2) << " %</td><td>"
          << pct(d.targetPlaneFraction) << " / " << pct(d.minimumPlaneFraction) << "</td>";
      } else {
        h << "<td colspan=\"2\">not computed</td>";
      }
      h << "</tr>\n";
    }
  h << "</tbody>\n</table>\n<p class=\"sub\">A level needs E<sub>T</sub> over 50 % of the plane and E<sub>TM</sub> "
       "over 95 %, for half of the daylight hours (hour first: an hour counts when the plane shares are reached; "
       "sensor first: a sensor counts when it reaches the illuminance in half of the hours).</p>\n";
}

void sunlightHtml(std::ostringstream& h, const En17037Report& r) {
  En17037Level lowest = En17037Level::kHigh;
  for (const SunlightReportPoint& p : r.sunlight) lowest = std::min(lowest, p.level);
  h << "<h3>Exposure to sunlight " << levelBadge(lowest) << "</h3>\n<p class=\"sub\">" << xmlEscape(r.sunlightDate)
    << ", the sun above " << formatFixed(r.sunlightMinAltitudeDeg, 1) << "°"
    << (r.sunlightMinAltitudeDefault ? " (the default, see docs/compliance.md)" : "") << " for "
    << formatFixed(r.sunAboveMinHours, 2) << " h. Levels: 1.5 h minimum, 3 h medium, 4 h high.</p>\n"
    << "<table>\n<thead><tr><th>Reference point (m)</th><th>Hours of sun</th><th>Sunlit</th><th>Level</th></tr>"
       "</thead>\n<tbody>\n";
  for (const SunlightReportPoint& p : r.sunlight) {
    std::string when;
    for (const auto& [a, b] : p.intervals) when += (when.empty() ? "" : ", ") + clock(a) + "–" + clock(b);
    h << "<tr><td>" << xyz(p.position) << "</td><td>" << formatFixed(p.hours, 2) << " h</td><td>"
      << (when.empty() ? "none" : when) << "</td><td>" << lv(p.level) << "</td></tr>\n";
  }
  h << "</tbody>\n</table>\n";
}

void viewHtml(std::ostringstream& h, const En17037Report& r) {
  En17037Level lowest = En17037Level::kHigh;
  for (const ViewOutReportPoint& v : r.viewOut) lowest = std::min(lowest, v.level);
  h << "<h3>View out " << levelBadge(lowest) << "</h3>\n<p class=\"sub\">Horizontal sight angle 14° / 28° / 54°, "
       "outside distance 6 / 20 / 50 m, layers landscape / + one / all three.</p>\n<table>\n<thead><tr><th>Eye (m)"
       "</th><th>Sight angle</th><th>Outside distance</th><th>Layers</th><th>Level</th></tr></thead>\n<tbody>\n";
  for (const ViewOutReportPoint& v : r.viewOut)
    h << "<tr><td>" << xyz(v.eye) << "</td><td>" << formatFixed(v.sightAngleDeg, 1) << "° (all windows "
      << formatFixed(v.totalSightAngleDeg, 1) << "°) " << lv(v.sightLevel) << "</td><td>"
      << (std::isinf(v.outsideDistanceM) ? std::string("nothing modelled outside") : formatFixed(v.outsideDistanceM, 1) + " m")
      << " " << lv(v.distanceLevel) << "</td><td>" << xmlEscape(v.layers) << " " << lv(v.layersLevel) << "</td><td>"
      << lv(v.level) << "</td></tr>\n";
  h << "</tbody>\n</table>\n";
}

void glareHtml(std::ostringstream& h, const En17037Report& r) {
  En17037Level lowest = En17037Level::kHigh;
  for (const GlareViewReport& g : r.glare) lowest = std::min(lowest, g.level);
  h << "<h3>Protection from glare " << levelBadge(lowest) << "</h3>\n<p class=\"sub\">Imageless DGP every occupied "
       "hour (docs/annual-glare.md) with the shading the case describes; a level allows its DGP (0.45 / 0.40 / 0.35) "
       "to be exceeded in "
    << pct(r.glareExceedance) << " of the hours.</p>\n<table>\n<thead><tr><th>View (m)</th><th>Direction</th><th>"
       "DGP &gt; 0.35</th><th>&gt; 0.40</th><th>&gt; 0.45</th><th>Glare autonomy</th><th>Blinds</th><th>Level</th>"
       "</tr></thead>\n<tbody>\n";
  for (const GlareViewReport& g : r.glare) {
    const std::string blinds = g.blinds == "lm83" ? "LM-83 of " + xmlEscape(g.blindsSpace) + ", closed " +
                                                        std::to_string(g.blindsClosedHours) + " h"
                                                  : std::string("open");
    h << "<tr><td>" << xyz(g.position) << "</td><td>" << xyz(g.direction) << "</td><td>" << pct(g.shareAbove035)
      << "</td><td>" << pct(g.shareAbove040) << "</td><td>" << pct(g.shareAbove045) << "</td><td>"
      << pct(g.glareAutonomy) << "</td><td>" << blinds << "</td><td>" << lv(g.level) << "</td></tr>\n";
  }
  h << "</tbody>\n</table>\n";
  bool checks = false;
  for (const GlareViewReport& g : r.glare) checks = checks || !g.checks.empty();
  if (!checks) return;
  h << "<table>\n<thead><tr><th>View</th><th>Hour</th><th>DGP imageless</th><th>DGP rendered</th><th>Difference</th>"
       "<th>E<sub>v</sub> imageless / rendered</th></tr></thead>\n<tbody>\n";
  for (std::size_t i = 0; i < r.glare.size(); ++i)
    for (const GlareViewReport::Check& c : r.glare[i].checks)
      h << "<tr><td>" << i + 1 << "</td><td>" << xmlEscape(c.time) << (c.blindsClosed ? " (blinds closed)" : "")
        << "</td><td>" << formatFixed(c.imagelessDgp, 3)
        << "</td><td>" << formatFixed(c.renderedDgp, 3) << "</td><td>" << formatFixed(c.imagelessDgp - c.renderedDgp, 3)
        << "</td><td>" << formatFixed(c.imagelessEvLux, 0) << " / " << formatFixed(c.renderedEvLux, 0) << " lx</td></tr>\n";
  h << "</tbody>\n</table>\n";
}

void leedHtml(std::ostringstream& h, const LeedReport& l) {
  const bool option2 = !l.times.empty();
  h << "<p class=\"sub\">" << l.points << " points; "
    << (option2 ? "area between 300 and 3000 lx, mean over " + std::to_string(l.times.size()) + " clear-sky times: "
                : std::string("area-weighted sDA300/50%: "))
    << formatFixed(l.averagePct, 1) << (option2 ? " ± " + formatFixed(l.averageStandardErrorPct, 1) : std::string())
    << " %" << (l.eachSpaceAbove55 ? "; every space reaches 55 %" : "")
    << (!option2 && l.aseExceeds10Percent ? "; ASE above 10 % in a space: document how its glare is addressed" : "")
    << ".</p>\n<table>\n<thead><tr><th>Space</th><th>Area</th>"
    << (option2 ? "<th>In range (mean)</th><th>Per time</th>" : "<th>sDA300/50%</th><th>ASE1000,250</th>")
    << "</tr></thead>\n<tbody>\n";
  for (const LeedSpaceReport& s : l.spaces) {
    h << "<tr><td>" << xmlEscape(s.space) << "</td><td>" << formatFixed(s.areaM2, 1) << " m²</td>";
    if (option2) {
      std::string per;
      for (std::size_t i = 0; i < s.inRangeByTimePct.size(); ++i)
        per += (i ? ", " : "") + xmlEscape(l.times[i]) + ": " + formatFixed(s.inRangeByTimePct[i], 1) + " ± " +
               formatFixed(s.inRangeByTimeStandardErrorPct.at(i), 1) + " %";
      h << "<td>" << formatFixed(s.inRangePct, 1) << " ± " << formatFixed(s.inRangeStandardErrorPct, 1) << " %</td><td>"
        << per << "</td>";
    } else {
      h << "<td>" << formatFixed(s.sdaPct, 1) << " %</td><td>" << formatFixed(s.asePct, 1) << " %"
        << (s.aseAbove10 ? " (above 10 %)" : "") << "</td>";
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
      << xmlEscape(r.standard == "en17037" ? "EN 17037:2018+A1:2023"
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
    h << "</section>\n";
  }
  return h.str();
}

}  // namespace candela
