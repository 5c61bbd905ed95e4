// Daylight coefficients (engine/daylight_coefficients.h) against independent numbers:
//  - the tally is the point-study estimator itself: with the same seed and settings, Σ DC·L over
//    the patches of a uniform sky and ground reproduces estimateIrradiance to rounding;
//  - an open sensor's coefficients against the closed-form projected solid angles of the bands;
//  - the site's north rotation puts a north-facing window's light into northern patches;
//  - the acceptance check of docs/annual.md: for a few hours of a year, the daylight-coefficient
//    illuminance in a side-lit room matches a point-in-time run of the same Perez sky (and sun)
//    within 3 %.
#include "engine/daylight.h"
#include "engine/daylight_coefficients.h"
#include "engine/radiance/reader.h"
#include "engine/tracer.h"
#include "photometry/annual_sky.h"
#include "photometry/epw.h"
#include "photometry/site.h"
#include "photometry/make_sky.h"
#include "engine/irradiance_estimator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace candela {
namespace {

// A 4 m × 4 m × 3 m room (x east, y north) with a 2.4 m × 1.4 m glazed opening in its south wall
// (y = 0, sill 0.8 m), on an open ground. Room surfaces face inwards.
const char* kRoom = R"(
void plastic wall 0 0 5 0.6 0.6 0.6 0 0
void plastic floor_mat 0 0 5 0.25 0.25 0.25 0 0
void plastic ceiling_mat 0 0 5 0.8 0.8 0.8 0 0
void glass pane 0 0 3 0.9 0.9 0.9
floor_mat polygon floor 0 0 12  0 0 0  0 4 0  4 4 0  4 0 0
ceiling_mat polygon ceiling 0 0 12  0 0 3  4 0 3  4 4 3  0 4 3
wall polygon north 0 0 12  0 4 0  0 4 3  4 4 3  4 4 0
wall polygon west 0 0 12  0 0 0  0 0 3  0 4 3  0 4 0
wall polygon east 0 0 12  4 0 0  4 4 0  4 4 3  4 0 3
wall polygon south_low 0 0 12  0 0 0  4 0 0  4 0 0.8  0 0 0.8
wall polygon south_high 0 0 12  0 0 2.2  4 0 2.2  4 0 3  0 0 3
wall polygon south_left 0 0 12  0 0 0.8  0.8 0 0.8  0.8 0 2.2  0 0 2.2
wall polygon south_right 0 0 12  3.2 0 0.8  4 0 0.8  4 0 2.2  3.2 0 2.2
pane polygon window 0 0 12  0.8 0 0.8  3.2 0 0.8  3.2 0 2.2  0.8 0 2.2
)";

void addRoom(Scene& scene) { readRadianceText(kRoom, "room.rad", scene); }

SkyDome uniformDome(double luminanceCdM2, double groundCdM2, double northDeg) {
  SkyConditions c;
  c.diffuseHorizontalLux = kPi * luminanceCdM2;
  SkyDome d;
  d.model = makeSky({SkyKind::kUniform}, c);
  d.northDeg = northDeg;
  d.groundLuminanceCdM2 = groundCdM2;
  d.horizontalSkyLux = c.diffuseHorizontalLux;
  return d;
}

TraceSettings plainSettings(int hemisphere, int light) {
  TraceSettings s;
  s.hemisphereSamples = hemisphere;
  s.lightSamples = light;
  s.maxBounces = kUnlimitedBounces;
  s.method = Method::kPath;
  s.adaptiveFraction = 0.0;
  s.seed = 7;
  return s;
}

TEST(DaylightCoefficients, TallyIsThePointEstimatorItself) {
  // Same seed, same settings, same sampling (the sky model only guides it): the coefficients
  // weighted by the patch luminances must give the point estimate's illuminance to rounding,
  // which checks every factor the tally carries (splits, albedo roulette, glass, MIS weights).
  Scene scene;
  addRoom(scene);
  const double sky = 3000.0, ground = 1700.0;  // cd/m²
  scene.sky = uniformDome(sky, ground, 25.0);
  const Tracer tracer(scene);
  const SkyPatches patches(1);
  const TraceSettings s = plainSettings(512, 32);
  const std::vector<std::pair<Vec3, Vec3>> sensors = {
      {{2.0, 1.0, 0.8}, {0, 0, 1}}, {{1.0, 3.0, 0.8}, {0, 0, 1}}, {{2.0, 2.0, 1.5}, {0, -1, 0}}};
  for (size_t i = 0; i < sensors.size(); ++i) {
    const auto& [p, n] = sensors[i];
    const double pointLux = estimateIrradiance(tracer, p, n, i, s).illuminanceLux();
    std::vector<double> direct(patches.count(), 0.0), indirect(patches.count(), 0.0);
    skyCoefficients(tracer, p, n, i, s, patches, direct.data(), indirect.data(), false);
    double dcLux = 0.0, directLux = 0.0;
    for (int b = 0; b < patches.count(); ++b) {
      const double l = b == 0 ? ground : sky;
      dcLux += (direct[b] + indirect[b]) * l;
      directLux += direct[b] * l;
    }
    std::printf("[ measured ] sensor %zu: point %.6f lx, coefficients %.6f lx (direct %.3f lx)\n", i, pointLux, dcLux,
                directLux);
    EXPECT_GT(pointLux, 0.0);
    EXPECT_NEAR(dcLux, pointLux, 1e-9 * pointLux) << "sensor " << i;
    EXPECT_GT(directLux, 0.0);
    EXPECT_LT(directLux, dcLux);
  }
}

TEST(DaylightCoefficients, OpenSensorSeesTheProjectedSolidAngleOfEachBand) {
  // Nothing but sky: a horizontal sensor's coefficients are all direct, and a band of altitude
  // [a1, a2] has ∫cos θ dω = π (sin² a2 − sin² a1) (lux per cd/m²).
  Scene scene;
  scene.sky = uniformDome(1000.0, 0.0, 0.0);
  const Tracer tracer(scene);
  const SkyPatches patches(1);
  const TraceSettings s = plainSettings(65536, 4096);
  std::vector<double> direct(patches.count(), 0.0), indirect(patches.count(), 0.0);
  skyCoefficients(tracer, Vec3(0.0), Vec3(0, 0, 1), 0, s, patches, direct.data(), indirect.data());
  double total = 0.0;
  for (double v : indirect) EXPECT_EQ(v, 0.0);
  for (double v : direct) total += v;
  EXPECT_NEAR(total, kPi, 0.01 * kPi);
  EXPECT_NEAR(direct[0], 0.0, 1e-12);  // the ground is below a sensor facing up
  // Bands of 12° (Tregenza), summed over their patches.
  const double alpha = patches.rowHeightRad();
  const int counts[7] = {30, 30, 24, 24, 18, 12, 6};
  int index = 1;
  for (int row = 0; row < 7; ++row) {
    double sum = 0.0;
    for (int k = 0; k < counts[row]; ++k) sum += direct[index++];
    const double a1 = row * alpha, a2 = (row + 1) * alpha;
    const double want = kPi * (std::sin(a2) * std::sin(a2) - std::sin(a1) * std::sin(a1));
    // ~65 k cosine rays and 4 k sky samples: a band's share is known to ~1 % (binomial).
    EXPECT_NEAR(sum, want, 0.03 * want + 0.003) << "row " << row;
  }
}

TEST(DaylightCoefficients, NorthRotationPutsNorthLightInNorthernPatches) {
  // A vertical sensor facing model +X, with true north 90° clockwise from model +Y (i.e. along
  // model +X): its direct light must come from patches around true azimuth 0.
  Scene scene;
  scene.sky = uniformDome(1000.0, 0.0, 90.0);
  const Tracer tracer(scene);
  const SkyPatches patches(1);
  const TraceSettings s = plainSettings(4096, 256);
  std::vector<double> direct(patches.count(), 0.0), indirect(patches.count(), 0.0);
  skyCoefficients(tracer, Vec3(0.0), Vec3(1, 0, 0), 0, s, patches, direct.data(), indirect.data());
  Vec3 mean(0.0);
  for (int b = 1; b < patches.count(); ++b) mean += direct[b] * patches.centre(b);
  // Mean direction in the true frame: towards +Y (north), up, not east or west.
  EXPECT_GT(mean.y, 0.0);
  EXPECT_NEAR(std::atan2(mean.x, mean.y) * 180.0 / kPi, 0.0, 3.0);
  // A vertical plane sees half the ground: π/2 per cd/m² of ground luminance, all direct.
  EXPECT_NEAR(direct[0], kPi / 2.0, 0.03 * kPi / 2.0);
}

// ---------------------------------------------------------------- against point-in-time runs

struct HourCase {
  int month, day, hour;  // EPW hour-ending
};

class DaylightCoefficientsVsPointInTime : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    epw_ = new EpwFile(readEpw(std::string(CANDELA_TEST_DATA) + "/epw/synthetic_golden_2026.epw"));
    site_ = new Site(makeSite(epw_->location.latitudeDeg, epw_->location.longitudeDeg, epw_->location.elevationM,
                              epw_->location.timezoneHours, 0.0));
    AnnualSkyOptions o;
    o.subdivision = 2;
    sky_ = new AnnualSky(makeAnnualSky(*epw_, *site_, o));
  }
  static void TearDownTestSuite() {
    delete sky_;
    delete site_;
    delete epw_;
  }
  static int hourIndex(const HourCase& hc) {
    for (size_t h = 0; h < sky_->hours.size(); ++h)
      if (sky_->hours[h].month == hc.month && sky_->hours[h].day == hc.day && sky_->hours[h].hour == hc.hour)
        return static_cast<int>(h);
    return -1;
  }
  static EpwFile* epw_;
  static Site* site_;
  static AnnualSky* sky_;
};
EpwFile* DaylightCoefficientsVsPointInTime::epw_ = nullptr;
Site* DaylightCoefficientsVsPointInTime::site_ = nullptr;
AnnualSky* DaylightCoefficientsVsPointInTime::sky_ = nullptr;

TEST_F(DaylightCoefficientsVsPointInTime, SkyAndSunWithinThreePercent) {
  const std::vector<Vec3> positions = {{1.2, 1.0, 0.8}, {2.0, 1.5, 0.8}, {2.8, 2.5, 0.8}, {2.0, 3.5, 0.8}};
  const std::vector<Vec3> normals(positions.size(), Vec3(0, 0, 1));
  Scene dcScene;
  addRoom(dcScene);
  dcScene.sky = uniformDome(1.0, 0.0, 0.0);
  const Tracer dcTracer(dcScene);
  const SkyPatches patches(sky_->subdivision);
  TraceSettings s = plainSettings(8192, 256);
  const DaylightCoefficients dc = computeDaylightCoefficients(dcTracer, positions, normals, patches, s, 0);
  const std::vector<float> sunCoef =
      directSunCoefficients(dcTracer, positions, normals, sunDirectionsModel(*sky_, 0.0), 16, 3, 0);
  const SunSet set = indirectSunSet(*sky_);
  std::vector<Vec3> setModel;
  for (const Vec3& d : set.dirsTrue) setModel.push_back(trueToModel(d, 0.0));
  const std::vector<float> sunIndirect =
      indirectSunCoefficients(dcTracer, positions, normals, setModel, plainSettings(4096, 16), 0);
  std::printf("[ measured ] %zu suns stand for the year's interreflected sun\n", set.dirsTrue.size());
  const AnnualIlluminance year = annualIlluminance(dc, sunCoef, sunIndirect, set, *sky_, 0);

  // Winter and equinox hours put a sun patch on the floor; a summer noon does not reach it.
  const std::vector<HourCase> hours = {{1, 15, 12}, {3, 21, 10}, {6, 21, 14}, {10, 10, 16}};
  for (const HourCase& hc : hours) {
    const int h = hourIndex(hc);
    ASSERT_GE(h, 0);
    const EpwRecord& rec = epw_->records[h];
    for (bool withSun : {false, true}) {
      Scene pit;
      addRoom(pit);
      DaylightSpec d;
      d.skyType = {SkyKind::kPerez};
      char time[40];
      std::snprintf(time, sizeof time, "2026-%02d-%02dT%02d:30", hc.month, hc.day, hc.hour - 1);
      d.time = time;
      d.latitudeDeg = site_->latitudeDeg;
      d.longitudeDeg = site_->longitudeDeg;
      d.elevationM = site_->elevationM;
      d.timezoneHours = site_->timezoneHours;
      d.directNormalWm2 = rec.directNormalWhm2;
      d.diffuseHorizontalWm2 = rec.diffuseHorizontalWhm2;
      d.sun = withSun;
      d.groundReflectance = 0.2;
      addDaylight(pit, d);
      // Without the sun, the point run's ground still glows with the sun's share: compare
      // against the coefficients with the same ground.
      const Tracer tracer(pit);
      for (size_t i = 0; i < positions.size(); ++i) {
        const IrradianceEstimate e = estimateIrradiance(tracer, positions[i], normals[i], 100 + i, s);
        double dcLux = 0.0;
        if (withSun) {
          dcLux = year.total[i * year.hours + h];
        } else {
          for (int p = 1; p < dc.patches; ++p) dcLux += dc.total[i * dc.patches + p] * sky_->at(h, p);
          dcLux += dc.total[i * dc.patches] * pit.sky->groundLuminanceCdM2;
        }
        const double pointLux = e.illuminanceLux(), se = e.standardErrorLux();
        std::printf("[ measured ] %02d-%02d h%02d %s sensor %zu: point %.1f ± %.1f lx, coefficients %.1f lx (%+.2f %%)\n",
                    hc.month, hc.day, hc.hour, withSun ? "sky+sun" : "sky    ", i, pointLux, se, dcLux,
                    100.0 * (dcLux - pointLux) / pointLux);
        ASSERT_GT(pointLux, 0.0);
        EXPECT_NEAR(dcLux, pointLux, 0.03 * pointLux + 3.0 * se)
            << hc.month << "-" << hc.day << " hour " << hc.hour << (withSun ? " sky+sun" : " sky") << " sensor " << i;
      }
    }
  }
}

}  // namespace
}  // namespace candela
