// EN 1838:2013 verdicts (metrics/en1838.h): each requirement passes at its threshold and fails
// just past it.
#include "metrics/en1838.h"

#include <gtest/gtest.h>

#include <limits>

#include <cmath>

namespace candela {
namespace {

// A route of one strip whose centre line reads `centre` and central band `band` (lx).
EscapeRouteResult route(std::vector<double> centre, std::vector<double> band) {
  EscapeRouteResult r;
  r.strips.push_back({0.0, 1.0, en1838Stats(centre), en1838Stats(band)});
  judgeEscapeRoute(r);
  return r;
}

TEST(En1838, StatsAndRatio) {
  const En1838Stats s = en1838Stats({2.0, 8.0, 5.0});
  EXPECT_EQ(s.points, 3u);
  EXPECT_DOUBLE_EQ(s.minLux, 2.0);
  EXPECT_DOUBLE_EQ(s.maxLux, 8.0);
  EXPECT_DOUBLE_EQ(s.averageLux, 5.0);
  EXPECT_DOUBLE_EQ(s.maxToMin(), 4.0);
  EXPECT_TRUE(std::isinf(en1838Stats({0.0, 1.0}).maxToMin()));
}

TEST(En1838, EscapeRouteCentreLineFlipsAtOneLux) {
  EXPECT_EQ(route({1.0, 2.0}, {0.5, 1.0}).verdict, Verdict::kPass);
  EXPECT_EQ(route({0.999, 2.0}, {0.5, 1.0}).verdict, Verdict::kFail);
}

TEST(En1838, EscapeRouteCentralBandFlipsAtHalfALux) {
  EXPECT_EQ(route({1.0, 2.0}, {0.5, 1.0}).verdict, Verdict::kPass);
  EXPECT_EQ(route({1.0, 2.0}, {0.499, 1.0}).verdict, Verdict::kFail);
}

TEST(En1838, EscapeRouteRatioFlipsAtForty) {
  EXPECT_EQ(route({1.0, 40.0}, {1.0}).verdict, Verdict::kPass);
  EXPECT_EQ(route({1.0, 40.01}, {1.0}).verdict, Verdict::kFail);
  EXPECT_DOUBLE_EQ(route({1.0, 40.0}, {1.0}).uniformityRatio, 40.0);
}

TEST(En1838, WideRouteTakesTheWorstStrip) {
  EscapeRouteResult r;
  r.strips.push_back({-1.0, 2.0, en1838Stats({2.0, 4.0}), en1838Stats({1.5})});
  r.strips.push_back({1.0, 2.0, en1838Stats({1.0, 30.0}), en1838Stats({0.7})});
  judgeEscapeRoute(r);
  EXPECT_DOUBLE_EQ(r.minCentreLineLux, 1.0);
  EXPECT_DOUBLE_EQ(r.maxCentreLineLux, 30.0);
  EXPECT_DOUBLE_EQ(r.uniformityRatio, 30.0);  // the strips' own ratios, not 30/1 across them by chance
  EXPECT_DOUBLE_EQ(r.centralBandMinLux, 0.7);
  EXPECT_EQ(r.verdict, Verdict::kPass);
}

TEST(En1838, OpenAreaFlipsAtHalfALuxAndForty) {
  auto area = [](std::vector<double> lux) {
    OpenAreaResult a;
    a.stats = en1838Stats(lux);
    judgeOpenArea(a);
    return a.verdict;
  };
  EXPECT_EQ(area({0.5, 20.0}), Verdict::kPass);
  EXPECT_EQ(area({0.499, 10.0}), Verdict::kFail);
  EXPECT_EQ(area({0.5, 20.0001}), Verdict::kFail);
  EXPECT_EQ(area({}), Verdict::kFail);
}

TEST(En1838, HighRiskAreaTakesTenPercentButAtLeastFifteenLux) {
  auto risky = [](double maintained, std::vector<double> lux) {
    HighRiskAreaResult a;
    a.maintainedLux = maintained;
    a.stats = en1838Stats(lux);
    judgeHighRiskArea(a);
    return a;
  };
  EXPECT_DOUBLE_EQ(risky(500.0, {50.0}).requiredLux, 50.0);
  EXPECT_DOUBLE_EQ(risky(100.0, {50.0}).requiredLux, 15.0);
  EXPECT_EQ(risky(500.0, {50.0, 60.0}).verdict, Verdict::kPass);
  EXPECT_EQ(risky(500.0, {49.9, 60.0}).verdict, Verdict::kFail);
  EXPECT_EQ(risky(100.0, {14.9, 20.0}).verdict, Verdict::kFail);
  // min/max: 0.1 passes, below fails.
  EXPECT_EQ(risky(100.0, {15.0, 150.0}).verdict, Verdict::kPass);
  EXPECT_EQ(risky(100.0, {15.0, 150.1}).verdict, Verdict::kFail);
}

TEST(En1838, SafetyPointFlipsAtFiveLuxAndTwoMetres) {
  SafetyPointResult p;
  p.verticalLux = 5.0;
  p.nearestLuminaireM = 2.0;
  judgeSafetyPoint(p);
  EXPECT_EQ(p.verdict, Verdict::kPass);
  p.verticalLux = 4.999;
  judgeSafetyPoint(p);
  EXPECT_EQ(p.verdict, Verdict::kFail);
  p.verticalLux = 5.0;
  p.nearestLuminaireM = 2.001;  // no emergency luminaire near (EN 1838 4.1)
  judgeSafetyPoint(p);
  EXPECT_EQ(p.verdict, Verdict::kFail);
  p.nearestLuminaireM = std::numeric_limits<double>::infinity();  // none at all
  judgeSafetyPoint(p);
  EXPECT_EQ(p.verdict, Verdict::kFail);
}

TEST(En1838, OverallVerdict) {
  En1838Result r;
  judgeEn1838(r);
  EXPECT_EQ(r.verdict, Verdict::kNotChecked);
  r.routes.push_back(route({1.0}, {1.0}));
  judgeEn1838(r);
  EXPECT_EQ(r.verdict, Verdict::kPass);
  r.routes.push_back(route({0.1}, {1.0}));
  judgeEn1838(r);
  EXPECT_EQ(r.verdict, Verdict::kFail);
}

}  // namespace
}  // namespace candela
