#include "metrics/en17037.h"

#include <gtest/gtest.h>

#include <vector>

namespace candela {
namespace {

TEST(En17037DaylightHours, HalfTheYearWithTheMostDiffuseLightTiesToTheEarlierHour) {
  // 8760 hours: diffuse 1 lx in the first 4000, 5 lx in the next 1000, 3 lx in the rest (3760).
  std::vector<double> e(8760, 3.0);
  for (int h = 0; h < 4000; ++h) e[h] = 1.0;
  for (int h = 4000; h < 5000; ++h) e[h] = 5.0;
  const std::vector<char> d = daylightHours(e);
  int count = 0;
  for (char f : d) count += f;
  EXPECT_EQ(count, 4380);
  // All 1000 hours at 5 lx and 3380 of those at 3 lx (the earliest), none at 1 lx.
  for (int h = 4000; h < 5000; ++h) EXPECT_TRUE(d[h]);
  EXPECT_TRUE(d[5000 + 3379]);
  EXPECT_FALSE(d[5000 + 3380]);
  for (int h = 0; h < 4000; ++h) ASSERT_FALSE(d[h]);
  // Median over them: 3380 values of 3 and 1000 of 5, sorted; the middle pair (2189, 2190) is 3.
  EXPECT_DOUBLE_EQ(medianDiffuseIlluminance(e, d), 3.0);
}

TEST(En17037DaylightHours, MedianOfAnEvenCountIsTheMeanOfTheMiddlePair) {
  const std::vector<double> e{10, 40, 20, 30};
  EXPECT_DOUBLE_EQ(medianDiffuseIlluminance(e, {1, 1, 1, 1}), 25.0);
  EXPECT_DOUBLE_EQ(medianDiffuseIlluminance(e, {1, 0, 1, 1}), 20.0);
  EXPECT_DOUBLE_EQ(medianDiffuseIlluminance(e, {0, 0, 0, 0}), 0.0);
}

// lux[s * hours + h] from one value per sensor for every hour.
std::vector<float> constantYear(const std::vector<float>& perSensor, int hours) {
  std::vector<float> lux;
  for (float v : perSensor) lux.insert(lux.end(), hours, v);
  return lux;
}

TEST(En17037Provision, UniformSixHundredLuxIsMediumBothWays) {
  const int hours = 10;
  ProvisionTally t(std::vector<char>(hours, 1), provisionThresholds());
  const std::vector<float> lux = constantYear(std::vector<float>(8, 600.0f), hours);
  t.add(lux.data(), 8, hours);
  const ProvisionResult r = evaluateProvision(t);
  EXPECT_EQ(r.hourFirstLevel, En17037Level::kMedium);
  EXPECT_EQ(r.sensorFirstLevel, En17037Level::kMedium);
  EXPECT_DOUBLE_EQ(r.levels[1].target.hourFirstTimeFraction, 1.0);
  EXPECT_DOUBLE_EQ(r.levels[2].target.sensorFirstPlaneFraction, 0.0);  // 750 lx nowhere
}

// Five sensors, four daylight hours (and two night hours, which must not count). Sensors 0..2
// reach 300 lx in exactly half of the daylight hours, in different hours: sensor first, 3 of 5
// sensors (60 %) pass; hour first, no hour has half of the sensors at 300 lx. Every sensor has
// 100 lx throughout, so E_TM passes both ways.
TEST(En17037Provision, TheTwoOrdersDisagreeOnAConstructedYear) {
  const std::vector<char> daylight{1, 1, 0, 1, 1, 0};
  const int hours = 6;
  std::vector<float> lux = constantYear(std::vector<float>(5, 150.0f), hours);
  auto set = [&](int s, int h) { lux[static_cast<std::size_t>(s) * hours + h] = 320.0f; };
  set(0, 0), set(0, 1);  // daylight hours 0, 1
  set(1, 3), set(1, 4);  // daylight hours 2, 3
  set(2, 0), set(2, 3);
  for (int s = 3; s < 5; ++s) set(s, 2), set(s, 5);  // night hours: ignored
  ProvisionTally t(daylight, provisionThresholds());
  t.add(lux.data(), 2, hours);  // in two blocks, as the study streams them
  t.add(lux.data() + 2 * hours, 3, hours);
  const ProvisionResult r = evaluateProvision(t);
  EXPECT_EQ(r.daylightHours, 4);
  const ProvisionCriterion& target = r.levels[0].target;
  EXPECT_DOUBLE_EQ(target.sensorFirstPlaneFraction, 0.6);
  EXPECT_TRUE(target.sensorFirstPass);
  EXPECT_DOUBLE_EQ(target.hourFirstTimeFraction, 0.0);  // at most 2 of 5 sensors in any hour
  EXPECT_FALSE(target.hourFirstPass);
  EXPECT_TRUE(r.levels[0].minimumTarget.hourFirstPass);
  EXPECT_TRUE(r.levels[0].minimumTarget.sensorFirstPass);
  EXPECT_EQ(r.sensorFirstLevel, En17037Level::kMinimum);
  EXPECT_EQ(r.hourFirstLevel, En17037Level::kNone);
}

TEST(En17037Provision, NinetyFivePercentOfThePlaneIsInclusive) {
  const int hours = 4;
  for (int lit : {19, 18}) {
    std::vector<float> perSensor(20, 50.0f);
    for (int s = 0; s < lit; ++s) perSensor[s] = 400.0f;
    ProvisionTally t(std::vector<char>(hours, 1), provisionThresholds());
    const std::vector<float> lux = constantYear(perSensor, hours);
    t.add(lux.data(), 20, hours);
    const ProvisionResult r = evaluateProvision(t);
    // E_TM = 100 lx over 95 %: 19 of 20 sensors is exactly 95 %.
    EXPECT_EQ(r.levels[0].minimumTarget.hourFirstPass, lit == 19);
    EXPECT_EQ(r.levels[0].minimumTarget.sensorFirstPass, lit == 19);
    EXPECT_EQ(r.hourFirstLevel, lit == 19 ? En17037Level::kMinimum : En17037Level::kNone);
  }
}

TEST(En17037Provision, HalfOfTheDaylightHoursIsInclusive) {
  // One sensor at 800 lx in 5 of 10 daylight hours, 600 lx otherwise: high (750/500) for
  // exactly 50 % of the time, both ways.
  std::vector<float> lux(10, 600.0f);
  for (int h = 0; h < 5; ++h) lux[h] = 800.0f;
  ProvisionTally t(std::vector<char>(10, 1), provisionThresholds());
  t.add(lux.data(), 1, 10);
  const ProvisionResult r = evaluateProvision(t);
  EXPECT_DOUBLE_EQ(r.levels[2].target.hourFirstTimeFraction, 0.5);
  EXPECT_EQ(r.hourFirstLevel, En17037Level::kHigh);
  EXPECT_EQ(r.sensorFirstLevel, En17037Level::kHigh);
}

TEST(En17037DaylightFactor, TargetsFollowTheSitesMedianDiffuseIlluminance) {
  // E_v,d,med = 15 000 lx: D_T = 2 %, 3.33 %, 5 %; D_TM = 0.67 %, 2 %, 3.33 %.
  std::vector<double> df(20, 2.5);
  df[0] = 0.5;  // one sensor of 20 below D_TM(minimum): 95 % still reach it
  const DaylightFactorResult r = evaluateDaylightFactor(df, 15000.0);
  EXPECT_NEAR(r.levels[0].targetPct, 2.0, 1e-12);
  EXPECT_NEAR(r.levels[0].minimumTargetPct, 100.0 * 100.0 / 15000.0, 1e-12);
  EXPECT_NEAR(r.levels[2].targetPct, 5.0, 1e-12);
  EXPECT_DOUBLE_EQ(r.levels[0].targetPlaneFraction, 0.95);
  EXPECT_DOUBLE_EQ(r.levels[0].minimumPlaneFraction, 0.95);
  EXPECT_TRUE(r.levels[0].pass);
  EXPECT_FALSE(r.levels[1].pass);  // 2.5 % < D_T(medium) 3.33 %
  EXPECT_EQ(r.level, En17037Level::kMinimum);
  df[1] = 0.5;  // 90 %: not even minimum
  EXPECT_EQ(evaluateDaylightFactor(df, 15000.0).level, En17037Level::kNone);
}

TEST(En17037Levels, ThresholdsGradeBothWays) {
  EXPECT_EQ(levelFromThresholds(3.0, 1.5, 3.0, 4.0), En17037Level::kMedium);
  EXPECT_EQ(levelFromThresholds(1.49, 1.5, 3.0, 4.0), En17037Level::kNone);
  EXPECT_EQ(levelFromThresholds(0.42, 0.45, 0.40, 0.35, false), En17037Level::kMinimum);
  EXPECT_EQ(levelFromThresholds(0.36, 0.45, 0.40, 0.35, false), En17037Level::kMedium);
  EXPECT_EQ(levelFromThresholds(0.46, 0.45, 0.40, 0.35, false), En17037Level::kNone);
  EXPECT_EQ(levelFromThresholds(0.35, 0.45, 0.40, 0.35, false), En17037Level::kHigh);
  EXPECT_EQ(levelName(En17037Level::kNone), "none");
}

}  // namespace
}  // namespace candela
