// EN 13201 (metrics/en13201.h): the classes and their requirements (each criterion passes at its
// limit and fails just past it), the R3 r-table against the CIE's own figures for it (S1 and Q0),
// its interpolation, and the threshold increment's formula.
#include "metrics/en13201.h"

#include <gtest/gtest.h>

#include <cmath>

namespace candela {
namespace {

TEST(En13201, ClassesParse) {
  for (const char* ok : {"M1", "M6", "m3", "C0", "C5", "P1", "p6"}) EXPECT_TRUE(parseRoadClass(ok)) << ok;
  for (const char* bad : {"M0", "M7", "C6", "P0", "P7", "ME3", "X1", "M", ""}) EXPECT_FALSE(parseRoadClass(bad)) << bad;
  EXPECT_EQ(parseRoadClass("c2")->name(), "C2");
  for (const char* ok : {"HS1", "hs3"}) EXPECT_EQ(parseRoadClass(ok)->family, RoadClassFamily::kHS) << ok;
  for (const char* bad : {"HS0", "HS4", "HSX", "H1", "SC3"}) EXPECT_FALSE(parseRoadClass(bad)) << bad;
  EXPECT_EQ(parseRoadClass("hs2")->name(), "HS2");
  for (const char* ok : {"SC1", "sc9", "EV1", "ev6"}) EXPECT_TRUE(parseAdditionalRoadClass(ok)) << ok;
  for (const char* bad : {"SC0", "SC10", "EV7", "EV0", "ES3", "S1", "P3"}) EXPECT_FALSE(parseAdditionalRoadClass(bad)) << bad;
  EXPECT_EQ(parseAdditionalRoadClass("ev4")->name(), "EV4");
}

// An HS2 road with SC5 and EV6 exactly at their limits (Ē_hs 2.50 lx, uniformity 0.15; E_sc,min
// 2.0 lx; E_v,min 0.5 lx): each criterion passes at its limit and fails just below it.
TEST(En13201, HsAndAdditionalClassesFlipAtTheirLimits) {
  auto atLimits = [] {
    RoadResult r;
    r.roadClass = *parseRoadClass("HS2");
    r.additional = {*parseAdditionalRoadClass("SC5"), *parseAdditionalRoadClass("EV6")};
    r.averageHemisphericalLux = 2.50;
    r.hemisphericalUniformity = 0.15;
    r.minSemiCylindricalLux = 2.0;
    r.minVerticalLux = 0.5;
    return r;
  };
  RoadResult r = atLimits();
  judgeRoad(r);
  EXPECT_EQ(r.verdict, Verdict::kPass);
  ASSERT_EQ(r.criteria.size(), 4u);
  EXPECT_EQ(r.criteria[2].name, "minimum_semi_cylindrical_illuminance_lux");
  EXPECT_DOUBLE_EQ(r.criteria[3].required, 0.5);
  auto failsWith = [&](auto change) {
    RoadResult x = atLimits();
    change(x);
    judgeRoad(x);
    return x.verdict == Verdict::kFail;
  };
  EXPECT_TRUE(failsWith([](RoadResult& x) { x.averageHemisphericalLux = 2.499; }));
  EXPECT_TRUE(failsWith([](RoadResult& x) { x.hemisphericalUniformity = 0.1499; }));
  EXPECT_TRUE(failsWith([](RoadResult& x) { x.minSemiCylindricalLux = 1.999; }));
  EXPECT_TRUE(failsWith([](RoadResult& x) { x.minVerticalLux = 0.499; }));
  // The tables' ends: HS1 5 lx, HS3 1 lx; SC1 10 lx, SC9 0.5 lx; EV1 50 lx, EV6 0.5 lx.
  EXPECT_DOUBLE_EQ(hsClassRequirement(1).averageLux, 5.0);
  EXPECT_DOUBLE_EQ(hsClassRequirement(3).averageLux, 1.0);
  EXPECT_DOUBLE_EQ(additionalClassMinimumLux(*parseAdditionalRoadClass("SC1")), 10.0);
  EXPECT_DOUBLE_EQ(additionalClassMinimumLux(*parseAdditionalRoadClass("SC9")), 0.5);
  EXPECT_DOUBLE_EQ(additionalClassMinimumLux(*parseAdditionalRoadClass("EV1")), 50.0);
}

// An M4 road exactly at every limit of EN 13201-2 Table 1 (0.75 cd/m², U0 0.40, Ul 0.60, TI 15 %,
// R_EI 0.30).
RoadResult atM4Limits() {
  RoadResult r;
  r.roadClass = *parseRoadClass("M4");
  RoadObserverResult o;
  o.averageLuminanceCdM2 = 0.75;
  o.overallUniformity = 0.40;
  o.longitudinalUniformity = 0.60;
  o.thresholdIncrementPct = 15.0;
  r.observers = {o};
  r.edgeIlluminanceRatio = 0.30;
  return r;
}

TEST(En13201, MClassEachCriterionFlipsAtItsLimit) {
  RoadResult r = atM4Limits();
  judgeRoad(r);
  EXPECT_EQ(r.verdict, Verdict::kPass);
  ASSERT_EQ(r.criteria.size(), 5u);
  auto failsWith = [](auto change) {
    RoadResult x = atM4Limits();
    change(x);
    judgeRoad(x);
    return x.verdict == Verdict::kFail;
  };
  EXPECT_TRUE(failsWith([](RoadResult& x) { x.observers[0].averageLuminanceCdM2 = 0.749; }));
  EXPECT_TRUE(failsWith([](RoadResult& x) { x.observers[0].overallUniformity = 0.399; }));
  EXPECT_TRUE(failsWith([](RoadResult& x) { x.observers[0].longitudinalUniformity = 0.599; }));
  EXPECT_TRUE(failsWith([](RoadResult& x) { x.observers[0].thresholdIncrementPct = 15.01; }));
  EXPECT_TRUE(failsWith([](RoadResult& x) { x.edgeIlluminanceRatio = 0.299; }));
}

TEST(En13201, InstallationTakesTheWorstObserver) {
  RoadResult r = atM4Limits();
  RoadObserverResult second = r.observers[0];
  second.averageLuminanceCdM2 = 2.0;
  second.longitudinalUniformity = 0.5;  // the second lane's centre line fails Ul
  second.thresholdIncrementPct = 5.0;
  r.observers.push_back(second);
  judgeRoad(r);
  EXPECT_DOUBLE_EQ(r.averageLuminanceCdM2, 0.75);
  EXPECT_DOUBLE_EQ(r.longitudinalUniformity, 0.5);
  EXPECT_DOUBLE_EQ(r.thresholdIncrementPct, 15.0);
  EXPECT_EQ(r.verdict, Verdict::kFail);
}

TEST(En13201, CAndPClasses) {
  RoadResult c;
  c.roadClass = *parseRoadClass("C2");  // Ē ≥ 20 lx, U0 ≥ 0.40
  c.averageLux = 20.0;
  c.illuminanceUniformity = 0.40;
  judgeRoad(c);
  EXPECT_EQ(c.verdict, Verdict::kPass);
  c.illuminanceUniformity = 0.39;
  judgeRoad(c);
  EXPECT_EQ(c.verdict, Verdict::kFail);
  RoadResult p;
  p.roadClass = *parseRoadClass("P4");  // Ē ≥ 5 lx, Emin ≥ 1 lx, Ē ≤ 7.5 lx
  p.averageLux = 7.5;
  p.minLux = 1.0;
  judgeRoad(p);
  EXPECT_EQ(p.verdict, Verdict::kPass);
  p.averageLux = 7.6;  // more than 1.5 × the class's Ē
  judgeRoad(p);
  EXPECT_EQ(p.verdict, Verdict::kFail);
  p.averageLux = 4.99;
  judgeRoad(p);
  EXPECT_EQ(p.verdict, Verdict::kFail);
}

TEST(En13201, ClassTablesAreOrdered) {
  // Each class asks at least as much as the next one down.
  for (int k = 1; k < 6; ++k) {
    EXPECT_GE(mClassRequirement(k).averageLuminanceCdM2, mClassRequirement(k + 1).averageLuminanceCdM2);
    EXPECT_LE(mClassRequirement(k).thresholdIncrementPct, mClassRequirement(k + 1).thresholdIncrementPct);
    EXPECT_GE(pClassRequirement(k).averageLux, pClassRequirement(k + 1).averageLux);
  }
  for (int k = 0; k < 5; ++k) EXPECT_GT(cClassRequirement(k).averageLux, cClassRequirement(k + 1).averageLux);
}

TEST(En13201, TheCiesStandardTables) {
  EXPECT_EQ(supportedRTables(), "R1, R2, R3, R4, C1, C2");
  for (const char* missing : {"W1", "N2", "R5", "r3"}) EXPECT_EQ(findRTable(missing), nullptr) << missing;
}

// What the CIE publishes about each standard table, from the table itself: its specular factor
// S1 = r(0, 2)/r(0, 0) lies in its class's range (R1 < 0.42 ≤ R2 < 0.85 ≤ R3 < 1.35 ≤ R4; C1 diffuse
// below 0.4, C2 specular above it) and its average luminance coefficient Q0 = (1/Ω) ∫ q dω is the
// one it is scaled to. The integral over the table's directions, with q dω = r tan γ d(tan γ) dβ,
// by the trapezoid rule on the table's own nodes (blank cells left out of Ω as well), is not the
// CIE's weighting of the cells: it lands 0.3 % (R3) to 4.6 % (R1) from the nominal Q0; 6 % tells a
// correct table from one with a row or the whole table out of scale (a factor 10 anywhere, or the
// wrong class's table under a name, moves Q0 or S1 out of its range).
TEST(En13201, TablesMatchTheCiesFigures) {
  struct Expect {
    const char* name;
    double q0, s1Lo, s1Hi;
  };
  for (const Expect& e : {Expect{"R1", 0.10, 0.0, 0.42}, Expect{"R2", 0.07, 0.42, 0.85}, Expect{"R3", 0.07, 0.85, 1.35},
                          Expect{"R4", 0.08, 1.35, 10.0}, Expect{"C1", 0.10, 0.0, 0.4}, Expect{"C2", 0.07, 0.4, 10.0}}) {
    const RTable& t = *findRTable(e.name);
    EXPECT_DOUBLE_EQ(t.q0, e.q0) << e.name;
    const double s1 = reducedLuminanceCoefficient(t, 0.0, 2.0) / reducedLuminanceCoefficient(t, 0.0, 0.0);
    EXPECT_GE(s1, e.s1Lo) << e.name;
    EXPECT_LT(s1, e.s1Hi) << e.name;
    const std::vector<double>& tg = rTableTanGammas();
    const std::vector<double>& bs = rTableBetasDeg();
    ASSERT_EQ(tg.size(), 29u);
    ASSERT_EQ(bs.size(), 20u);
    double flux = 0.0, solid = 0.0;
    for (std::size_t i = 0; i + 1 < tg.size(); ++i)
      for (std::size_t j = 0; j + 1 < bs.size(); ++j) {
        const double cell = (tg[i + 1] - tg[i]) * (bs[j + 1] - bs[j]) * kPi / 180.0 / 4.0;
        for (std::size_t a : {i, i + 1})
          for (std::size_t b : {j, j + 1}) {
            const double r = reducedLuminanceCoefficient(t, bs[b], tg[a]);
            flux += cell * r * tg[a];
            // dω = sin γ dγ dβ = tan γ / (1 + tan² γ)^{3/2} d(tan γ) dβ, where the table has a value.
            if (r > 0.0) solid += cell * tg[a] / std::pow(1.0 + tg[a] * tg[a], 1.5);
          }
      }
    EXPECT_NEAR(flux / solid, e.q0, 0.06 * e.q0) << e.name;
  }
  // R3's S1 to the two decimals the CIE gives (1.11): read at two printed nodes, 326/294.
  EXPECT_NEAR(reducedLuminanceCoefficient(*findRTable("R3"), 0.0, 2.0) / 0.0294, 1.11, 0.005);
}

TEST(En13201, RTableInterpolation) {
  const RTable& t = *findRTable("R3");
  // Nodes: the printed values × 10⁻⁴.
  EXPECT_DOUBLE_EQ(reducedLuminanceCoefficient(t, 0.0, 0.0), 0.0294);
  EXPECT_DOUBLE_EQ(reducedLuminanceCoefficient(t, 90.0, 1.0), 0.0100);
  EXPECT_DOUBLE_EQ(reducedLuminanceCoefficient(t, 180.0, 12.0), 0.0);  // a blank cell
  // Midway between nodes: linear in β and in tan γ.
  EXPECT_NEAR(reducedLuminanceCoefficient(t, 0.0, 1.125), 0.5 * (0.0362 + 0.0357), 1e-15);
  EXPECT_NEAR(reducedLuminanceCoefficient(t, 52.5, 1.0), 0.5 * (0.0140 + 0.0118), 1e-15);
  EXPECT_NEAR(reducedLuminanceCoefficient(t, 52.5, 1.125),
              0.25 * (0.0140 + 0.0118 + 0.0104 + 0.0083), 1e-15);
  // β is symmetric about the plane of observation.
  EXPECT_DOUBLE_EQ(reducedLuminanceCoefficient(t, -30.0, 1.5), reducedLuminanceCoefficient(t, 30.0, 1.5));
  EXPECT_DOUBLE_EQ(reducedLuminanceCoefficient(t, 330.0, 1.5), reducedLuminanceCoefficient(t, 30.0, 1.5));
  // Past the last row the table says nothing: 0.
  EXPECT_EQ(reducedLuminanceCoefficient(t, 0.0, 12.01), 0.0);
}

TEST(En13201, ThresholdIncrementFormula) {
  EXPECT_NEAR(thresholdIncrementPct(0.1, 1.0), 6.5, 1e-12);
  EXPECT_NEAR(thresholdIncrementPct(0.1, 2.0), 6.5 / std::pow(2.0, 0.8), 1e-12);
  EXPECT_NEAR(thresholdIncrementPct(0.1, 10.0), 9.5 / std::pow(10.0, 1.05), 1e-12);  // above 5 cd/m²
  EXPECT_TRUE(std::isinf(thresholdIncrementPct(0.1, 0.0)));
  EXPECT_EQ(thresholdIncrementPct(0.0, 0.0), 0.0);
  // Lv = 10 E / θ²: 1 lx at 10° gives 0.1 cd/m².
  EXPECT_DOUBLE_EQ(veilingLuminanceCdM2(1.0, 10.0), 0.1);
}

}  // namespace
}  // namespace candela
