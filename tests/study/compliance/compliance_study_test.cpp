// [[compliance]] through the whole annual study: EN 17037's daylight provision on a synthetic
// weather year whose hours are constructed to land at known fractions of the daylight hours, its
// daylight factor against the open sky's 100 %, LEED option 1's points from the study's sDA, and
// option 2's sky (the equinox window's means) and shares on spaces of known illuminance.
#include "study/annual_study.h"

#include "photometry/annual_sky.h"
#include "photometry/epw.h"
#include "photometry/sun_spa.h"
#include "metrics/annual.h"
#include "reports/annual_results.h"
#include "study/case/case_file.h"
#include "study/case/case_scene.h"
#include "study/compliance/compliance_leed.h"
#include "study/run_case.h"
#include "study/trace_options.h"

#include "tests/support/temp_files.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace candela {
namespace {

namespace fs = std::filesystem;
using test_support::scratchDir;

// Diffuse horizontal irradiance (W/m²) of the twelve hours ending 7..18 of every day: 7 hours
// bright, 5 dull, in an order that moves through the day with the date; no direct sun, night
// dark. So exactly 4380 hours have daylight: they are the daylight hours. The Perez efficacy of
// these hours spans 108–169 lm/W, so the bright hours have 1080–1510 lx (above 750 lx by more than
// 10 %) and the dull ones 164–220 lx (between 100 and 300 lx, 10 % clear of both).
double diffuseWm2(int day, int hourEnding) {
  if (hourEnding < 7 || hourEnding > 18) return 0.0;
  static const double kLevels[12] = {10, 10, 10, 10, 10, 10, 10, 1.3, 1.3, 1.3, 1.3, 1.3};
  return kLevels[(hourEnding - 7 + day) % 12];
}

// The repository's synthetic Golden year with its radiation replaced by diffuseWm2.
fs::path writeWeather(const fs::path& dir) {
  std::ifstream in(std::string(CANDELA_TEST_DATA) + "/epw/synthetic_golden_2026.epw");
  std::ofstream out(dir / "constructed.epw");
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    if (n++ < 8) {
      out << line << "\n";
      continue;
    }
    std::vector<std::string> f;
    std::stringstream ss(line);
    for (std::string v; std::getline(ss, v, ',');) f.push_back(v);
    const int day = (n - 9) / 24, hourEnding = std::stoi(f[3]);
    const double dhi = diffuseWm2(day, hourEnding);
    f[13] = f[15] = std::to_string(dhi);  // global = diffuse
    f[14] = "0";                          // no beam
    f[16] = f[18] = std::to_string(110.0 * dhi);
    f[17] = "0";
    for (std::size_t i = 0; i < f.size(); ++i) out << (i ? "," : "") << f[i];
    out << "\n";
  }
  return dir / "constructed.epw";
}

// The annual study of dir/case.toml, its results in dir/out.
RunResult runCaseIn(const fs::path& dir) {
  CaseFile c = readCaseFile(dir / "case.toml");
  RunContext run;
  run.request.outDir = dir / "out";
  c.settings.scene = sceneReadOptions(&c.settings, run.request.trace);
  run.outDir = dir / "out";
  run.start = std::chrono::steady_clock::now();
  run.startedAt = "2026-01-01 00:00";
  return runAnnualStudy(c, run, silentObserver());
}

class ComplianceStudy : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = scratchDir("compliance_study", std::to_string(::getpid()));
    const fs::path epw = writeWeather(dir_);
    // Nine upward sensors under the open sky: no geometry, so each sees the sky's horizontal
    // illuminance, the same at every sensor.
    std::ofstream(dir_ / "case.toml")
        << "[sky]\ntype = \"annual\"\nweather = \"constructed.epw\"\n[annual]\nblinds = false\n"
           "[[grid]]\nname = \"plane\"\ncorners = [[0, 0], [3, 3]]\nheight = 0.8\nspacing = 1\n"
           "[[compliance]]\nstandard = \"en17037\"\n"
           "[[compliance]]\nstandard = \"leed-v4.1-option1\"\n"
           "[settings]\nquality = \"draft\"\n";
    result_ = new RunResult(runCaseIn(dir_));
    // The year's diffuse illuminance as the study's sky has it (Perez efficacy of each hour).
    const EpwFile w = readEpw(epw.string());
    sky_ = new AnnualSky(makeAnnualSky(w, caseSite(readCaseFile(dir_ / "case.toml"), &w.location), AnnualSkyOptions{}));
  }
  static void TearDownTestSuite() {
    delete result_;
    delete sky_;
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  static const ComplianceReport& entry(int i) { return result_->data.compliance.at(static_cast<std::size_t>(i)); }
  static RunResult* result_;
  static AnnualSky* sky_;
  static fs::path dir_;
};
RunResult* ComplianceStudy::result_ = nullptr;
AnnualSky* ComplianceStudy::sky_ = nullptr;
fs::path ComplianceStudy::dir_;

TEST_F(ComplianceStudy, ProvisionLandsAtTheConstructedFractions) {
  ASSERT_EQ(sky_->degenerateHours, 0);
  if (std::getenv("PRINT_EFFICACY"))
    for (double level : {10.0, 1.3}) {
      double lo = 1e9, hi = 0;
      for (std::size_t h = 0; h < sky_->hours.size(); ++h) {
        const AnnualHour& a = sky_->hours[h];
        if (diffuseWm2(static_cast<int>(h / 24), a.hour) != level) continue;
        lo = std::min(lo, a.diffuseHorizontalLux / level), hi = std::max(hi, a.diffuseHorizontalLux / level);
      }
      std::printf("%g W/m2: %g .. %g lm/W\n", level, lo, hi);
    }
  const En17037Report& r = *entry(0).en17037;
  EXPECT_EQ(r.daylightHours, 4380);
  ASSERT_EQ(r.spaces.size(), 1u);
  const ProvisionResult& p = r.spaces[0].illuminance;
  EXPECT_EQ(p.sensors, 9);
  // Every sensor sees the sky's horizontal illuminance (the coefficients' error is well under the
  // 10 % margin below), so an hour has all sensors or none at a threshold: the share of daylight
  // hours at it is the share of hours whose outdoor diffuse illuminance reaches it.
  for (const ProvisionLevelResult& l : p.levels)
    for (const ProvisionCriterion* c : {&l.target, &l.minimumTarget}) {
      int reach = 0, daylight = 0;
      for (const AnnualHour& h : sky_->hours) {
        if (h.diffuseHorizontalLux <= 0.0) continue;
        ++daylight;
        // The construction keeps every hour clear of the thresholds by 10 %.
        ASSERT_GT(std::abs(h.diffuseHorizontalLux / c->thresholdLux - 1.0), 0.10) << c->thresholdLux;
        reach += h.diffuseHorizontalLux >= c->thresholdLux;
      }
      ASSERT_EQ(daylight, 4380);
      EXPECT_DOUBLE_EQ(c->hourFirstTimeFraction, reach / 4380.0) << c->thresholdLux;
      EXPECT_DOUBLE_EQ(c->sensorFirstPlaneFraction, reach >= 2190 ? 1.0 : 0.0) << c->thresholdLux;
    }
  // 300, 500 and 750 lx in the 7 bright hours of 12, 100 lx in all: high, both ways; a year of
  // 5 bright hours in 12 would be none.
  for (const ProvisionLevelResult& l : p.levels) {
    EXPECT_NEAR(l.target.hourFirstTimeFraction, 7.0 / 12.0, 1e-12);
    EXPECT_NEAR(l.minimumTarget.hourFirstTimeFraction, l.minimumTarget.thresholdLux < 300 ? 1.0 : 7.0 / 12.0, 1e-12);
  }
  EXPECT_EQ(p.hourFirstLevel, En17037Level::kHigh);
  EXPECT_EQ(p.sensorFirstLevel, En17037Level::kHigh);
  EXPECT_EQ(r.provisionLevel, En17037Level::kHigh);
}

TEST_F(ComplianceStudy, DaylightFactorOfTheOpenSkyIsAHundredPercent) {
  const En17037Report& r = *entry(0).en17037;
  ASSERT_TRUE(r.spaces[0].daylightFactor);
  // E_v,d,med: the median of the 4380 daylight hours' diffuse illuminance (the sky's own).
  std::vector<double> e;
  for (const AnnualHour& h : sky_->hours)
    if (h.diffuseHorizontalLux > 0.0) e.push_back(h.diffuseHorizontalLux);
  std::sort(e.begin(), e.end());
  EXPECT_NEAR(r.medianDiffuseLux, 0.5 * (e[2189] + e[2190]), 1e-9);
  // An upward sensor under the open overcast sky has D = 100 %: the coefficients' product with the
  // overcast patches reproduces it to the patch quadrature and the draft coefficients' noise
  // (the open-sky validation case: within 0.4 %).
  EXPECT_NEAR(r.spaces[0].meanDaylightFactorPct, 100.0, 1.0);
  // The levels whose targets lie below 99 % are reached, those above 101 % not.
  for (const DaylightFactorLevelResult& l : r.spaces[0].daylightFactor->levels) {
    if (l.targetPct < 99.0) EXPECT_TRUE(l.pass) << l.targetPct;
    if (l.minimumTargetPct > 101.0 || l.targetPct > 101.0) EXPECT_FALSE(l.pass) << l.targetPct;
  }
}

TEST_F(ComplianceStudy, LeedOption1ScoresTheStudysSda) {
  const ComplianceReport& e = entry(1);
  ASSERT_TRUE(e.leed);
  const AnnualGridReport& a = *result_->data.grids.at(0).annual;
  EXPECT_DOUBLE_EQ(e.leed->averagePct, a.summary.sDA300_50);
  EXPECT_DOUBLE_EQ(e.leed->spaces.at(0).areaM2, 9.0);  // 9 sensors of 1 m²
  // Every sensor reaches 300 lx in 10 of its 12 daylight hours, whatever the occupancy: sDA 100 %,
  // three points; no sun, so no ASE.
  EXPECT_DOUBLE_EQ(a.summary.sDA300_50, 100.0);
  EXPECT_EQ(e.leed->points, 3);
  EXPECT_FALSE(e.leed->aseExceeds10Percent);
  EXPECT_EQ(e.verdict, "pass");
}


// A 4 m × 4 m × 3 m grey room with a south window (glass, 3 m × 1.6 m) under the synthetic
// Golden year, one glare view at the room's middle facing the window.
const char* kWindowRoom = R"(void plastic grey
0
0
5 0.5 0.5 0.5 0 0
void glass pane
0
0
3 0.88 0.88 0.88
grey polygon floor
0
0
12 0 0 0  0 4 0  4 4 0  4 0 0
grey polygon ceiling
0
0
12 0 0 3  4 0 3  4 4 3  0 4 3
grey polygon north
0
0
12 0 4 0  0 4 3  4 4 3  4 4 0
grey polygon west
0
0
12 0 0 0  0 0 3  0 4 3  0 4 0
grey polygon east
0
0
12 4 0 0  4 4 0  4 4 3  4 0 3
grey polygon sill
0
0
12 0 0 0  4 0 0  4 0 0.8  0 0 0.8
grey polygon head
0
0
12 0 0 2.4  4 0 2.4  4 0 3  0 0 3
grey polygon jamb_west
0
0
12 0 0 0.8  0.5 0 0.8  0.5 0 2.4  0 0 2.4
grey polygon jamb_east
0
0
12 3.5 0 0.8  4 0 0.8  4 0 2.4  3.5 0 2.4
pane polygon window
0
0
12 0.5 0 0.8  3.5 0 0.8  3.5 0 2.4  0.5 0 2.4
)";

RunResult runWindowRoom(const fs::path& dir, bool blinds) {
  fs::create_directories(dir);
  std::ofstream(dir / "room.rad") << kWindowRoom;
  std::ofstream(dir / "case.toml")
      << "[[scene]]\nfile = \"room.rad\"\n[sky]\ntype = \"annual\"\nweather = \"" << CANDELA_TEST_DATA
      << "/epw/synthetic_golden_2026.epw\"\n[annual]\nblinds = " << (blinds ? "true" : "false")
      << "\n[[grid]]\nname = \"floor\"\ncorners = [[0.2, 0.2], [3.8, 3.8]]\nheight = 0.8\nspacing = 0.6\n"
         "[[compliance]]\nstandard = \"en17037\"\n[[compliance.glare_views]]\nposition = [2.0, 2.5, 1.2]\n"
         "direction = [0.0, -1.0, 0.0]\ncheck_hours = [\"2026-01-15T11:00\"]\ncheck_resolution = 64\n"
         "[settings]\nquality = \"draft\"\n";
  return runCaseIn(dir);
}

// The glare view follows the space's LM-83 blinds: closed in exactly the occupied hours the
// space's direct sun closes them (recomputed here from the study's own direct-sun file), and the
// rendered check hour is rendered in that hour's state.
TEST(ComplianceGlare, ViewsFollowTheSpacesBlinds) {
  const fs::path dir = scratchDir("compliance_glare", std::to_string(::getpid()));
  const RunResult shaded = runWindowRoom(dir / "blinds", true);
  const RunResult open = runWindowRoom(dir / "open", false);
  const AnnualResults sun = readAnnualResults(dir / "blinds" / "out" / "floor_direct_sun_hourly.f32");
  std::vector<char> occupied(sun.hours.size(), 0);
  int checkHour = -1;
  for (std::size_t h = 0; h < sun.hours.size(); ++h) {
    occupied[h] = sun.hours[h].hourEnding >= 9 && sun.hours[h].hourEnding <= 18;  // middles in [08:00, 18:00)
    if (sun.hours[h].month == 1 && sun.hours[h].day == 15 && sun.hours[h].hourEnding == 12) checkHour = static_cast<int>(h);
  }
  const std::vector<char> closed = blindsClosedHours(sun.lux.data(), sun.sensors, sun.hourCount(), occupied);
  int closedOccupied = 0;
  for (std::size_t h = 0; h < closed.size(); ++h) closedOccupied += closed[h] && occupied[h];
  ASSERT_GT(closedOccupied, 100);  // a south window in Golden: the blinds close often
  const GlareViewReport& withBlinds = shaded.data.compliance.at(0).en17037->glare.at(0);
  const GlareViewReport& without = open.data.compliance.at(0).en17037->glare.at(0);
  EXPECT_EQ(withBlinds.blinds, "lm83");
  EXPECT_EQ(withBlinds.blindsSpace, "floor");
  EXPECT_EQ(withBlinds.blindsClosedHours, closedOccupied);
  EXPECT_EQ(without.blinds, "open");
  EXPECT_EQ(without.blindsClosedHours, 0);
  ASSERT_GE(checkHour, 0);
  ASSERT_EQ(withBlinds.checks.size(), 1u);
  EXPECT_EQ(withBlinds.checks[0].blindsClosed, static_cast<bool>(closed[static_cast<std::size_t>(checkHour)]));
  EXPECT_FALSE(without.checks.at(0).blindsClosed);
  // Closed blinds pass no beam and show no sky: the view's glare can only drop, and it does, as
  // the sun stands in front of this view in the hours that close them.
  EXPECT_LE(withBlinds.shareAbove035, without.shareAbove035);
  EXPECT_LT(withBlinds.shareAbove045, without.shareAbove045);
  std::error_code ec;
  fs::remove_all(dir, ec);
}

}  // namespace
}  // namespace candela

namespace candela {
namespace {

// LEED option 2's sky: the weather year's mean at the instant over the days within 15 days of the
// equinox, recomputed here by calendar dates (6 March to 5 April, 6 September to 6 October) and
// the records' middles.
TEST(LeedOption2Sky, MeansOverTheEquinoxWindow) {
  const EpwFile w = readEpw(std::string(CANDELA_TEST_DATA) + "/epw/synthetic_golden_2026.epw");
  CaseFile c;
  const AnnualSky sky = makeAnnualSky(w, caseSite(c, &w.location), AnnualSkyOptions{});
  const auto inWindow = [](const AnnualHour& h, int month) {
    if (month == 3) return (h.month == 3 && h.day >= 6) || (h.month == 4 && h.day <= 5);
    return (h.month == 9 && h.day >= 6) || (h.month == 10 && h.day <= 6);
  };
  for (const auto& [month, hour] : {std::pair{3, 9.0}, std::pair{9, 15.5}}) {
    double diffuse = 0.0, direct = 0.0;
    int days = 0;
    for (const AnnualHour& h : sky.hours) {
      if (!inWindow(h, month)) continue;
      // 9:00 lies halfway between the middles of the hours ending 9:00 and 10:00; 15:30 is the
      // middle of the hour ending 16:00.
      const double weight = hour == 9.0 ? (h.hour == 9 || h.hour == 10 ? 0.5 : 0.0) : (h.hour == 16 ? 1.0 : 0.0);
      diffuse += weight * h.diffuseHorizontalLux;
      direct += weight * h.directNormalLux;
      days += h.hour == (hour == 9.0 ? 10 : 16);
    }
    const EquinoxLight l = equinoxWindowLight(sky, {2026, month, month == 3 ? 30 : 12}, hour);
    EXPECT_EQ(l.days, 31);
    EXPECT_EQ(days, 31);
    EXPECT_NEAR(l.diffuseHorizontalLux, diffuse / days, 1e-9 * diffuse);
    EXPECT_NEAR(l.directNormalLux, direct / days, 1e-9 * direct);
    EXPECT_GT(l.directNormalLux, 1000.0);  // a sunny climate: the sun is in it
  }
}

// Option 2 through the whole study. Three spaces far apart: an open plane, a plane under a
// tinted lid and one under an opaque lid, each inside black walls that end 5 cm above it. The
// open plane's mean illuminance is the sky's diffuse plus the sun's direct illuminance on the
// plane, from the sun's altitude by the NREL SPA at the site and time (within 4 standard errors);
// it is far above 3000 lx, the tinted plane between 300 and 3000 lx, the dark one at 0: shares
// 0, 100 and 0 % of areas 9, 9 and 18 m², so 25 % of the area, no point.
TEST(LeedOption2, OpenTintedAndDarkSpaces) {
  const fs::path dir = scratchDir("leed_option2", std::to_string(::getpid()));
  std::ostringstream rad;
  rad << "void plastic black\n0\n0\n5 0 0 0 0 0\nvoid glass tinted\n0\n0\n3 0.03 0.03 0.03\n";
  const auto box = [&rad](const std::string& name, double x0, double x1, const std::string& lid) {
    const double y0 = 0.0, y1 = 3.0, h = 0.85;
    const auto poly = [&rad](const std::string& m, const std::string& n, std::vector<Vec3> p) {
      rad << m << " polygon " << n << "\n0\n0\n" << 3 * p.size();
      for (const Vec3& v : p) rad << "  " << v.x << " " << v.y << " " << v.z;
      rad << "\n";
    };
    poly("black", name + "_s", {{x0, y0, 0}, {x1, y0, 0}, {x1, y0, h}, {x0, y0, h}});
    poly("black", name + "_n", {{x0, y1, 0}, {x0, y1, h}, {x1, y1, h}, {x1, y1, 0}});
    poly("black", name + "_w", {{x0, y0, 0}, {x0, y0, h}, {x0, y1, h}, {x0, y1, 0}});
    poly("black", name + "_e", {{x1, y0, 0}, {x1, y1, 0}, {x1, y1, h}, {x1, y0, h}});
    poly(lid, name + "_lid", {{x0, y0, h}, {x1, y0, h}, {x1, y1, h}, {x0, y1, h}});
  };
  box("a", 0, 3, "tinted");
  box("b", 4, 10, "black");
  // A speck on the ground far east so that the open plane lies within the scene's bounds.
  rad << "black polygon speck\n0\n0\n12 43 3 0  43.1 3 0  43.1 3.1 0  43 3.1 0\n";
  std::ofstream(dir / "boxes.rad") << rad.str();
  std::ofstream(dir / "case.toml")
      << "[[scene]]\nfile = \"boxes.rad\"\n[sky]\ntype = \"annual\"\nweather = \"" << CANDELA_TEST_DATA
      << "/epw/synthetic_golden_2026.epw\"\n[annual]\nblinds = false\n"
         "[[grid]]\nname = \"tinted\"\ncorners = [[0, 0], [3, 3]]\nheight = 0.8\nspacing = 1\n"
         "[[grid]]\nname = \"dark\"\ncorners = [[4, 0], [10, 3]]\nheight = 0.8\nspacing = 1\n"
         "[[grid]]\nname = \"open\"\ncorners = [[40, 0], [43, 3]]\nheight = 0.8\nspacing = 1\n"
         "[[compliance]]\nstandard = \"leed-v4.1-option2\"\n[settings]\nquality = \"draft\"\n";
  const RunResult r = runCaseIn(dir);
  const LeedReport& l = *r.data.compliance.at(0).leed;
  ASSERT_EQ(l.times.size(), 4u);
  ASSERT_EQ(l.skyByTime.size(), 4u);
  ASSERT_EQ(l.spaces.size(), 3u);
  const EpwFile w = readEpw(std::string(CANDELA_TEST_DATA) + "/epw/synthetic_golden_2026.epw");
  for (std::size_t t = 0; t < 4; ++t) {
    SpaInput in;
    in.year = 2026;
    in.month = t < 2 ? 3 : 9;
    in.day = 21;
    in.hourOfDay = t % 2 == 0 ? 9.0 : 15.0;
    in.timezoneHours = w.location.timezoneHours;
    in.latitudeDeg = w.location.latitudeDeg;
    in.longitudeDeg = w.location.longitudeDeg;
    in.elevationM = w.location.elevationM;
    in.deltaTSec = estimateDeltaTSec(2026.5);
    const double altitude = computeSunPosition(in).altitudeDeg * kPi / 180.0;
    // The sun disc's horizontal illuminance (engine/daylight.cpp's cap formula, 1 − 1.1e-5 of E_n sin a).
    const double expected = l.skyByTime[t].diffuseHorizontalLux +
                            l.skyByTime[t].directNormalLux * std::sin(altitude) * (1.0 + std::cos(0.267 * kPi / 180.0)) / 2.0;
    const LeedSpaceReport& open = l.spaces[2];
    EXPECT_NEAR(open.meanLuxByTime.at(t), expected, 4.0 * open.meanLuxByTimeStandardError.at(t) + 1e-6 * expected)
        << l.times[t];
    EXPECT_GT(expected, 3000.0 * 1.5);
    EXPECT_DOUBLE_EQ(open.inRangeByTimePct.at(t), 0.0);
    const LeedSpaceReport& tinted = l.spaces[0];
    EXPECT_GT(tinted.meanLuxByTime.at(t), 300.0 * 1.5) << l.times[t];
    EXPECT_LT(tinted.meanLuxByTime.at(t), 3000.0 / 1.5) << l.times[t];
    EXPECT_DOUBLE_EQ(tinted.inRangeByTimePct.at(t), 100.0);
    EXPECT_DOUBLE_EQ(l.spaces[1].meanLuxByTime.at(t), 0.0);
    EXPECT_DOUBLE_EQ(l.spaces[1].inRangeByTimePct.at(t), 0.0);
  }
  EXPECT_DOUBLE_EQ(l.spaces[0].areaM2, 9.0);
  EXPECT_DOUBLE_EQ(l.spaces[1].areaM2, 18.0);
  EXPECT_NEAR(l.averagePct, 25.0, 1e-9);
  EXPECT_EQ(l.points, 0);
  EXPECT_FALSE(l.eachSpaceAbove55);
  std::error_code ec;
  fs::remove_all(dir, ec);
}

TEST(LeedOption2Points, AtLeastEachShareOfTheArea) {
  EXPECT_EQ(leedOption2Points(54.99), 0);
  EXPECT_EQ(leedOption2Points(55.0), 1);
  EXPECT_EQ(leedOption2Points(74.99), 1);
  EXPECT_EQ(leedOption2Points(75.0), 2);
  EXPECT_EQ(leedOption2Points(90.0), 3);
  EXPECT_EQ(leedOption2Points(100.0), 3);
}

}  // namespace
}  // namespace candela
