#include "engine/daylight.h"

#include "photometry/site.h"
#include "photometry/sky_perez.h"
#include "photometry/sun_spa.h"
#include "photometry/make_sky.h"

#include <cmath>

namespace candela {

void replaceSceneSky(Scene& scene, const FileLoc& by) {
  if (!scene.sky || !scene.sky->fromScene) return;
  const SkyDome& old = *scene.sky;
  const std::string where = old.sceneLoc.file + ":" + std::to_string(old.sceneLoc.line);
  if (old.sceneSun >= 0) scene.distant.erase(scene.distant.begin() + old.sceneSun);
  scene.inputWarnings.push_back(Warning{"scene_sky_replaced",
                                        "the scene's own sky (" + old.model->name() + ", " + where +
                                            ") and its sun are replaced by the case's sky",
                                        by});
  scene.sky.reset();
}

void addDaylight(Scene& scene, const DaylightSpec& spec) {
  if (spec.skyType.kind == SkyKind::kNone) return;
  replaceSceneSky(scene, spec.skyLoc);

  // Sun position (true frame): explicit, else from the site and time by the NREL SPA.
  double altitude = 90.0, azimuth = 180.0;
  int dayOfYear = 172;
  const bool needSunPosition = spec.skyType.dependsOnSun() || spec.directNormalLux.has_value();
  if (spec.sunAltitudeDeg && spec.sunAzimuthDeg) {
    altitude = *spec.sunAltitudeDeg;
    azimuth = *spec.sunAzimuthDeg;
    if (!spec.time.empty()) dayOfYear = parseLocalTime(spec.time, spec.timeLoc).dayOfYear();
  } else if (spec.latitudeDeg && spec.longitudeDeg && !spec.time.empty()) {
    const LocalTime t = parseLocalTime(spec.time, spec.timeLoc);
    SpaInput in;
    in.year = t.year;
    in.month = t.month;
    in.day = t.day;
    in.hourOfDay = t.hourOfDay();
    in.timezoneHours = t.utcOffsetHours.value_or(spec.timezoneHours);
    in.latitudeDeg = *spec.latitudeDeg;
    in.longitudeDeg = *spec.longitudeDeg;
    in.elevationM = spec.elevationM;
    in.deltaTSec = estimateDeltaTSec(t.year + (t.dayOfYear() - 0.5) / 365.25);
    const SpaResult r = computeSunPosition(in);
    altitude = r.altitudeDeg;
    azimuth = r.azimuthDeg;
    dayOfYear = t.dayOfYear();
  } else if (needSunPosition) {
    throw InputError(spec.skyLoc, "sky '" + skyTypeName(spec.skyType) +
                                      "' needs the sun's position: sun altitude and azimuth, or latitude, "
                                      "longitude and time");
  }

  SkyConditions cond;
  cond.sunDirTrue = directionFromAzAlt(azimuth, std::max(altitude, 0.0), 0.0);
  cond.dayOfYear = dayOfYear;
  cond.diffuseHorizontalLux = spec.diffuseHorizontalLux.value_or(10000.0);
  if (spec.skyType.kind == SkyKind::kPerez) {
    if (!spec.directNormalWm2 || !spec.diffuseHorizontalWm2)
      throw InputError(spec.skyLoc, "sky 'perez' needs the direct normal and diffuse horizontal irradiance (W/m2)");
    cond.directNormalWm2 = *spec.directNormalWm2;
    cond.diffuseHorizontalWm2 = *spec.diffuseHorizontalWm2;
  }
  std::shared_ptr<SkyModel> model = makeSky(spec.skyType, cond, spec.skyLoc);

  SkyDome dome;
  dome.model = model;
  dome.northDeg = spec.northDeg;
  dome.horizontalSkyLux = model->horizontalIlluminanceLux();
  dome.sunAltitudeDeg = altitude;
  dome.sunAzimuthDeg = azimuth;
  dome.sunDirModel = directionFromAzAlt(azimuth, altitude, spec.northDeg);

  // The sun: direct normal illuminance given, or Perez's beam through its efficacy model.
  double dnLux = spec.directNormalLux.value_or(0.0);
  if (spec.skyType.kind == SkyKind::kPerez && !spec.directNormalLux) {
    if (const auto* perez = dynamic_cast<const PerezSky*>(model.get())) dnLux = perez->directNormalIlluminanceLux();
  }
  if (spec.sun && dnLux > 0.0 && altitude > 0.0) {
    // A uniform disk of luminance L = E_dn / Ω reproduces the direct normal illuminance.
    const double halfAngle = degToRad(0.5 * kSunDiameterDeg);
    const double omega = kTwoPi * (1.0 - std::cos(halfAngle));
    Material m;
    m.type = MaterialType::kLight;
    m.name = "sun";
    m.color = Rgb(dnLux / omega / kLumensPerWatt);
    scene.addDistant(dome.sunDirModel, kSunDiameterDeg, scene.addMaterial(m), "sun");
    // Horizontal illuminance of the disk, π L sin²α sin(altitude), with the cap formula.
    dome.horizontalSunLux = dnLux / omega * kPi * std::pow(std::sin(halfAngle), 2) * std::sin(degToRad(altitude));
  }
  dome.groundLuminanceCdM2 = spec.groundReflectance * dome.outsideHorizontalLux() / kPi;
  scene.sky = dome;
}

}  // namespace candela
