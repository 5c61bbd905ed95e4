#include "metrics/en17037_view_sunlight.h"

#include <cmath>
#include <stdexcept>

namespace candela {

std::string viewLayersName(uint8_t layers) {
  std::string s;
  auto add = [&](ViewLayer bit, const char* name) {
    if (!(layers & bit)) return;
    if (!s.empty()) s += '+';
    s += name;
  };
  add(kLayerSky, "sky");
  add(kLayerLandscape, "landscape");
  add(kLayerGround, "ground");
  return s.empty() ? "none" : s;
}

En17037Level viewSightAngleLevel(double sightAngleDeg) {
  return levelFromThresholds(sightAngleDeg, kViewSightAngleDeg[0], kViewSightAngleDeg[1], kViewSightAngleDeg[2]);
}

En17037Level viewDistanceLevel(double distanceM) {
  return levelFromThresholds(distanceM, kViewOutsideDistanceM[0], kViewOutsideDistanceM[1],
                             kViewOutsideDistanceM[2]);
}

En17037Level viewLayersLevel(uint8_t layers) {
  if (!(layers & kLayerLandscape)) return En17037Level::kNone;
  const int others = ((layers & kLayerSky) ? 1 : 0) + ((layers & kLayerGround) ? 1 : 0);
  return others == 2 ? En17037Level::kHigh : others == 1 ? En17037Level::kMedium : En17037Level::kMinimum;
}

En17037Level viewOutLevel(double sightAngleDeg, double distanceM, uint8_t layers) {
  return lowerLevel(lowerLevel(viewSightAngleLevel(sightAngleDeg), viewDistanceLevel(distanceM)),
                    viewLayersLevel(layers));
}

En17037Level sunlightExposureLevel(double hours) {
  return levelFromThresholds(hours, kSunlightHours[0], kSunlightHours[1], kSunlightHours[2]);
}

double en17037MinSunAltitudeDeg(double latitudeDeg) {
  if (!(std::abs(latitudeDeg) <= 90.0)) throw std::invalid_argument("latitude must be in [-90, 90] degrees");
  return kSunlightMinAltitudeFallbackDeg;
}

}  // namespace candela
