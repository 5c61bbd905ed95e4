// Daylight in a scene: a sky model (photometry/), the sun as a 0.533° disk source and the ground
// below the horizon as a uniform glow, all rotated from true north into the model by the site's
// `north` (the geometry is never rotated).
#pragma once

#include "base/error.h"
#include "engine/scene.h"
#include "photometry/sky_model.h"
#include "photometry/sky_type.h"

#include <memory>
#include <optional>
#include <string>

namespace candela {

// The angular diameter of the sun's disk, degrees.
inline constexpr double kSunDiameterDeg = 0.533;

// What the command line or the case file say about the sky.
struct DaylightSpec {
  SkyType skyType;               // kNone: no daylight (kAnnual is not a point-in-time sky)
  FileLoc skyLoc;                // where the type was given (errors point here)
  // Sun position: given directly, or from site and time (NREL SPA).
  std::optional<double> sunAltitudeDeg, sunAzimuthDeg;  // azimuth clockwise from north
  std::optional<double> latitudeDeg, longitudeDeg;
  double elevationM = 0.0;
  double timezoneHours = 0.0;    // local standard time minus UTC
  std::string time;              // ISO 8601 local standard time (an offset in it wins)
  FileLoc timeLoc;
  double northDeg = 0.0;         // true north, clockwise from model +Y
  bool sun = true;               // include the sun where the sky has one
  std::optional<double> diffuseHorizontalLux;   // sky's illuminance on the open horizontal plane
  std::optional<double> directNormalLux;        // sun's direct normal illuminance
  std::optional<double> directNormalWm2, diffuseHorizontalWm2;  // Perez inputs
  double groundReflectance = 0.2;
};

// Builds the sky, adds the sun as a distant `light` source and sets scene.sky. Throws
// InputError at spec.skyLoc/timeLoc for impossible combinations (a sun position with no way to
// get it, Perez without irradiances, ...). Does nothing for SkyKind::kNone.
// A scene whose files define their own sky (gensky, gendaylit: engine/radiance/sky.h) first loses it
// and its sun, with the warning `scene_sky_replaced` at `by` (replaceSceneSky).
void addDaylight(Scene& scene, const DaylightSpec& spec);

// Removes a sky read from the scene files and its sun (Scene::distant[sky.sceneSun]) and adds the
// warning `scene_sky_replaced` at `by`, the case's sky that replaces it. Nothing for a scene
// without such a sky.
void replaceSceneSky(Scene& scene, const FileLoc& by);

}  // namespace candela
