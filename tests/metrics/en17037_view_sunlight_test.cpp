#include "metrics/en17037_view_sunlight.h"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

namespace candela {
namespace {

using L = En17037Level;

TEST(En17037ViewSunlightTest, SunlightHoursThresholds) {
  EXPECT_EQ(sunlightExposureLevel(0.0), L::kNone);
  EXPECT_EQ(sunlightExposureLevel(1.49), L::kNone);
  EXPECT_EQ(sunlightExposureLevel(1.5), L::kMinimum);
  EXPECT_EQ(sunlightExposureLevel(2.99), L::kMinimum);
  EXPECT_EQ(sunlightExposureLevel(3.0), L::kMedium);
  EXPECT_EQ(sunlightExposureLevel(3.99), L::kMedium);
  EXPECT_EQ(sunlightExposureLevel(4.0), L::kHigh);
  EXPECT_EQ(sunlightExposureLevel(11.0), L::kHigh);
}

TEST(En17037ViewSunlightTest, SightAngleAndDistanceThresholds) {
  EXPECT_EQ(viewSightAngleLevel(13.99), L::kNone);
  EXPECT_EQ(viewSightAngleLevel(14.0), L::kMinimum);
  EXPECT_EQ(viewSightAngleLevel(28.0), L::kMedium);
  EXPECT_EQ(viewSightAngleLevel(53.99), L::kMedium);
  EXPECT_EQ(viewSightAngleLevel(54.0), L::kHigh);
  EXPECT_EQ(viewDistanceLevel(0.0), L::kNone);
  EXPECT_EQ(viewDistanceLevel(5.99), L::kNone);
  EXPECT_EQ(viewDistanceLevel(6.0), L::kMinimum);
  EXPECT_EQ(viewDistanceLevel(20.0), L::kMedium);
  EXPECT_EQ(viewDistanceLevel(49.9), L::kMedium);
  EXPECT_EQ(viewDistanceLevel(50.0), L::kHigh);
  EXPECT_EQ(viewDistanceLevel(std::numeric_limits<double>::infinity()), L::kHigh);
}

TEST(En17037ViewSunlightTest, LayersNeedTheLandscape) {
  EXPECT_EQ(viewLayersLevel(0), L::kNone);
  EXPECT_EQ(viewLayersLevel(kLayerSky | kLayerGround), L::kNone);
  EXPECT_EQ(viewLayersLevel(kLayerLandscape), L::kMinimum);
  EXPECT_EQ(viewLayersLevel(kLayerLandscape | kLayerSky), L::kMedium);
  EXPECT_EQ(viewLayersLevel(kLayerLandscape | kLayerGround), L::kMedium);
  EXPECT_EQ(viewLayersLevel(kLayerLandscape | kLayerSky | kLayerGround), L::kHigh);
  EXPECT_EQ(viewLayersName(kLayerGround | kLayerSky), "sky+ground");
  EXPECT_EQ(viewLayersName(0), "none");
}

TEST(En17037ViewSunlightTest, ViewOutIsTheLowestCriterion) {
  const uint8_t all = kLayerSky | kLayerLandscape | kLayerGround;
  EXPECT_EQ(viewOutLevel(60.0, 100.0, all), L::kHigh);
  EXPECT_EQ(viewOutLevel(30.0, 100.0, all), L::kMedium);
  EXPECT_EQ(viewOutLevel(60.0, 10.0, all), L::kMinimum);
  EXPECT_EQ(viewOutLevel(60.0, 100.0, kLayerSky), L::kNone);
}

TEST(En17037ViewSunlightTest, MinimumSunAltitudeFallback) {
  EXPECT_EQ(en17037MinSunAltitudeDeg(52.5), kSunlightMinAltitudeFallbackDeg);
  EXPECT_EQ(en17037MinSunAltitudeDeg(-33.9), kSunlightMinAltitudeFallbackDeg);
  EXPECT_THROW(en17037MinSunAltitudeDeg(91.0), std::invalid_argument);
}

}  // namespace
}  // namespace candela
