#include "reports/compliance_html.h"
#include "reports/compliance_report.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <limits>

namespace candela {
namespace {

ComplianceReport en17037Entry() {
  ComplianceReport r;
  r.name = "en17037";
  r.standard = "en17037";
  r.verdict = "pass";
  r.verdictLines = {"view out: medium <1 position>"};
  En17037Report e;
  ProvisionSpaceReport s;
  s.space = "work & plane";
  s.illuminance.hourFirstLevel = En17037Level::kMedium;
  e.spaces.push_back(s);
  e.provisionLevel = En17037Level::kMedium;
  e.provisionLevelOther = En17037Level::kMinimum;
  e.sunlightDate = "2026-03-21";
  e.sunlight.push_back({Vec3(1, 0, 1.2), 3.5, {{8.0, 11.5}}, En17037Level::kMedium});
  ViewOutReportPoint v;
  v.sightAngleDeg = 33.4;
  v.outsideDistanceM = std::numeric_limits<double>::infinity();
  e.viewOut.push_back(v);
  r.en17037 = e;
  return r;
}

TEST(ComplianceJson, CarriesTheIssuesKeys) {
  const nlohmann::json j = complianceJson(en17037Entry());
  EXPECT_EQ(j["sunlight_exposure"][0]["hours"], 3.5);
  EXPECT_EQ(j["sunlight_exposure"][0]["intervals"][0][1], 11.5);
  EXPECT_EQ(j["view_out"][0]["horizontal_sight_angle_deg"], 33.4);
  EXPECT_TRUE(j["view_out"][0]["outside_distance_m"].is_null());  // infinite: nothing outside
  EXPECT_TRUE(j["view_out"][0]["outside_unobstructed"].get<bool>());
  EXPECT_EQ(j["daylight_provision"]["level"], "medium");
  EXPECT_TRUE(j["daylight_provision"]["aggregations_disagree"].get<bool>());
  EXPECT_FALSE(j.contains("points"));

  ComplianceReport l;
  l.standard = l.name = "leed-v4.1-option1";
  LeedReport leed;
  leed.points = 2;
  leed.aseExceeds10Percent = true;
  leed.spaces.push_back({"office", 40.0, 60.0, 12.0, 0.0, {}, true, 0.0, {}});
  l.leed = leed;
  const nlohmann::json k = complianceJson(l);
  EXPECT_EQ(k["points"], 2);
  EXPECT_TRUE(k["ase_exceeds_10_percent"].get<bool>());
  EXPECT_EQ(k["spaces"][0]["sDA300_50"], 60.0);
}

TEST(ComplianceHtml, OneSectionPerEntryTextsEscaped) {
  EXPECT_EQ(complianceHtml({}), "");
  const std::string h = complianceHtml({en17037Entry()});
  EXPECT_NE(h.find("EN 17037:2018+A1:2023"), std::string::npos);
  EXPECT_NE(h.find("work &amp; plane"), std::string::npos);
  EXPECT_NE(h.find("&lt;1 position&gt;"), std::string::npos);
  EXPECT_NE(h.find("08:00–11:30"), std::string::npos);
  EXPECT_NE(h.find("nothing modelled outside"), std::string::npos);
  EXPECT_EQ(h.find("work & plane"), std::string::npos);
  EXPECT_NE(h.find("21 March 2026"), std::string::npos);  // dates in words, not ISO
}

// The glare part: the view's direction as a compass point from its true azimuth, check hours in
// words, the difference signed with a real minus, and a level below minimum said so.
TEST(ComplianceHtml, GlareViewsAndChecksReadAsWords) {
  ComplianceReport r = en17037Entry();
  GlareViewReport g;
  g.azimuthDeg = 180.0;
  g.blinds = "lm83";
  g.blindsSpace = "workplane";
  g.blindsClosedHours = 1;
  g.checks.push_back({"2026-11-12T15:00", false, 0.262, 0.305, 1000.0, 1050.0});
  r.en17037->glare.push_back(g);
  r.en17037->sunlight[0].level = En17037Level::kNone;
  const std::string h = complianceHtml({r});
  EXPECT_NE(h.find("south (180°)"), std::string::npos);
  EXPECT_NE(h.find("12 November 2026, 15:00"), std::string::npos);
  EXPECT_NE(h.find("−0.043"), std::string::npos);
  EXPECT_NE(h.find("closed 1 occupied hour<"), std::string::npos);
  EXPECT_NE(h.find("below minimum"), std::string::npos);
  EXPECT_EQ(h.find("2026-11-12T15:00"), std::string::npos);
}

// LEED option 2: one column per clear-sky time, the points' count in the right number, the
// standard error named.
TEST(ComplianceHtml, LeedOption2TimesAsColumns) {
  ComplianceReport l;
  l.standard = l.name = "leed-v4.1-option2";
  LeedReport leed;
  leed.points = 1;
  leed.times = {"2026-03-21T09:00", "2026-09-21T15:00"};
  LeedSpaceReport s;
  s.space = "office";
  s.inRangeByTimePct = {70.0, 69.0};
  s.inRangeByTimeStandardErrorPct = {0.2, 0.1};
  leed.spaces.push_back(s);
  l.leed = leed;
  const std::string h = complianceHtml({l});
  EXPECT_NE(h.find("<th class=\"num\">21 March 2026, 09:00</th>"), std::string::npos);
  EXPECT_NE(h.find("<th class=\"num\">21 September 2026, 15:00</th>"), std::string::npos);
  EXPECT_NE(h.find("1 point (provisional"), std::string::npos);
  EXPECT_EQ(h.find("1 points"), std::string::npos);
  EXPECT_NE(h.find("standard error"), std::string::npos);
}

}  // namespace
}  // namespace candela
