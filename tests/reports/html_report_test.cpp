#include "reports/html_report.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "reports/plan_svg.h"
#include "sample_report.h"

namespace candela {
namespace {

namespace fs = std::filesystem;

std::string reportText() {
  const fs::path path = fs::path(testing::TempDir()) / "candela_report_test" / "report.html";
  writeHtmlReport(path, testing_sample::sampleReport());
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Opens offline: nothing is fetched from anywhere — no URLs, no src= attribute except embedded
// data: URIs, no stylesheets or scripts by reference, no url() except to in-document ids.
TEST(HtmlReport, IsSelfContained) {
  const std::string html = reportText();
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_EQ(html.find("http://"), std::string::npos);
  EXPECT_EQ(html.find("https://"), std::string::npos);
  const std::regex externalSrc(R"(src="(?!data:image/png;base64,))");
  EXPECT_FALSE(std::regex_search(html, externalSrc));
  EXPECT_EQ(html.find("<link"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(html.find("@import"), std::string::npos);
  const std::regex externalUrl(R"(url\((?!#))");
  EXPECT_FALSE(std::regex_search(html, externalUrl));
  const std::regex externalHref(R"(href="(?!#))");
  EXPECT_FALSE(std::regex_search(html, externalHref));
  EXPECT_NE(html.find("<style>"), std::string::npos);
  EXPECT_NE(html.find("</html>"), std::string::npos);
}

// Control characters in names from the case file (ESC, BEL: a terminal title sequence) reached
// report.html raw; they are written as \xNN there, as in error messages.
TEST(HtmlReport, ControlCharactersInCaseNamesAreEscaped) {
  ReportData data = testing_sample::sampleReport();
  data.run.caseName = "Office\x1b]0;pwned\x07 \x7f";
  data.run.description = "line\x1b[2J";
  data.grids[0].name = "grid\x01";
  const std::string html = htmlReport(data);
  for (const char c : {'\x1b', '\x07', '\x7f', '\x01'}) EXPECT_EQ(html.find(c), std::string::npos) << int(c);
  EXPECT_NE(html.find("<h1>Office\\x1b]0;pwned\\x07 \\x7f</h1>"), std::string::npos);
  EXPECT_NE(html.find("line\\x1b[2J"), std::string::npos);
  EXPECT_EQ(xmlEscape("a\tb\nc<"), "a\tb\nc&lt;");
}

TEST(HtmlReport, HasEachGridsPlanAndTable) {
  const ReportData data = testing_sample::sampleReport();
  const std::string html = reportText();
  EXPECT_NE(html.find("Open office, level 2"), std::string::npos);
  for (std::size_t i = 0; i < data.grids.size(); ++i) {
    const std::string id = "id=\"grid-" + std::to_string(i + 1) + "\"";
    const std::size_t at = html.find(id);
    ASSERT_NE(at, std::string::npos) << id;
    const std::size_t end = html.find("</section>", at);
    const std::string section = html.substr(at, end - at);
    EXPECT_NE(section.find(xmlEscape(data.grids[i].name)), std::string::npos);
    EXPECT_NE(section.find("<svg "), std::string::npos);
    EXPECT_NE(section.find("<table>"), std::string::npos);
    EXPECT_NE(section.find("Uniformity U<sub>0</sub>"), std::string::npos);
    // The average shown is the grid's, rounded as printed (0 decimals above 100 lx).
    EXPECT_NE(section.find(formatFixed(data.grids[i].stats.averageLux, 0) + " lx"), std::string::npos)
        << data.grids[i].stats.averageLux;
    const std::string verdict = std::string("badge ") + verdictName(data.grids[i].check.overall);
    EXPECT_NE(section.find(verdict), std::string::npos);
  }
  EXPECT_NE(html.find("Desk &lt;A&amp;B&gt;"), std::string::npos);  // names are escaped
  EXPECT_EQ(html.find("Desk <A&B>"), std::string::npos);
  EXPECT_NE(html.find("badge pass"), std::string::npos);
  EXPECT_NE(html.find("badge fail"), std::string::npos);
  EXPECT_NE(html.find("3.25 s"), std::string::npos);  // run time
}

// scripts/screenshot_report.sh sets CANDELA_SAMPLE_REPORT to get the sample report for the
// manual visual check (docs/reports.md); without it this test only writes to a temp folder.
// A named quantity in the grid's heading and metrics (its symbol's index as a subscript), and a
// modelling grid's ratio under the summary and in its section.
TEST(HtmlReport, ShowsTheQuantityAndModelling) {
  ReportData d = testing_sample::sampleReport();
  EXPECT_EQ(htmlReport(d).find("Modelling"), std::string::npos);
  d.grids[1].quantity = "Cylindrical illuminance Ē_z";
  d.grids[1].quantityKey = "cylindrical";
  d.grids[1].modelling = modellingRatio({100.0}, {400.0});
  const std::string html = htmlReport(d);
  EXPECT_NE(html.find("<p class=\"sub\">Cylindrical illuminance Ē<sub>z</sub> in lx"), std::string::npos);
  EXPECT_NE(html.find("<td>Average cylindrical illuminance Ē<sub>z</sub></td>"), std::string::npos);
  EXPECT_NE(html.find("Modelling on <a href=\"#grid-2\">Desk &lt;A&amp;B&gt;</a>: Ē<sub>z</sub> / Ē<sub>h</sub> = 100 lx / "
                      "400 lx = 0.25 (EN 12464-1:2021: 0.30–0.60) <span class=\"badge fail\">fail</span>"),
            std::string::npos);
  EXPECT_NE(html.find("<td class=\"num\">0.25</td><td class=\"num\">0.30–0.60</td><td><span class=\"badge fail\">"),
            std::string::npos);
}

// A daylight-factor run is reported in the daylight factor's words and symbols, never under
// EN 12464-1's illuminance sentence.
TEST(HtmlReport, DaylightFactorGridsInTheirOwnTerms) {
  ReportData d = testing_sample::sampleReport();
  for (GridReport& g : d.grids) {
    g.quantity = "Daylight factor";
    g.unit = "%";
  }
  const std::string html = htmlReport(d);
  EXPECT_EQ(html.find("EN 12464-1: maintained illuminance"), std::string::npos);
  EXPECT_NE(html.find("Daylight factors in % of the outside horizontal illuminance under the CIE overcast sky"),
            std::string::npos);
  EXPECT_NE(html.find("<th class=\"num\">D̄</th><th class=\"num\">D<sub>min</sub></th>"), std::string::npos);
  EXPECT_NE(html.find("<td>Average daylight factor D̄</td>"), std::string::npos);
  EXPECT_NE(html.find("<td>Minimum D<sub>min</sub></td>"), std::string::npos);
  EXPECT_EQ(html.find("<td>Minimum E<sub>min</sub></td>"), std::string::npos);
  // With an illuminance grid beside them, the columns are named for both.
  d.grids[0].unit = "lx";
  d.grids[0].quantity = "Illuminance";
  const std::string mixed = htmlReport(d);
  EXPECT_NE(mixed.find("EN 12464-1: maintained illuminance"), std::string::npos);
  EXPECT_NE(mixed.find("<th class=\"num\">Average</th><th class=\"num\">Minimum</th>"), std::string::npos);
}

TEST(HtmlReport, WritesSampleForScreenshot) {
  const char* target = std::getenv("CANDELA_SAMPLE_REPORT");
  const fs::path path = target ? fs::path(target) : fs::path(testing::TempDir()) / "candela_sample_report.html";
  writeHtmlReport(path, testing_sample::sampleReport());
  EXPECT_TRUE(fs::exists(path));
}

}  // namespace
}  // namespace candela

namespace candela {
namespace {

// A view's pictures are embedded as base64 data URIs (RFC 4648: bytes 1 2 3 4 → "AQIDBA==")
// with its metrics beside them.
TEST(HtmlReport, EmbedsViewPicturesAndMetrics) {
  ReportData data = testing_sample::sampleReport();
  ViewReport v;
  v.name = "desk <view>";
  v.description = "fisheye 180°";
  v.previewPng = {1, 2, 3, 4};
  v.falseColorPng = {255, 0};
  v.metrics = {{"UGR", "18.5"}, {"DGP", "0.192"}};
  data.views.push_back(v);
  const std::filesystem::path path = std::filesystem::path(testing::TempDir()) / "candela_report_view" / "report.html";
  writeHtmlReport(path, data);
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  const std::string html = s.str();
  EXPECT_NE(html.find("src=\"data:image/png;base64,AQIDBA==\""), std::string::npos);
  EXPECT_NE(html.find("src=\"data:image/png;base64,/wA=\""), std::string::npos);
  EXPECT_NE(html.find("desk &lt;view&gt;"), std::string::npos);
  EXPECT_NE(html.find("<td>UGR</td><td class=\"num\">18.5</td>"), std::string::npos);
}

}  // namespace
}  // namespace candela

namespace candela {
namespace {

// The run's verdict: every checked line counted once, a failing one fails it, nothing checked is
// no verdict; the report's summary and summary.json state it.
TEST(OverallVerdict, CountsEveryCheckedLine) {
  ReportData d;
  int checked = -1, failed = -1;
  EXPECT_EQ(overallVerdict(d, &checked, &failed), Verdict::kNotChecked);
  EXPECT_EQ(checked, 0);
  GridReport a, b;
  a.check.overall = Verdict::kPass;
  b.check.overall = Verdict::kNotChecked;
  b.modelling.emplace().verdict = Verdict::kPass;
  d.grids = {a, b};
  ObserverReport seat;
  seat.ugrLimit = 19.0;
  seat.ugr = 17.0;
  d.observers.push_back(seat);
  TaskAreaReport desk;
  desk.raVerdict = Verdict::kPass;
  desk.ugrVerdict = Verdict::kPass;  // the observer's line, counted with the observers
  d.taskAreas.push_back(desk);
  EXPECT_EQ(overallVerdict(d, &checked, &failed), Verdict::kPass);
  EXPECT_EQ(checked, 4);
  EXPECT_EQ(failed, 0);
  EXPECT_NE(htmlReport(d).find("all 4 checked lines pass"), std::string::npos);
  d.observers[0].ugr = 22.0;
  EXPECT_EQ(overallVerdict(d, &checked, &failed), Verdict::kFail);
  EXPECT_EQ(failed, 1);
  EXPECT_NE(htmlReport(d).find("1 of 4 checked lines fail"), std::string::npos);
  // The summary names the kinds of line the run has, and only those.
  EXPECT_EQ(checkedCategories(d), (std::vector<std::string>{"grids", "modelling", "colour rendering", "observers' UGR"}));
  EXPECT_NE(htmlReport(d).find("(grids, modelling, colour rendering and observers&#39; UGR)"), std::string::npos);
}

// A daylight run checked only against its [[compliance]] entries says so, not "walls and ceiling".
TEST(OverallVerdict, NamesOnlyTheCategoriesChecked) {
  ReportData d;
  d.grids.emplace_back();  // an annual grid: no targets
  ComplianceReport c;
  c.verdict = "pass";
  d.compliance = {c, c};
  EXPECT_EQ(checkedCategories(d), std::vector<std::string>{"daylight compliance"});
  const std::string h = htmlReport(d);
  EXPECT_NE(h.find("all 2 checked lines pass (daylight compliance)"), std::string::npos);
  GridReport wall;
  wall.surfaceGrid = "walls";
  wall.check.overall = Verdict::kFail;
  d.grids.push_back(wall);
  EXPECT_EQ(checkedCategories(d), (std::vector<std::string>{"walls and ceiling", "daylight compliance"}));
  EXPECT_EQ(countOf(1, "point", "points"), "1 point");
  EXPECT_EQ(countOf(0, "point", "points"), "0 points");
  EXPECT_EQ(dateInWords("2026-09-21"), "21 September 2026");
  EXPECT_EQ(dateInWords("2026-01-05T09:30"), "5 January 2026, 09:30");
  EXPECT_EQ(dateInWords("2026-13-01"), "2026-13-01");  // not a date: as written
}

}  // namespace
}  // namespace candela
