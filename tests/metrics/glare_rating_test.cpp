// The glare rating of CIE 112 (metrics/glare_rating.h) against the formulas worked by hand: a
// luminaire's E_eye and θ from the geometry, L_vl, L_ve, GR, the lines of sight; and the
// verdicts of EN 12464-2 (metrics/en12464_2.h).
#include "metrics/glare_rating.h"

#include "metrics/en12464_2.h"

#include <gtest/gtest.h>

#include <cmath>

namespace candela {
namespace {

constexpr double kDeg = kPi / 180.0;

TEST(GlareRating, SingleLuminaireByHand) {
  // Eye 1.5 m above the ground looking north, horizontally; a 1000 cd luminaire 20 m ahead, 8 m
  // above the eye: d² = 20² + 8² = 464, cos θ = 20/√464, θ = atan(8/20).
  const Vec3 eye(0.0, 0.0, 1.5), source(0.0, 20.0, 9.5);
  const std::optional<VeilingSource> s = veilingSource(eye, lineOfSight(0.0, 0.0), source, 1000.0);
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->angleDeg, std::atan(8.0 / 20.0) / kDeg, 1e-12);
  EXPECT_NEAR(s->eyeLux, 1000.0 * (20.0 / std::sqrt(464.0)) / 464.0, 1e-12);
  // Looking 2° down the angle grows by 2° (the luminaire is in the sight's vertical plane).
  const std::optional<VeilingSource> down = veilingSource(eye, lineOfSight(0.0, -2.0), source, 1000.0);
  ASSERT_TRUE(down);
  EXPECT_NEAR(down->angleDeg, std::atan(8.0 / 20.0) / kDeg + 2.0, 1e-9);
  EXPECT_NEAR(down->eyeLux, 1000.0 * std::cos(down->angleDeg * kDeg) / 464.0, 1e-12);
  // Half of it passes an obstruction: half the illuminance.
  EXPECT_NEAR(veilingSource(eye, lineOfSight(0.0, 0.0), source, 1000.0, 0.5)->eyeLux, 0.5 * s->eyeLux, 1e-15);
  // L_vl = 10 E / θ².
  EXPECT_NEAR(luminairesVeilingLuminance({*s}), 10.0 * s->eyeLux / (s->angleDeg * s->angleDeg), 1e-15);
}

TEST(GlareRating, SourcesBehindTheEyeGiveNoVeil) {
  const Vec3 eye(0.0, 0.0, 1.5);
  EXPECT_FALSE(veilingSource(eye, lineOfSight(0.0, 0.0), Vec3(0.0, -20.0, 9.5), 1000.0));  // behind
  EXPECT_FALSE(veilingSource(eye, lineOfSight(0.0, 0.0), Vec3(0.0, 0.0, 9.5), 1000.0));    // θ = 90°
  EXPECT_FALSE(veilingSource(eye, lineOfSight(0.0, 0.0), Vec3(0.0, 20.0, 9.5), 0.0));      // dark
  EXPECT_FALSE(veilingSource(eye, lineOfSight(0.0, 0.0), Vec3(0.0, 20.0, 9.5), 1000.0, 0.0));  // hidden
  EXPECT_EQ(luminairesVeilingLuminance({}), 0.0);
}

TEST(GlareRating, EnvironmentVeilAndRatingByHand) {
  // L_ve = 0.035 ρ E_hav / π: ρ 0.2 and 20 lx give 0.14/π cd/m².
  EXPECT_NEAR(environmentVeilingLuminance(0.2, 20.0), 0.14 / kPi, 1e-15);
  // L_vl 2 cd/m², L_ve 0.1 cd/m²: GR = 27 + 24 (log10 2 − 0.9 log10 0.1) = 27 + 24 (log10 2 + 0.9).
  EXPECT_NEAR(*glareRating(2.0, 0.1), 27.0 + 24.0 * (std::log10(2.0) + 0.9), 1e-12);
  // Ten times the veil of the luminaires: 24 more.
  EXPECT_NEAR(*glareRating(20.0, 0.1) - *glareRating(2.0, 0.1), 24.0, 1e-12);
  // Ten times the environment's: 24 × 0.9 less.
  EXPECT_NEAR(*glareRating(2.0, 0.1) - *glareRating(2.0, 1.0), 21.6, 1e-12);
  EXPECT_FALSE(glareRating(0.0, 0.1));  // no luminaire in front of the eye
  EXPECT_FALSE(glareRating(2.0, 0.0));  // a black or unlit area: unbounded
}

TEST(GlareRating, LinesOfSight) {
  const std::vector<double> az = viewAzimuthsDeg(45.0);
  ASSERT_EQ(az.size(), 8u);
  for (std::size_t k = 0; k < az.size(); ++k) EXPECT_DOUBLE_EQ(az[k], 45.0 * static_cast<double>(k));
  EXPECT_EQ(viewAzimuthsDeg(360.0).size(), 1u);
  EXPECT_EQ(viewAzimuthsDeg(7.0).size(), 52u);  // 0, 7, …, 357
  // Azimuth clockwise from plan +Y; inclination above the horizontal.
  const Vec3 north = lineOfSight(0.0, 0.0), east = lineOfSight(90.0, 0.0), sw = lineOfSight(225.0, 0.0);
  EXPECT_NEAR(glm::length(north - Vec3(0.0, 1.0, 0.0)), 0.0, 1e-15);
  EXPECT_NEAR(glm::length(east - Vec3(1.0, 0.0, 0.0)), 0.0, 1e-15);
  EXPECT_NEAR(glm::length(sw - Vec3(-std::sqrt(0.5), -std::sqrt(0.5), 0.0)), 0.0, 1e-15);
  const Vec3 down = lineOfSight(0.0, -2.0);
  EXPECT_NEAR(glm::length(down - Vec3(0.0, std::cos(2.0 * kDeg), -std::sin(2.0 * kDeg))), 0.0, 1e-15);
}

TEST(En12464_2Verdicts, ObserverAndArea) {
  GrObserverResult o;
  o.taskArea = "yard";
  o.views = {GrViewResult{0.0, {}, 1.0, 1, 44.0}, GrViewResult{45.0, {}, 0.0, 0, std::nullopt},
             GrViewResult{90.0, {}, 2.0, 1, 47.5}};
  judgeGrObserver(o);
  EXPECT_DOUBLE_EQ(*o.grMax, 47.5);
  EXPECT_EQ(o.verdict, Verdict::kNotChecked);  // no limit
  o.grLimit = 47.5;
  judgeGrObserver(o);
  EXPECT_EQ(o.verdict, Verdict::kPass);  // "not above": equal passes
  o.grLimit = 45.0;
  judgeGrObserver(o);
  EXPECT_EQ(o.verdict, Verdict::kFail);

  OutdoorAreaResult a;
  a.name = "yard";
  a.averageLux = 20.0;
  a.maintainedLux = 20.0;
  a.u0 = 0.39;
  a.uniformityRequired = 0.40;
  judgeOutdoorArea(a, {});
  EXPECT_EQ(a.averageVerdict, Verdict::kPass);
  EXPECT_EQ(a.uniformityVerdict, Verdict::kFail);
  EXPECT_EQ(a.grVerdict, Verdict::kNotChecked);  // no observer
  EXPECT_EQ(a.verdict, Verdict::kFail);
  a.uniformityRequired = 0.39;
  judgeOutdoorArea(a, {o});
  EXPECT_EQ(a.grVerdict, Verdict::kFail);
  EXPECT_DOUBLE_EQ(*a.grMax, 47.5);
  ASSERT_EQ(a.grObservers.size(), 1u);
  EXPECT_EQ(a.verdict, Verdict::kFail);
  o.taskArea = "other";
  judgeOutdoorArea(a, {o});
  EXPECT_TRUE(a.grObservers.empty());
  EXPECT_EQ(a.verdict, Verdict::kPass);

  En12464_2Result r;
  r.areas = {a};
  r.observers = {o};
  judgeEn12464_2(r);
  EXPECT_EQ(r.verdict, Verdict::kFail);  // the observer fails on its own
}

}  // namespace
}  // namespace candela
