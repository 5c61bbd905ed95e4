// `points` through the study layer: the case's [settings] apply (method included) and the
// caller's overrides win over them.
#include "study/points_study.h"

#include "study/grids/sensor_grid.h"
#include "engine/irradiance_estimator.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace candela {
namespace {

namespace fs = std::filesystem;

const fs::path kCacheCase = fs::path(CANDELA_TEST_DATA) / "study" / "cache_method.toml";

std::vector<SensorPoint> deskPoints() {
  return readPointsFile(fs::path(CANDELA_TEST_DATA) / ".." / ".." / "cases" / "small-room" / "sensors.pts").points;
}

std::vector<double> lux(const PointsJob& job) {
  const PointsScene scene = loadPointsScene(job);
  std::vector<double> out;
  for (const IrradianceEstimate& e : computePoints(scene, job.accelerator, deskPoints()).estimates)
    out.push_back(e.illuminanceLux());
  return out;
}

TEST(PointsStudy, CaseMethodIsHonoured) {
  PointsJob job;
  job.caseFile = kCacheCase;
  EXPECT_EQ(loadPointsScene(job).trace.settings.method, Method::kCache);
  PointsJob cache = job, path = job;
  cache.trace.method = Method::kCache;
  path.trace.method = Method::kPath;
  EXPECT_EQ(loadPointsScene(path).trace.settings.method, Method::kPath);
  const std::vector<double> fromCase = lux(job), withCache = lux(cache), withPath = lux(path);
  ASSERT_EQ(fromCase.size(), 5u);
  EXPECT_EQ(fromCase, withCache);
  // The two methods draw different random numbers: equal values would mean the case's method
  // was ignored in favour of the path tracer.
  EXPECT_NE(fromCase, withPath);
}

TEST(PointsStudy, WithoutACasePointsArePathTracedAtTheNormalPreset) {
  const PointsScene s = loadPointsScene(PointsJob{});
  EXPECT_EQ(s.trace.settings.method, Method::kPath);
  EXPECT_EQ(s.trace.quality, Quality::kNormal);
  EXPECT_EQ(s.trace.settings.hemisphereSamples, settingsForQuality(Quality::kNormal).hemisphereSamples);
}

}  // namespace
}  // namespace candela
