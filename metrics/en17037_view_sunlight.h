// EN 17037:2018+A1:2023, the level rules of view out (clause 5.2, Annex A's table of view) and
// of exposure to sunlight (clause 5.3): pure functions over the figures that study/view_out.h
// and study/sunlight_exposure.h compute (docs/en17037-view-sunlight.md).
//
// Thresholds as the standard's Annex A tables give them (minimum / medium / high):
//   view out: horizontal sight angle ≥ 14° / 28° / 54°, outside distance of the view
//   ≥ 6 m / 20 m / 50 m, layers seen: landscape / landscape + one of sky and ground / all three;
//   sunlight: ≥ 1.5 h / 3 h / 4 h of possible sun on a day between 1 February and 21 March.
// The sight angles and the hours were checked against public summaries: DL-Light's EN 17037
// horizontal-sight-angle page (deluminaelab.com, "EN 17037 uses 3 thresholds for the sight angle:
// 14°, 28° and 54°") and the Almond EN 17037 sunlight tool's description (glama.ai, almond-mcp
// en17037_sunlight: "Levels: >= 1.5 h minimum, 3 h medium, 4 h high", a day between 1 February
// and 21 March). The outside distances and the layer rule are the figures, not yet
// checked against the standard's text (docs/en17037-view-sunlight.md).
#pragma once

#include "metrics/compliance_levels.h"

#include <cstdint>
#include <string>

namespace candela {

// Horizontal sight angle in degrees (minimum, medium, high).
inline constexpr double kViewSightAngleDeg[3] = {14.0, 28.0, 54.0};
// Outside distance of the view in metres (minimum, medium, high).
inline constexpr double kViewOutsideDistanceM[3] = {6.0, 20.0, 50.0};
// Hours of possible sunlight on the reference day (minimum, medium, high).
inline constexpr double kSunlightHours[3] = {1.5, 3.0, 4.0};

// The layers of a view (EN 17037 Annex C: the sky, the landscape — urban or natural, up to the
// horizon — and the ground), as bits.
enum ViewLayer : uint8_t { kLayerSky = 1, kLayerLandscape = 2, kLayerGround = 4 };

// "sky+landscape+ground" style, in that order; "none" for 0.
std::string viewLayersName(uint8_t layers);

En17037Level viewSightAngleLevel(double sightAngleDeg);
// distanceM may be +infinity (nothing outside): high.
En17037Level viewDistanceLevel(double distanceM);
// Landscape alone: minimum; landscape and one other: medium; all three: high; without the
// landscape layer: none, whatever else is seen.
En17037Level viewLayersLevel(uint8_t layers);
// A point's view out reaches the lowest of its three criteria' levels.
En17037Level viewOutLevel(double sightAngleDeg, double distanceM, uint8_t layers);

En17037Level sunlightExposureLevel(double hours);

// The lower of two levels.
constexpr En17037Level lowerLevel(En17037Level a, En17037Level b) { return a < b ? a : b; }

// The minimum sun altitude (degrees) below which the sun is not counted, for a site's latitude
// (degrees, north positive). EN 17037 Annex D tabulates it by country (capital and its
// latitude); that table's figures could not be verified from public sources here, so this is a
// FALLBACK: kSunlightMinAltitudeFallbackDeg at every latitude, the figure a review of DIN EN 17037
// quotes for Germany ("Mindest-Sonnenhöhenwinkel von elf Grad", artikelschreiber.com, "Tageslicht
// in Innenräumen: die neue ..."). Cases override it with the value of their country.
// Throws std::invalid_argument outside [-90, 90].
inline constexpr double kSunlightMinAltitudeFallbackDeg = 11.0;
double en17037MinSunAltitudeDeg(double latitudeDeg);

}  // namespace candela
