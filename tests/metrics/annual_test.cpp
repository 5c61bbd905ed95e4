#include "metrics/annual.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace candela {
namespace {

constexpr int kDays = 365;
constexpr int kYearHours = kDays * 24;

// EPW hour-ending numbers of a non-leap year: 1..24 repeated for 365 days.
std::vector<int> yearHourEnding() {
  std::vector<int> h(kYearHours);
  for (int i = 0; i < kYearHours; ++i) h[i] = i % 24 + 1;
  return h;
}

std::vector<char> defaultOccupancy() {
  const AnnualThresholds t;
  return occupiedHours(yearHourEnding(), t.occupancyStartHour, t.occupancyEndHour);
}

TEST(AnnualOccupancy, EightToSixIsTenHoursADay) {
  const std::vector<char> occ = defaultOccupancy();
  EXPECT_EQ(countHours(occ), 3650);
  // Hour-ending 9 (08:00-09:00, middle 08:30) is the first occupied hour, 18 (17:00-18:00) the last.
  for (int i = 0; i < 24; ++i) EXPECT_EQ(occ[i] != 0, i + 1 >= 9 && i + 1 <= 18) << "hour-ending " << i + 1;
}

TEST(AnnualOccupancy, MiddleOfHourDecides) {
  // 07:30-17:15: middles 7.5 (hour-ending 8) .. 16.5 (hour-ending 17) fall inside, 17.5 does not.
  const std::vector<char> occ = occupiedHours({7, 8, 17, 18}, 7.5, 17.25);
  EXPECT_EQ(occ, (std::vector<char>{0, 1, 1, 0}));
  EXPECT_EQ(countHours(occupiedHours(yearHourEnding(), 0.0, 24.0)), kYearHours);
  EXPECT_EQ(countHours(occupiedHours(yearHourEnding(), 12.0, 12.0)), 0);
  EXPECT_THROW(occupiedHours({1}, 18.0, 8.0), std::invalid_argument);
  EXPECT_THROW(occupiedHours({1}, -1.0, 8.0), std::invalid_argument);
  EXPECT_THROW(occupiedHours({1}, 8.0, 25.0), std::invalid_argument);
}

// The repository's synthetic full-year EPW: its hour field (5th of each record) gives 3650
// occupied hours. The EPW rows are parsed here directly because metrics_test does not link
// candela_photometry (metrics depend on base only).
TEST(AnnualOccupancy, SyntheticEpwYear) {
  std::ifstream in(std::string(CANDELA_TEST_DATA) + "/epw/synthetic_golden_2026.epw");
  ASSERT_TRUE(in) << "missing EPW fixture";
  std::string line;
  for (int i = 0; i < 8 && std::getline(in, line); ++i) {}  // the 8 header lines
  std::vector<int> hours;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::istringstream fields(line);
    std::string field;
    for (int f = 0; f < 4; ++f) std::getline(fields, field, ',');  // year, month, day, hour
    hours.push_back(std::stoi(field));
  }
  ASSERT_EQ(hours.size(), static_cast<std::size_t>(kYearHours));  // 2026 is not a leap year
  EXPECT_EQ(hours.front(), 1);
  EXPECT_EQ(hours.back(), 24);
  EXPECT_EQ(countHours(occupiedHours(hours, 8.0, 18.0)), 3650);
}

// A one-sensor year of the same value every hour.
std::vector<float> constantYear(float lux) { return std::vector<float>(kYearHours, lux); }

TEST(AnnualMetrics, Constant500LuxYear) {
  const std::vector<float> e = constantYear(500.0f), direct = constantYear(0.0f);
  const std::vector<char> occ = defaultOccupancy();
  const auto m = sensorAnnualMetrics(e.data(), direct.data(), 1, kYearHours, occ, AnnualThresholds{});
  ASSERT_EQ(m.size(), 1u);
  EXPECT_DOUBLE_EQ(m[0].da, 100.0);
  EXPECT_DOUBLE_EQ(m[0].cda, 100.0);
  EXPECT_DOUBLE_EQ(m[0].udiAutonomous, 100.0);
  EXPECT_EQ(m[0].udiFellShort + m[0].udiSupplementary + m[0].udiExceeded, 0.0);
  EXPECT_TRUE(m[0].sdaPass);
  EXPECT_EQ(m[0].aseHours, 0);
  EXPECT_FALSE(m[0].aseExceeded);
  EXPECT_EQ(m[0].sunHours, 0);
  const GridAnnualSummary g = summarizeAnnual(m, countHours(occ));
  EXPECT_DOUBLE_EQ(g.DA300, 100.0);
  EXPECT_DOUBLE_EQ(g.cDA300, 100.0);
  EXPECT_DOUBLE_EQ(g.UDI_autonomous, 100.0);
  EXPECT_DOUBLE_EQ(g.sDA300_50, 100.0);
  EXPECT_DOUBLE_EQ(g.ASE1000_250, 0.0);
  EXPECT_EQ(g.sensors, 1);
  EXPECT_EQ(g.occupiedHours, 3650);
}

// 250 lux all year: below 300, so DA 0; cDA partial credit 250/300 = 83.33 %; UDI supplementary.
TEST(AnnualMetrics, Constant250LuxYear) {
  const std::vector<float> e = constantYear(250.0f);
  const auto m = sensorAnnualMetrics(e.data(), nullptr, 1, kYearHours, defaultOccupancy(), AnnualThresholds{});
  EXPECT_DOUBLE_EQ(m[0].da, 0.0);
  EXPECT_NEAR(m[0].cda, 100.0 * 250.0 / 300.0, 1e-9);
  EXPECT_DOUBLE_EQ(m[0].udiSupplementary, 100.0);
  EXPECT_FALSE(m[0].sdaPass);
}

// Dark for the first 100 days, 5000 lux of direct sun (and total) from day 100 on.
// Occupied: 100 days x 10 h = 1000 h at 0 lux, 265 x 10 = 2650 h at 5000 lux (of 3650).
TEST(AnnualMetrics, StepSeries) {
  std::vector<float> e(kYearHours, 0.0f);
  for (int i = 100 * 24; i < kYearHours; ++i) e[i] = 5000.0f;
  const auto m = sensorAnnualMetrics(e.data(), e.data(), 1, kYearHours, defaultOccupancy(), AnnualThresholds{});
  EXPECT_DOUBLE_EQ(m[0].da, 100.0 * 2650 / 3650);
  EXPECT_DOUBLE_EQ(m[0].cda, 100.0 * 2650 / 3650);  // 0 lux earns nothing, 5000 lux full credit
  EXPECT_DOUBLE_EQ(m[0].udiFellShort, 100.0 * 1000 / 3650);
  EXPECT_DOUBLE_EQ(m[0].udiExceeded, 100.0 * 2650 / 3650);
  EXPECT_EQ(m[0].udiSupplementary + m[0].udiAutonomous, 0.0);
  EXPECT_TRUE(m[0].sdaPass);                 // 72.6 % >= 50 %
  EXPECT_EQ(m[0].aseHours, 2650);            // occupied hours only
  EXPECT_TRUE(m[0].aseExceeded);
  EXPECT_EQ(m[0].sunHours, 265 * 24);        // every hour of the year, night included
}

// Alternating hours: even record indices 1000 lux, odd 200 lux. Occupied indices of a day are
// 8..17, five of each parity, so 1825 h at 1000 lux and 1825 h at 200 lux.
TEST(AnnualMetrics, AlternatingHoursSitOnTheSdaBoundary) {
  std::vector<float> e(kYearHours);
  for (int i = 0; i < kYearHours; ++i) e[i] = (i % 2 == 0) ? 1000.0f : 200.0f;
  const std::vector<char> occ = defaultOccupancy();
  auto m = sensorAnnualMetrics(e.data(), nullptr, 1, kYearHours, occ, AnnualThresholds{});
  EXPECT_DOUBLE_EQ(m[0].da, 50.0);
  EXPECT_NEAR(m[0].cda, 100.0 * (1825 * 1.0 + 1825 * (200.0 / 300.0)) / 3650, 1e-9);
  EXPECT_DOUBLE_EQ(m[0].udiSupplementary, 50.0);
  EXPECT_DOUBLE_EQ(m[0].udiAutonomous, 50.0);
  EXPECT_TRUE(m[0].sdaPass);  // exactly 50 %: LM-83 asks for "at least" 50 %
  EXPECT_EQ(m[0].sunHours, 0);
  // One bright occupied hour less (day 0, index 8) and the sensor falls short of 50 %.
  e[8] = 200.0f;
  m = sensorAnnualMetrics(e.data(), nullptr, 1, kYearHours, occ, AnnualThresholds{});
  EXPECT_DOUBLE_EQ(m[0].da, 100.0 * 1824 / 3650);
  EXPECT_FALSE(m[0].sdaPass);
}

// Each sensor holds one constant value; the bins follow the boundary rules of annual.h.
TEST(AnnualMetrics, UdiBoundaries) {
  const std::vector<float> values = {99.5f, 100.0f, 299.5f, 300.0f, 3000.0f, 3000.5f};
  const int nHours = 24;
  std::vector<float> e;
  for (float v : values) e.insert(e.end(), nHours, v);
  std::vector<int> hours(nHours);
  for (int i = 0; i < nHours; ++i) hours[i] = i + 1;
  const std::vector<char> occ = occupiedHours(hours, 8.0, 18.0);
  const auto m = sensorAnnualMetrics(e.data(), nullptr, static_cast<int>(values.size()), nHours, occ,
                                     AnnualThresholds{});
  EXPECT_EQ(m[0].udiFellShort, 100.0);      // 99.5 < 100
  EXPECT_EQ(m[1].udiSupplementary, 100.0);  // 100 belongs to supplementary
  EXPECT_EQ(m[2].udiSupplementary, 100.0);  // 299.5 < 300
  EXPECT_EQ(m[3].udiAutonomous, 100.0);     // 300 is autonomous ...
  EXPECT_EQ(m[3].da, 100.0);                // ... and reaches the DA threshold
  EXPECT_EQ(m[2].da, 0.0);
  EXPECT_EQ(m[4].udiAutonomous, 100.0);     // 3000 is still autonomous
  EXPECT_EQ(m[5].udiExceeded, 100.0);       // above 3000
  EXPECT_EQ(m[5].cda, 100.0);               // credit capped at 1
}

TEST(AnnualMetrics, AseCountsOccupiedHoursAndHasStrictHourLimit) {
  const std::vector<char> occ = defaultOccupancy();
  // Sensor 0: 2000 lux direct sun every hour. Sensor 1: exactly 1000 lux in the first 250
  // occupied hours. Sensor 2: the same for 251 occupied hours. Sensor 3: 999 lux all year.
  std::vector<float> direct(4 * kYearHours, 0.0f);
  for (int h = 0; h < kYearHours; ++h) {
    direct[h] = 2000.0f;
    direct[3 * kYearHours + h] = 999.0f;
  }
  int seen = 0;
  for (int h = 0; h < kYearHours && seen < 251; ++h) {
    if (!occ[h]) continue;
    if (seen < 250) direct[kYearHours + h] = 1000.0f;
    direct[2 * kYearHours + h] = 1000.0f;
    ++seen;
  }
  const std::vector<float> total(4 * kYearHours, 500.0f);
  const auto m = sensorAnnualMetrics(total.data(), direct.data(), 4, kYearHours, occ, AnnualThresholds{});
  EXPECT_EQ(m[0].aseHours, 3650);
  EXPECT_EQ(m[0].sunHours, kYearHours);
  EXPECT_TRUE(m[0].aseExceeded);
  EXPECT_EQ(m[1].aseHours, 250);  // 1000 lux counts (">= 1000"), 250 h is not "more than 250"
  EXPECT_FALSE(m[1].aseExceeded);
  EXPECT_EQ(m[2].aseHours, 251);
  EXPECT_TRUE(m[2].aseExceeded);
  EXPECT_EQ(m[3].aseHours, 0);
  EXPECT_EQ(m[3].sunHours, kYearHours);
  const GridAnnualSummary g = summarizeAnnual(m, countHours(occ));
  EXPECT_DOUBLE_EQ(g.ASE1000_250, 50.0);  // sensors 0 and 2 of 4
  EXPECT_DOUBLE_EQ(g.sunHoursMean, (kYearHours + 250 + 251 + kYearHours) / 4.0);
}

// 100 sensors, 5 hours. Hour 0: 2 sunlit sensors (2 %, not more) -> open. Hour 1: 3 -> closed.
// Hour 2: 3 sensors at 999 lux (not direct sun) -> open. Hour 3: 3 at exactly 1000 -> closed.
// Hour 4: 50 sunlit but unoccupied -> open.
TEST(AnnualBlinds, TwoPercentRule) {
  const int nSensors = 100, nHours = 5;
  std::vector<float> direct(nSensors * nHours, 0.0f);
  auto set = [&](int count, int hour, float lux) {
    for (int s = 0; s < count; ++s) direct[s * nHours + hour] = lux;
  };
  set(2, 0, 5000.0f);
  set(3, 1, 5000.0f);
  set(3, 2, 999.0f);
  set(3, 3, 1000.0f);
  set(50, 4, 5000.0f);
  const std::vector<char> occ = {1, 1, 1, 1, 0};
  const std::vector<char> closed = blindsClosedHours(direct.data(), nSensors, nHours, occ);
  EXPECT_EQ(closed, (std::vector<char>{0, 1, 0, 1, 0}));

  // With the blinds closed in hours 1 and 3 the shaded illuminance (50 lux) replaces the open
  // one (800 lux) for DA/UDI: 2 of 4 occupied hours reach 300 lux.
  const std::vector<float> open(nSensors * nHours, 800.0f), shaded(nSensors * nHours, 50.0f);
  const auto m = sensorAnnualMetrics(open.data(), direct.data(), nSensors, nHours, occ, AnnualThresholds{},
                                     shaded.data(), &closed);
  EXPECT_DOUBLE_EQ(m[50].da, 50.0);
  EXPECT_DOUBLE_EQ(m[50].cda, 100.0 * (2 * 1.0 + 2 * 50.0 / 300.0) / 4);
  EXPECT_DOUBLE_EQ(m[50].udiFellShort, 50.0);
  EXPECT_DOUBLE_EQ(m[50].udiAutonomous, 50.0);
  EXPECT_TRUE(m[50].sdaPass);
  // ASE and sun hours ignore the blinds: sensor 0 has direct sun >= 1000 in occupied hours 0, 1, 3.
  EXPECT_EQ(m[0].aseHours, 3);
  EXPECT_EQ(m[0].sunHours, 5);
  // Without the closed flags (or without shaded values) the open illuminance is used throughout.
  const auto noBlinds = sensorAnnualMetrics(open.data(), direct.data(), nSensors, nHours, occ,
                                            AnnualThresholds{}, shaded.data(), nullptr);
  EXPECT_DOUBLE_EQ(noBlinds[50].da, 100.0);
}

TEST(AnnualBlinds, CountsOverBlocksOfSensorsGiveTheWholeGridsFlags) {
  // 10 sensors, 3 hours; the count of hour 1 crosses the blocks: 3 of 10 (> 2 % × 10 = 0.2, and
  // also past a 25 % fraction) only when both blocks are counted.
  const int nSensors = 10, nHours = 3;
  std::vector<float> direct(nSensors * nHours, 0.0f);
  direct[1 * nHours + 1] = 1500.0f;   // block 1 (sensors 0..3)
  direct[5 * nHours + 1] = 1000.0f;   // block 2 (sensors 4..9)
  direct[8 * nHours + 1] = 2000.0f;
  direct[9 * nHours + 2] = 999.0f;    // below the threshold
  const std::vector<char> occ = {1, 1, 1};
  for (double fraction : {0.02, 0.25}) {
    std::vector<int> sunlit(nHours, 0);
    countSunlitSensors(direct.data(), 4, nHours, 1000.0, sunlit);
    countSunlitSensors(direct.data() + 4 * nHours, 6, nHours, 1000.0, sunlit);
    EXPECT_EQ(sunlit, (std::vector<int>{0, 3, 0}));
    EXPECT_EQ(blindsClosedFromCounts(sunlit, nSensors, occ, fraction),
              blindsClosedHours(direct.data(), nSensors, nHours, occ, 1000.0, fraction));
  }
  std::vector<int> firstBlockOnly(nHours, 0);
  countSunlitSensors(direct.data(), 4, nHours, 1000.0, firstBlockOnly);
  EXPECT_EQ(blindsClosedFromCounts(firstBlockOnly, nSensors, occ, 0.25), (std::vector<char>{0, 0, 0}));
  EXPECT_EQ(blindsClosedFromCounts({0, 3, 0}, nSensors, occ, 0.25), (std::vector<char>{0, 1, 0}));
  std::vector<int> wrong(2, 0);
  EXPECT_THROW(countSunlitSensors(direct.data(), 4, nHours, 1000.0, wrong), std::invalid_argument);
  EXPECT_THROW(blindsClosedFromCounts(wrong, nSensors, occ), std::invalid_argument);
}

TEST(AnnualBlinds, CustomFractionAndThreshold) {
  // 10 sensors, one hour, 1 sensor at 600 lux: with aseLux 500 and 5 %, 1 > 0.5 closes the blinds.
  std::vector<float> direct(10, 0.0f);
  direct[0] = 600.0f;
  EXPECT_EQ(blindsClosedHours(direct.data(), 10, 1, {1}, 500.0, 0.05), (std::vector<char>{1}));
  EXPECT_EQ(blindsClosedHours(direct.data(), 10, 1, {1}, 1000.0, 0.05), (std::vector<char>{0}));
  EXPECT_EQ(blindsClosedHours(direct.data(), 10, 1, {1}, 500.0, 0.10), (std::vector<char>{0}));
}

TEST(AnnualSummary, MeansAndSharesOverSensors) {
  // Sensor 0 at 500 lux, sensor 1 at 250 lux, all year.
  std::vector<float> e = constantYear(500.0f);
  const std::vector<float> second = constantYear(250.0f);
  e.insert(e.end(), second.begin(), second.end());
  const std::vector<char> occ = defaultOccupancy();
  const GridAnnualSummary g =
      summarizeAnnual(sensorAnnualMetrics(e.data(), nullptr, 2, kYearHours, occ, AnnualThresholds{}),
                      countHours(occ));
  EXPECT_DOUBLE_EQ(g.DA300, 50.0);
  EXPECT_NEAR(g.cDA300, (100.0 + 100.0 * 250.0 / 300.0) / 2, 1e-9);
  EXPECT_DOUBLE_EQ(g.UDI_autonomous, 50.0);
  EXPECT_DOUBLE_EQ(g.UDI_supplementary, 50.0);
  EXPECT_DOUBLE_EQ(g.UDI_fell_short + g.UDI_exceeded, 0.0);
  EXPECT_DOUBLE_EQ(g.sDA300_50, 50.0);
  EXPECT_EQ(g.sensors, 2);
  const GridAnnualSummary empty = summarizeAnnual({}, 3650);
  EXPECT_EQ(empty.sensors, 0);
  EXPECT_EQ(empty.DA300, 0.0);
}

TEST(AnnualMetrics, CustomThresholds) {
  // DA at 500 lux: a 500 lux year passes, a 499 lux year earns cDA 99.8 %.
  AnnualThresholds t;
  t.daLux = 500.0;
  const std::vector<float> a = constantYear(500.0f), b = constantYear(499.0f);
  const std::vector<char> occ = defaultOccupancy();
  EXPECT_DOUBLE_EQ(sensorAnnualMetrics(a.data(), nullptr, 1, kYearHours, occ, t)[0].da, 100.0);
  const auto mb = sensorAnnualMetrics(b.data(), nullptr, 1, kYearHours, occ, t);
  EXPECT_DOUBLE_EQ(mb[0].da, 0.0);
  EXPECT_NEAR(mb[0].cda, 100.0 * 499.0 / 500.0, 1e-9);
  EXPECT_DOUBLE_EQ(mb[0].udiSupplementary, 100.0);  // 100 <= 499 < daLux
}

TEST(AnnualMetrics, NoOccupiedHoursGivesZeros) {
  const std::vector<float> e = constantYear(500.0f);
  const std::vector<char> none(kYearHours, 0);
  const auto m = sensorAnnualMetrics(e.data(), e.data(), 1, kYearHours, none, AnnualThresholds{});
  EXPECT_EQ(m[0].da, 0.0);
  EXPECT_EQ(m[0].cda, 0.0);
  EXPECT_FALSE(m[0].sdaPass);
  EXPECT_EQ(m[0].aseHours, 0);
  EXPECT_EQ(m[0].sunHours, kYearHours);
}

TEST(AnnualMetrics, SizeErrors) {
  const std::vector<float> e(10, 1.0f);
  const std::vector<char> occ(5, 1), wrong(4, 1);
  EXPECT_THROW(sensorAnnualMetrics(e.data(), nullptr, 2, 5, wrong, AnnualThresholds{}), std::invalid_argument);
  EXPECT_THROW(sensorAnnualMetrics(nullptr, nullptr, 2, 5, occ, AnnualThresholds{}), std::invalid_argument);
  EXPECT_THROW(sensorAnnualMetrics(e.data(), nullptr, 2, 5, occ, AnnualThresholds{}, e.data(), &wrong),
               std::invalid_argument);
  EXPECT_THROW(blindsClosedHours(e.data(), 2, 5, wrong), std::invalid_argument);
  EXPECT_THROW(blindsClosedHours(nullptr, 2, 5, occ), std::invalid_argument);
  EXPECT_THROW(blindsClosedHours(e.data(), -1, 5, occ), std::invalid_argument);
}

}  // namespace
}  // namespace candela
