// EN 1838's summary.json keys and report section (reports/en1838_report.h).
#include "reports/en1838_report.h"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

namespace candela {
namespace {

En1838Result sample() {
  En1838Result r;
  EscapeRouteResult e;
  e.name = "corridor <A>";
  e.widthM = 1.2;
  e.path = {{0.0, 0.0}, {10.0, 0.0}};
  e.strips.push_back({0.0, 1.2, en1838Stats({2.0, 10.0}), en1838Stats({1.5})});
  judgeEscapeRoute(e);
  r.routes.push_back(e);
  OpenAreaResult a;
  a.name = "hall";
  a.outline = {{0, 1}, {4, 1}, {4, 4}, {0, 4}};
  a.core = {{0.5, 1.5}, {3.5, 1.5}, {3.5, 3.5}, {0.5, 3.5}};
  a.stats = en1838Stats({0.0, 3.0});
  judgeOpenArea(a);
  r.openAreas.push_back(a);
  SafetyPointResult p;
  p.name = "first aid";
  p.positionM = {4.0, 0.5, 1.2};
  p.verticalLux = 6.0;
  p.nearestLuminaireM = std::hypot(4.0 - 3.0, 0.5 - 0.0);  // E1's, 1.12 m: near (within 2 m)
  judgeSafetyPoint(p);
  r.safetyPoints.push_back(p);
  r.luminaires = {{"E1", {3.0, 0.0}, true}, {"N1", {2.0, 2.0}, false}};
  r.emergencyLuminaires = 1;
  judgeEn1838(r);
  return r;
}

TEST(En1838Report, JsonKeysAsTheContractNamesThem) {
  const En1838Section section(sample(), std::nullopt);
  nlohmann::json j = nlohmann::json::object();
  section.addJson(j);
  const nlohmann::json& route = j["escape_routes"][0];
  EXPECT_EQ(route["name"], "corridor <A>");
  EXPECT_DOUBLE_EQ(route["min_centre_line_lux"].get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(route["max_centre_line_lux"].get<double>(), 10.0);
  EXPECT_DOUBLE_EQ(route["uniformity_ratio"].get<double>(), 5.0);
  EXPECT_DOUBLE_EQ(route["central_band_min_lux"].get<double>(), 1.5);
  EXPECT_EQ(route["verdict"], "pass");
  const nlohmann::json& area = j["open_areas"][0];
  for (const char* key : {"name", "min_lux", "max_lux", "uniformity_ratio", "verdict"}) EXPECT_TRUE(area.contains(key));
  EXPECT_TRUE(area["uniformity_ratio"].is_null());  // max/min over a minimum of 0: no number
  EXPECT_EQ(area["verdict"], "fail");
  EXPECT_EQ(j["safety_points"][0]["verdict"], "pass");
  EXPECT_DOUBLE_EQ(j["safety_points"][0]["nearest_emergency_luminaire_m"].get<double>(), std::hypot(1.0, 0.5));
  EXPECT_DOUBLE_EQ(j["safety_points"][0]["near_m"].get<double>(), 2.0);
  EXPECT_EQ(j["emergency_luminaires"], 1);
  EXPECT_EQ(j["light"], "direct");
}

TEST(En1838Report, PlanShowsEveryPartAndEscapesNames) {
  const std::string svg = en1838PlanSvg(sample(), nullptr);
  EXPECT_NE(svg.find("corridor &lt;A&gt; pass"), std::string::npos);
  EXPECT_NE(svg.find("hall fail"), std::string::npos);
  EXPECT_NE(svg.find("first aid pass"), std::string::npos);
  EXPECT_NE(svg.find("E1 (emergency)"), std::string::npos);
  EXPECT_NE(svg.find("<title>N1</title>"), std::string::npos);
  EXPECT_NE(svg.find("stroke-dasharray=\"4 3\""), std::string::npos);  // the open area's core
  const std::string html = En1838Section(sample(), std::nullopt).html();
  EXPECT_NE(html.find("Escape routes"), std::string::npos);
  EXPECT_NE(html.find("∞"), std::string::npos);  // the open area's ratio
  EXPECT_EQ(html.find("corridor <A>"), std::string::npos);
}

}  // namespace
}  // namespace candela
