// The annual chain on the repository's full-year weather file (tests/data/epw/
// synthetic_golden_2026.epw, SYNTHETIC: a clear-sky model with deterministic clouds): sky vectors,
// coefficients of open sensors, the hourly product and the metrics, against series computed
// independently from the same weather.
//  - An open horizontal sensor must see E_dh + E_dn sin h every hour (the patch means cost up to a
//    few % in an hour of low sun: docs/annual-sky.md), and its metrics must be those of that series.
//  - Hours and occupancy: 8760 records, 3650 occupied hours (08–18).
//  - A sensor facing down over a black ground sees nothing at all, every hour.
#include "engine/daylight_coefficients.h"
#include "engine/radiance/reader.h"
#include "metrics/annual.h"
#include "photometry/annual_sky.h"
#include "photometry/epw.h"
#include "photometry/site.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <span>
#include <cstdio>
#include <string>
#include <vector>

namespace candela {
namespace {

TEST(AnnualPipeline, OpenSensorsOverTheTestYear) {
  const EpwFile epw = readEpw(std::string(CANDELA_TEST_DATA) + "/epw/synthetic_golden_2026.epw");
  ASSERT_TRUE(epw.isFullYear());
  const Site site = makeSite(epw.location.latitudeDeg, epw.location.longitudeDeg, epw.location.elevationM,
                             epw.location.timezoneHours, 0.0);
  AnnualSkyOptions o;
  o.groundReflectance = 0.0;
  const AnnualSky sky = makeAnnualSky(epw, site, o);
  ASSERT_EQ(sky.hours.size(), 8760u);

  Scene scene;
  SkyDome dome;
  dome.model = yearSamplingGuide(sky);
  scene.sky = dome;
  const Tracer tracer(scene);
  const SkyPatches patches(sky.subdivision);
  TraceSettings s;
  s.hemisphereSamples = 256;
  s.lightSamples = 64;
  s.maxBounces = kUnlimitedBounces;
  const std::vector<Vec3> pos = {Vec3(0.0), Vec3(0.0)}, nrm = {Vec3(0, 0, 1), Vec3(0, 0, -1)};
  const DaylightCoefficients dc = computeDaylightCoefficients(tracer, pos, nrm, patches, s, 0);
  const std::vector<float> direct = directSunCoefficients(tracer, pos, nrm, sunDirectionsModel(sky, 0.0), 4, 1, 0);
  const SunSet set = indirectSunSet(sky);
  const std::vector<float> inter(pos.size() * set.dirsTrue.size(), 0.0f);
  const AnnualIlluminance year = annualIlluminance(dc, direct, inter, set, sky, 0);
  ASSERT_EQ(year.hours, 8760);

  // Hour by hour, against the weather's own horizontal illuminance (sky part: patch means;
  // direct part: exact but for the disc's 4 samples).
  std::vector<float> ref(8760), refSun(8760);
  std::vector<int> hourEnding(8760);
  double sumRef = 0.0, sumGot = 0.0, worstNoon = 0.0;
  for (int h = 0; h < 8760; ++h) {
    const AnnualHour& a = sky.hours[h];
    ref[h] = static_cast<float>(a.globalHorizontalLux);
    refSun[h] = a.sunUp ? static_cast<float>(a.directNormalLux * std::sin(degToRad(a.sunAltitudeDeg))) : 0.0f;
    hourEnding[h] = a.hour;
    sumRef += ref[h];
    sumGot += year.total[h];
    EXPECT_EQ(year.total[8760 + h], 0.0f) << "the downward sensor sees a black ground, hour " << h;
    if (a.sunAltitudeDeg > 30.0 && ref[h] > 0.0)
      worstNoon = std::max(worstNoon, std::abs(double(year.total[h]) - ref[h]) / ref[h]);
    // The direct sun: 4 rays over the disc estimate its mean cosine, which can differ from the
    // centre's by at most the disc's half-angle (0.267°) times the slope of sin h: cot h · 0.00466.
    if (a.sunUp && a.sunAltitudeDeg > 1.0)
      EXPECT_NEAR(year.directSun[h], refSun[h],
                  refSun[h] * 0.00466 / std::tan(degToRad(a.sunAltitudeDeg)) + 1e-3)
          << "hour " << h;
  }
  std::printf("[ measured ] year: %.4g vs %.4g lux·h (%+.3f %%), worst hour with the sun above 30°: %.2f %%\n", sumGot,
              sumRef, 100.0 * (sumGot - sumRef) / sumRef, 100.0 * worstNoon);
  EXPECT_NEAR(sumGot, sumRef, 0.005 * sumRef);
  EXPECT_LT(worstNoon, 0.02);

  const std::vector<char> occ = occupiedHours(hourEnding, 8.0, 18.0);
  EXPECT_EQ(countHours(occ), 3650);
  // Thresholds scaled to outdoor levels cut through the year's distribution.
  AnnualThresholds t;
  t.daLux = 20000.0;
  t.udiLowLux = 5000.0;
  t.udiHighLux = 60000.0;
  t.aseLux = 40000.0;
  const SensorAnnualMetrics want = sensorAnnualMetrics(ref.data(), refSun.data(), 1, 8760, occ, t).front();
  const SensorAnnualMetrics got = sensorAnnualMetrics(year.total.data(), year.directSun.data(), 1, 8760, occ, t).front();
  std::printf("[ measured ] DA %.3f / %.3f, cDA %.3f / %.3f, UDI-a %.3f / %.3f, ASE hours %d / %d, sun hours %d / %d\n",
              got.da, want.da, got.cda, want.cda, got.udiAutonomous, want.udiAutonomous, got.aseHours, want.aseHours,
              got.sunHours, want.sunHours);
  // An hour may land on the other side of a threshold only if its reference lies within the
  // sky's patch-mean error of it (at most 4.3 % of an hour's sky light at MF:1,
  // docs/annual-sky.md): the metrics may differ by at most the share of such hours.
  auto near = [&](double thr) {
    int n = 0;
    for (int h = 0; h < 8760; ++h) n += occ[h] && std::abs(ref[h] - thr) <= 0.045 * ref[h];
    return 100.0 * n / 3650.0;
  };
  std::printf("[ measured ] occupied hours within 4.5 %% of 5000 / 20000 / 60000 lx: %.2f / %.2f / %.2f %%\n",
              near(t.udiLowLux), near(t.daLux), near(t.udiHighLux));
  EXPECT_GT(want.da, 10.0);
  EXPECT_LT(want.da, 90.0);
  EXPECT_NEAR(got.da, want.da, near(t.daLux));
  // cDA: below the threshold each hour's credit moves with its value (≤ 4.5 %).
  EXPECT_NEAR(got.cda, want.cda, 0.045 * want.cda);
  EXPECT_NEAR(got.udiFellShort, want.udiFellShort, near(t.udiLowLux));
  EXPECT_NEAR(got.udiSupplementary, want.udiSupplementary, near(t.udiLowLux) + near(t.daLux));
  EXPECT_NEAR(got.udiAutonomous, want.udiAutonomous, near(t.daLux) + near(t.udiHighLux));
  EXPECT_NEAR(got.udiExceeded, want.udiExceeded, near(t.udiHighLux));
  // ASE looks at the direct sun alone, which the sky's patches do not touch.
  EXPECT_NEAR(got.aseHours, want.aseHours, 0.01 * want.aseHours);
  EXPECT_EQ(got.sunHours, want.sunHours);
}

}  // namespace
}  // namespace candela

namespace candela {
namespace {

// A 3 m side-lit room under the test year's sampling guide, north at 30°.
struct SideLitRoom {
  Scene scene;
  AnnualSky sky;
  SunSet set;
  std::vector<Vec3> setModel;
  std::unique_ptr<Tracer> tracer;
  SideLitRoom() {
    readRadianceText("void plastic w 0 0 5 0.5 0.5 0.5 0 0\nvoid glass g 0 0 3 0.9 0.9 0.9\n"
                     "w polygon floor 0 0 12 0 0 0 0 3 0 3 3 0 3 0 0\n"
                     "w polygon ceiling 0 0 12 0 0 2.5 3 0 2.5 3 3 2.5 0 3 2.5\n"
                     "w polygon north 0 0 12 0 3 0 0 3 2.5 3 3 2.5 3 3 0\n"
                     "w polygon west 0 0 12 0 0 0 0 0 2.5 0 3 2.5 0 3 0\n"
                     "w polygon east 0 0 12 3 0 0 3 3 0 3 3 2.5 3 0 2.5\n"
                     "w polygon south_low 0 0 12 0 0 0 3 0 0 3 0 1 0 0 1\n"
                     "g polygon pane 0 0 12 0 0 1 3 0 1 3 0 2.5 0 0 2.5\n",
                     "room.rad", scene);
    const EpwFile epw = readEpw(std::string(CANDELA_TEST_DATA) + "/epw/synthetic_golden_2026.epw");
    const Site site = makeSite(epw.location.latitudeDeg, epw.location.longitudeDeg, epw.location.elevationM,
                               epw.location.timezoneHours, 30.0);
    sky = makeAnnualSky(epw, site, AnnualSkyOptions{});
    SkyDome dome;
    dome.model = yearSamplingGuide(sky);
    dome.northDeg = 30.0;
    scene.sky = dome;
    tracer = std::make_unique<Tracer>(scene);
    set = indirectSunSet(sky);
    for (const Vec3& d : set.dirsTrue) setModel.push_back(trueToModel(d, 30.0));
  }
};

TraceSettings fewSamples() {
  TraceSettings s;
  s.hemisphereSamples = 64;
  s.lightSamples = 4;
  s.maxBounces = kUnlimitedBounces;
  return s;
}

TEST(AnnualPipeline, SameNumbersForAnyThreadCount) {
  // A side-lit room's coefficients and year, on 1 and 2 threads: identical bits.
  const SideLitRoom room;
  const Tracer& tracer = *room.tracer;
  const AnnualSky& sky = room.sky;
  const SunSet& set = room.set;
  const std::vector<Vec3>& setModel = room.setModel;
  const SkyPatches patches(sky.subdivision);
  const TraceSettings s = fewSamples();
  std::vector<Vec3> pos, nrm;
  for (int i = 0; i < 6; ++i) {
    pos.emplace_back(0.4 + 0.4 * i, 0.3 + 0.4 * i, 0.8);
    nrm.emplace_back(0, 0, 1);
  }
  auto yearOn = [&](int threads) {
    const DaylightCoefficients dc = computeDaylightCoefficients(tracer, pos, nrm, patches, s, threads);
    const std::vector<float> direct =
        directSunCoefficients(tracer, pos, nrm, sunDirectionsModel(sky, 30.0), 2, 5, threads);
    const std::vector<float> inter = indirectSunCoefficients(tracer, pos, nrm, setModel, s, threads);
    return annualIlluminance(dc, direct, inter, set, sky, threads).total;
  };
  const std::vector<float> one = yearOn(1), two = yearOn(2);
  ASSERT_EQ(one.size(), two.size());
  size_t differ = 0;
  double sum = 0.0;
  for (size_t i = 0; i < one.size(); ++i) {
    differ += one[i] != two[i];
    sum += one[i];
  }
  EXPECT_GT(sum, 0.0);
  EXPECT_EQ(differ, 0u);
}

TEST(AnnualPipeline, BlocksOfSensorsGiveTheWholeStudysFloats) {
  // 150 sensors traced whole, then as blocks of 64 from their first index (the annual study's
  // way, engine/daylight_coefficients.h SensorBlock): the same bits, coefficients and year.
  const SideLitRoom room;
  const SkyPatches patches(room.sky.subdivision);
  const TraceSettings s = fewSamples();
  const std::vector<Vec3> suns = sunDirectionsModel(room.sky, 30.0);
  std::vector<Vec3> pos, nrm;
  for (int i = 0; i < 150; ++i) {
    pos.emplace_back(0.2 + 0.2 * (i % 14), 0.2 + 0.2 * (i / 14), 0.8);
    nrm.emplace_back(0, 0, 1);
  }
  const int threads = 2;
  const DaylightCoefficients dc = computeDaylightCoefficients(*room.tracer, pos, nrm, patches, s, threads);
  const std::vector<float> direct = directSunCoefficients(*room.tracer, pos, nrm, suns, 2, 5, threads);
  const std::vector<float> inter = indirectSunCoefficients(*room.tracer, pos, nrm, room.setModel, s, threads);
  const AnnualIlluminance whole = annualIlluminance(dc, direct, inter, room.set, room.sky, threads);
  std::vector<float> dcBlocks, total, directSun;
  size_t streamsMatter = 0;
  for (size_t first = 0; first < pos.size(); first += kAnnualProductBlock) {
    const size_t n = std::min<size_t>(kAnnualProductBlock, pos.size() - first);
    const SensorBlock b{std::span(pos).subspan(first, n), std::span(nrm).subspan(first, n), first};
    const DaylightCoefficients bdc = computeDaylightCoefficients(*room.tracer, b, patches, s, threads);
    const AnnualIlluminance year =
        annualIlluminance(bdc, directSunCoefficients(*room.tracer, b, suns, 2, 5, threads),
                          indirectSunCoefficients(*room.tracer, b, room.setModel, s, threads), room.set, room.sky,
                          threads);
    dcBlocks.insert(dcBlocks.end(), bdc.total.begin(), bdc.total.end());
    total.insert(total.end(), year.total.begin(), year.total.end());
    directSun.insert(directSun.end(), year.directSun.begin(), year.directSun.end());
    // Control: the same block with the streams of sensors 0.. instead of its own differs.
    if (first > 0) {
      const SensorBlock wrong{b.positions, b.normals, 0};
      const DaylightCoefficients w = computeDaylightCoefficients(*room.tracer, wrong, patches, s, threads);
      for (size_t i = 0; i < w.total.size(); ++i) streamsMatter += w.total[i] != bdc.total[i];
    }
  }
  EXPECT_TRUE(dcBlocks == dc.total);
  EXPECT_TRUE(total == whole.total);
  EXPECT_TRUE(directSun == whole.directSun);
  EXPECT_GT(streamsMatter, 0u);
  double sum = 0.0;
  for (float v : total) sum += v;
  EXPECT_GT(sum, 0.0);
}

}  // namespace
}  // namespace candela
