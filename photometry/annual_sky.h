// Hourly sky vectors for climate-based (annual) daylight: for every record of an EPW weather file,
// the mean Perez all-weather sky luminance of each Tregenza/Reinhart patch (photometry/
// sky_patches.h), plus the sun's position and the Perez direct/diffuse illuminances. Multiplied
// by daylight coefficients (illuminance per unit patch luminance) they give hourly illuminance,
// like Radiance's gendaymtx (sky only, no sun in the patches: the sun is a separate source).
//
// Each hour is built as engine/daylight.cpp builds a point-in-time Perez sky from an EPW hour:
//  - the sun position by the NREL SPA at the middle of the hour-ending record (hour - 0.5, local
//    standard time at site.timezoneHours), refraction included;
//  - PerezSky with the record's direct normal and diffuse horizontal irradiance, the sun
//    direction clamped to the horizon (altitude max(0, h)), the default precipitable water
//    W = 2 cm (no dew point, like daylight.cpp; gendaymtx's default dew point 11 C gives the same
//    W), scaled so that the sky's horizontal illuminance equals the Perez diffuse illuminance;
//  - the ground (patch 0) glows with rho_g x E_global / pi, where E_global is the sky's horizontal
//    illuminance plus that of the 0.533 deg sun disc (daylight.cpp's cap formula).
// Twilight (sun centre below the horizon, diffuse irradiance > 0): like PerezSky and gendaymtx,
// the sky is evaluated with the sun on the horizon at its azimuth and no direct component; the
// diffuse light is kept. See docs/annual-sky.md.
#pragma once

#include "base/math.h"
#include "photometry/epw.h"
#include "photometry/site.h"
#include "photometry/sky_model.h"

#include <vector>

namespace candela {

struct AnnualHour {
  int month = 1, day = 1, hour = 1;  // EPW hour-ending 1..24, local standard time
  int dayOfYear = 1;
  bool sunUp = false;                // sun centre above the horizon at mid-hour
  Vec3 sunDirTrue{0, 0, 1};          // unit, true frame (+X east, +Y true north, +Z up), at mid-hour
                                     // (hour - 0.5); below the horizon when !sunUp
  double sunAltitudeDeg = 0, sunAzimuthDeg = 0;  // SPA topocentric, refraction included
  double directNormalLux = 0;        // Perez 1990 direct efficacy x DNI; 0 when the sun is down
  double diffuseHorizontalLux = 0;   // Perez diffuse efficacy x DHI
  // diffuse + direct x sin(altitude) x (1 + cos(0.267 deg)) / 2: the sun disc's exact horizontal
  // illuminance as engine/daylight.cpp computes it (the factor is 1 - 1.1e-5).
  double globalHorizontalLux = 0;
  int sunPatch = -1;                 // SkyPatches index containing the sun (-1 when down)
};

struct AnnualSky {
  int subdivision = 1;               // Reinhart MF
  int patchCount = 0;                // SkyPatches(n).count(), incl. ground patch 0
  std::vector<AnnualHour> hours;     // one per EPW record, in file order
  // Mean luminance of each patch over each hour, cd/m2, hour-major: luminance[h * patchCount + p].
  // Sky only (the sun's disc is not in it); patch 0 is the ground glow.
  std::vector<float> luminance;
  // Missing (NaN) or negative direct normal / diffuse horizontal irradiances replaced by 0: the
  // number of such values and of the records that had at least one.
  int missingValues = 0;
  int missingHours = 0;
  // Hours with diffuse light whose Perez shape is <= 0 in every direction (e.g. a < -1 with
  // b >= 0, outside the model's fitted range): PerezSky gives them a black sky (scale 0) and so
  // does this; their diffuseHorizontalLux is still the Perez value but not in the patches, and
  // globalHorizontalLux / the ground count the sun only, as in engine/daylight.cpp.
  int degenerateHours = 0;

  float at(int hour, int patch) const { return luminance[size_t(hour) * patchCount + patch]; }
};

struct AnnualSkyOptions {
  int subdivision = 1;               // Reinhart MF >= 1 (1 = Tregenza's 145 sky patches)
  double groundReflectance = 0.2;    // rho_g in [0, 1]
  int subSamples = 4;                // Gauss-Legendre points per side per patch for the patch mean
  int threads = 0;                   // threads for the hours (0 = all cores); results do not depend on it
};

// site gives latitude/longitude/elevation/timezone (true frame; the model's north rotation is the
// engine's business). EPW hours are read as local standard time at site.timezoneHours; the
// record's own year is used for the sun position. Throws InputError (at the EPW record's line)
// for bad options or a record the sun position algorithm rejects. Deterministic; hours are
// computed in parallel.
AnnualSky makeAnnualSky(const EpwFile& epw, const Site& site, const AnnualSkyOptions& options);

// Relative horizontal illuminance of a Perez shape: the integral over the sky hemisphere of
// sky.relativeLuminance(d) * d.z d(omega), by Gauss-Legendre in sun-centred polar coordinates
// (angle from the sun gamma, and the angle around it), where the circumsolar term exp(d gamma) is
// smooth and the horizon cut is found in closed form. `sunDirTrue` must be the sky's (clamped,
// z >= 0) sun direction. About 2 000 evaluations instead of SkyModel::calibrate's ~100 000;
// agrees with it to ~1e-7 (tests/photometry/annual_sky_test.cpp).
double perezRelativeHorizontal(const SkyModel& sky, const Vec3& sunDirTrue);

// Mean luminance (cd/m2) of `sky` over each patch of SkyPatches(subdivision), by the quadrature
// the hourly sky vectors use (`subSamples` Gauss-Legendre points per side); index 0, the ground,
// is ρ_g E_h / π with E_h the sky's own horizontal illuminance (a daylight factor's overcast sky,
// compliance studies). One value per patch.
std::vector<float> patchMeanLuminance(const SkyModel& sky, int subdivision, double groundReflectance,
                                      int subSamples = 4);

}  // namespace candela
