#include "study/case/case_scene.h"

#include "engine/daylight.h"
#include "engine/luminaire_opening.h"
#include "engine/radiance/reader.h"
#include "photometry/epw.h"
#include "photometry/site.h"
#include "photometry/photometric_file.h"
#include "photometry/make_sky.h"
#include "study/grids/surface_grids.h"
#include "study/window_states.h"

#include <cmath>
#include <optional>

#include <algorithm>
#include <map>

namespace candela {

namespace {
std::vector<std::filesystem::path> scenePaths(const CaseFile& c) {
  std::vector<std::filesystem::path> files;
  for (const ScenePath& s : c.scenes) files.push_back(s.file);
  return files;
}
}  // namespace

void readCaseGeometry(const CaseFile& c, Scene& scene) {
  // Window states (docs/annual.md): point-in-time studies see every group in its first state.
  if (hasWindowStates(c))
    readStateScene(c, {}, scene);
  else
    readSceneFiles(scenePaths(c), scene, c.settings.scene);
  scene.portals.insert(scene.portals.end(), c.portals.begin(), c.portals.end());
}

void removeSurfaces(Scene& scene, const std::vector<std::string>& patterns, std::vector<bool>& used) {
  auto matches = [&](const std::string& name) {
    bool hit = false;
    for (std::size_t k = 0; k < patterns.size(); ++k)
      if (globMatch(patterns[k], name)) hit = used[k] = true;
    return hit;
  };
  std::vector<Shape> shapes;
  std::vector<std::string> names;
  for (std::size_t i = 0; i < scene.shapes.size(); ++i) {
    const std::string& name = i < scene.shapeNames.size() ? scene.shapeNames[i] : std::string();
    if (matches(name)) continue;
    shapes.push_back(scene.shapes[i]);
    if (i < scene.shapeNames.size()) names.push_back(name);
  }
  scene.shapes = std::move(shapes);
  scene.shapeNames = std::move(names);
  TriangleMesh& m = scene.mesh;
  std::vector<std::array<uint32_t, 3>> triangles;
  std::vector<TriangleMesh::Run> runs;
  for (std::size_t r = 0; r < m.runs.size(); ++r) {
    const uint32_t end = r + 1 < m.runs.size() ? m.runs[r + 1].firstTriangle : static_cast<uint32_t>(m.triangles.size());
    if (matches(m.names[m.runs[r].name])) continue;
    TriangleMesh::Run run = m.runs[r];
    run.firstTriangle = static_cast<uint32_t>(triangles.size());
    if (m.runs[r].firstTriangle < end) runs.push_back(run);
    triangles.insert(triangles.end(), m.triangles.begin() + m.runs[r].firstTriangle, m.triangles.begin() + end);
  }
  m.triangles = std::move(triangles);
  m.runs = std::move(runs);
}

std::unique_ptr<Scene> loadCaseScene(const CaseFile& c, bool withDaylight) {
  auto scene = std::make_unique<Scene>();
  readCaseGeometry(c, *scene);
  placeLuminaires(*scene, c.luminaires);
  if (withDaylight) addDaylight(*scene, daylightFromCase(c));
  return scene;
}

void placeLuminaires(Scene& scene, const std::vector<LuminairePlacement>& luminaires) {
  std::map<std::filesystem::path, std::shared_ptr<const PhotometricWeb>> webs;
  for (const LuminairePlacement& p : luminaires) {
    auto& web = webs[p.file];
    if (!web) web = std::make_shared<const PhotometricWeb>(readPhotometricFile(p.file));
    scene.luminaires.push_back(placeLuminaire(web, p.mounting()));
    if (p.openingReflectance)
      addOpeningSurface(scene, static_cast<uint32_t>(scene.luminaires.size() - 1), *p.openingReflectance);
  }
}

Site caseSite(const CaseFile& c, const EpwLocation* weather) {
  if (c.site.present) {
    const double lat = c.site.latitudeDeg ? *c.site.latitudeDeg
                                          : parseLatitudeDeg(c.site.latitudeText, c.site.latitudeLoc);
    const double lon = c.site.longitudeDeg ? *c.site.longitudeDeg
                                           : parseLongitudeDeg(c.site.longitudeText, c.site.longitudeLoc);
    const double tz = c.site.timezoneHours ? *c.site.timezoneHours : (weather ? weather->timezoneHours : 0.0);
    return makeSite(lat, lon, c.site.elevationM, tz, c.site.northDeg, c.site.grid == "utm" ? "utm" : "", c.site.loc);
  }
  if (weather)
    return makeSite(weather->latitudeDeg, weather->longitudeDeg, weather->elevationM, weather->timezoneHours, 0.0);
  return Site{};
}

std::unique_ptr<Scene> loadAnnualScene(const CaseFile& c, double northDeg) {
  auto scene = std::make_unique<Scene>();
  readSceneFiles(scenePaths(c), *scene, c.settings.scene);
  finishAnnualScene(c, northDeg, *scene);
  return scene;
}

void finishAnnualScene(const CaseFile& c, double northDeg, Scene& scene) {
  scene.portals.insert(scene.portals.end(), c.portals.begin(), c.portals.end());
  SkyConditions uniform;
  uniform.diffuseHorizontalLux = kPi;  // 1 cd/m² everywhere: its value is never used
  replaceSceneSky(scene, c.sky.loc);
  SkyDome dome;
  dome.model = makeSky({SkyKind::kUniform}, uniform, c.sky.loc);
  dome.northDeg = northDeg;
  dome.horizontalSkyLux = uniform.diffuseHorizontalLux;
  scene.sky = dome;
}

DaylightSpec daylightFromCase(const CaseFile& c) {
  DaylightSpec d;
  if (!c.sky.present || c.sky.type.kind == SkyKind::kNone) return d;
  if (c.sky.type.kind == SkyKind::kAnnual)
    throw InputError(c.sky.loc, "an annual sky is a whole year: `candela run` computes it (docs/annual.md); "
                                "point and view commands need a point-in-time sky");
  d.skyType = c.sky.type;
  d.skyLoc = c.sky.loc;
  d.time = c.sky.time;
  d.timeLoc = c.sky.timeLoc;
  d.sun = c.sky.sun;
  d.sunAltitudeDeg = c.sky.sunAltitudeDeg;
  d.sunAzimuthDeg = c.sky.sunAzimuthDeg;
  d.diffuseHorizontalLux = c.sky.diffuseHorizontalIlluminanceLux;
  d.directNormalLux = c.sky.directNormalIlluminanceLux;
  d.directNormalWm2 = c.sky.directNormalIrradianceWm2;
  d.diffuseHorizontalWm2 = c.sky.diffuseHorizontalIrradianceWm2;
  d.groundReflectance = c.sky.groundReflectance;
  // A weather file's LOCATION fills what [site] leaves out (all of it without a [site]), as in
  // annual studies (caseSite); a [site] that contradicts it is warned of (study/warnings.h).
  std::optional<EpwFile> epw;
  if (!c.sky.weather.empty()) {
    if (d.time.empty()) throw InputError(c.sky.loc, "a weather file needs a time to pick the hour");
    epw = readEpw(c.sky.weather.string());
  }
  if (c.site.present || epw) {
    const Site site = caseSite(c, epw ? &epw->location : nullptr);
    d.latitudeDeg = site.latitudeDeg;
    d.longitudeDeg = site.longitudeDeg;
    d.elevationM = site.elevationM;
    d.timezoneHours = site.timezoneHours;
    d.northDeg = site.trueNorthDeg();
  }
  if (epw) {
    const LocalTime t = parseLocalTime(d.time, d.timeLoc);
    // EPW hours are hour-ending: hour h covers (h − 1, h].
    const int hour = std::clamp(static_cast<int>(std::ceil(t.hourOfDay())), 1, 24);
    const EpwRecord* rec = nullptr;
    for (const EpwRecord& r : epw->records)
      if (r.month == t.month && r.day == t.day && r.hour == hour) rec = &r;
    if (!rec) throw InputError(d.timeLoc, "the weather file has no hour " + std::to_string(hour) + " on " + d.time);
    if (std::isnan(rec->directNormalWhm2) || std::isnan(rec->diffuseHorizontalWhm2))
      throw InputError(d.timeLoc, "the weather file's hour " + std::to_string(hour) + " on " + d.time +
                                      " has missing irradiance (line " + std::to_string(rec->line) +
                                      "); choose another time or give the irradiances in [sky]");
    if (!d.directNormalWm2) d.directNormalWm2 = rec->directNormalWhm2;
    if (!d.diffuseHorizontalWm2) d.diffuseHorizontalWm2 = rec->diffuseHorizontalWhm2;
    if (d.skyType.kind != SkyKind::kPerez) {
      if (!d.diffuseHorizontalLux) d.diffuseHorizontalLux = rec->diffuseHorizontalLux;
      if (!d.directNormalLux) d.directNormalLux = rec->directNormalLux;
    }
  }
  return d;
}

}  // namespace candela
