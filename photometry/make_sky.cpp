#include "photometry/make_sky.h"

#include "photometry/sky_cie.h"
#include "photometry/sky_perez.h"

#include <cmath>

namespace candela {

std::unique_ptr<SkyModel> makeSky(const SkyType& type, const SkyConditions& cond, const FileLoc& loc) {
  const double sunLen = glm::length(cond.sunDirTrue);
  if (!(sunLen > 0.0) || !std::isfinite(sunLen)) throw InputError(loc, "sky: the sun direction is not a direction");
  const Vec3 sun = cond.sunDirTrue / sunLen;
  const bool needsLux = type.kind != SkyKind::kPerez;
  if (needsLux && !(cond.diffuseHorizontalLux >= 0.0 && std::isfinite(cond.diffuseHorizontalLux)))
    throw InputError(loc, "sky: diffuse_horizontal_illuminance must be >= 0 lux");
  // No sky gives more than about 1.5·10^5 lux; 10^7 leaves room for any study and keeps the
  // squares of the estimates finite (1e300 lux ended in a non-finite result, an internal error).
  if (needsLux && cond.diffuseHorizontalLux > 1e7)
    throw InputError(loc, "sky: diffuse_horizontal_illuminance must be at most 1e7 lux (skies give up to about "
                          "1.5e5), got " + compactNumber(cond.diffuseHorizontalLux));
  switch (type.kind) {
    case SkyKind::kUniform: return std::make_unique<UniformSky>(cond.diffuseHorizontalLux);
    case SkyKind::kCieOvercast: return std::make_unique<CieOvercastSky>(cond.diffuseHorizontalLux);
    case SkyKind::kCieClear: return std::make_unique<CieGeneralSky>(12, sun, cond.diffuseHorizontalLux);
    case SkyKind::kCieGeneral:
      if (type.cieType < 1 || type.cieType > 15)
        throw InputError(loc, "sky type '" + skyTypeName(type) + "': the CIE general sky number must be 1..15");
      return std::make_unique<CieGeneralSky>(type.cieType, sun, cond.diffuseHorizontalLux);
    case SkyKind::kPerez: {
      PerezInput in;
      in.directNormalWm2 = cond.directNormalWm2;
      in.diffuseHorizontalWm2 = cond.diffuseHorizontalWm2;
      in.sunDirTrue = sun;
      in.dayOfYear = cond.dayOfYear;
      in.dewPointC = cond.dewPointC;
      return std::make_unique<PerezSky>(in, loc);
    }
    case SkyKind::kNone:
    case SkyKind::kAnnual: break;
  }
  throw InputError(loc, "sky type '" + skyTypeName(type) + "' has no point-in-time sky model");
}

}  // namespace candela
