#include "study/ugr_table_study.h"

#include "base/error.h"
#include "photometry/luminous_opening.h"

#include <cmath>
#include <string>

namespace candela {

double LuminaireUgrTable::fluxCorrection() const { return 8.0 * std::log10(lampLumens / kUgrReferenceLampLumens); }

UgrLuminaire ugrLuminaireOf(const PhotometricWeb& web, double scale) {
  UgrLuminaire lum;
  lum.intensityCd = [&web, scale](const Vec3& d) { return scale * web.intensityCd(d); };
  lum.projectedAreaM2 = [&web](const Vec3& d) { return projectedOpeningAreaM2(web.info(), d); };
  // CIE 52's cone boundaries: cos γ = 0.75, 0.5, 0.25, 0.
  const double cones[4] = {radToDeg(std::acos(0.75)), 60.0, radToDeg(std::acos(0.25)), 90.0};
  for (int n = 0; n < 4; ++n) lum.downwardConeLm[size_t(n)] = scale * web.lumensBetween(0.0, cones[n]);
  lum.upwardLm = scale * web.lumensBetween(90.0, 180.0);
  return lum;
}

LuminaireUgrTable luminaireUgrTable(const PhotometricWeb& web, const UgrTableSettings& settings) {
  const PhotometricInfo& info = web.info();
  if (!hasLuminousArea(info)) {
    const std::string what = info.openingShape == OpeningShape::kPoint
                                 ? std::string("luminous opening is a point (width, length and height all 0)")
                                 : std::string("luminous opening (") + openingShapeName(info.openingShape) +
                                       ") has no area";
    throw InputError(info.openingLoc, what + ": a UGR needs the luminance of a luminous area");
  }
  LuminaireUgrTable out;
  out.absolutePhotometry = web.isAbsolute();
  out.lampLumens = out.absolutePhotometry ? web.totalLumens() : web.lampLumens();
  if (!(out.lampLumens > 0.0))
    throw InputError(FileLoc{info.fileName}, "the luminaire emits no light: its UGR table is undefined");
  out.table = computeUgrTable(ugrLuminaireOf(web, kUgrReferenceLampLumens / out.lampLumens), settings);
  return out;
}

}  // namespace candela
