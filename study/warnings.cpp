#include "study/warnings.h"

#include "base/units.h"
#include "engine/source_distribution.h"
#include "photometry/site.h"
#include "reports/report_data.h"
#include "study/case/case_scene.h"
#include "study/sight_line.h"

#include <algorithm>
#include <limits>
#include <set>
#include <cmath>

namespace candela {

namespace {

constexpr double kNearSurfaceM = 0.005;   // a sensor this close to a surface reads both of its sides
constexpr double kProbeLiftM = 0.001;     // probes start this far into the sensor's hemisphere
constexpr double kLuminaireBoxToleranceM = 0.05;
constexpr double kClosedVolumeM = 0.5;    // a luminaire enclosed this close on every side is boxed in
constexpr double kSiteToleranceDeg = 1.0;
constexpr std::size_t kSensorsPerLuminaireCheck = 16;
constexpr std::size_t kGlowShapesChecked = 64;
// EN 12464-1:2021's heights for modelling, m above the floor (z = 0), and the leeway of a grid.
constexpr double kSeatedEyeHeightM = 1.2, kStandingEyeHeightM = 1.6, kModellingHeightToleranceM = 0.1;

std::string num(double v) { return formatNumber(v, 4); }
std::string vec(const Vec3& p) { return "(" + num(p.x) + ", " + num(p.y) + ", " + num(p.z) + ")"; }

bool inside(const Box& b, const Vec3& p, double tol) {
  return p.x >= b.lo.x - tol && p.y >= b.lo.y - tol && p.z >= b.lo.z - tol && p.x <= b.hi.x + tol &&
         p.y <= b.hi.y + tol && p.z <= b.hi.z + tol;
}

// Far beyond the scene (over ten times its size away) and inside it once read in millimetres.
bool millimetresFor(const Box& box, const Vec3& p, double tol) {
  if (inside(box, p, tol)) return false;
  const double away = glm::length(glm::max(glm::max(box.lo - p, p - box.hi), Vec3(0.0)));
  const double size = std::max({box.size().x, box.size().y, box.size().z});
  return away > 10.0 * size && inside(box, p / 1000.0, tol);
}

// Two unit vectors that complete n to an orthonormal basis.
void tangents(const Vec3& n, Vec3& t1, Vec3& t2) {
  const Vec3 a = std::abs(n.x) < 0.9 ? Vec3(1.0, 0.0, 0.0) : Vec3(0.0, 1.0, 0.0);
  t1 = glm::normalize(glm::cross(n, a));
  t2 = glm::cross(n, t1);
}

bool hitWithin(const RayAccelerator& accel, const Vec3& o, const Vec3& dir, double tMin, double tMax) {
  RayHit h;
  return accel.intersect(o, dir, tMin, tMax, h);
}

// A surface within kNearSurfaceM of the sensor that cuts its hemisphere: one ray up the normal,
// and four chords across the hemisphere 1 mm above the point, offset sideways by 2 mm so that a
// corner through the point itself is crossed inside a face rather than on its edge. A surface
// the sensor lies on and faces away from (a floor under a floor-level grid) is never crossed.
bool nearSurface(const RayAccelerator& accel, const SensorPoint& s) {
  const Vec3& p = s.position;
  const Vec3& n = s.normal;
  if (hitWithin(accel, p, n, 1e-6, kNearSurfaceM)) return true;
  Vec3 t1, t2;
  tangents(n, t1, t2);
  const Vec3 base = p + kProbeLiftM * n;
  const double side = 0.4 * kNearSurfaceM;
  for (int axis = 0; axis < 2; ++axis) {
    const Vec3 along = axis == 0 ? t1 : t2;
    const Vec3 across = axis == 0 ? t2 : t1;
    for (const double sign : {1.0, -1.0}) {
      const Vec3 o = base + sign * side * across - kNearSurfaceM * along;
      if (hitWithin(accel, o, along, 0.0, 2.0 * kNearSurfaceM)) return true;
    }
  }
  return false;
}

// How many of the six axis directions from just above the sensor meet no surface at all.
int openDirections(const RayAccelerator& accel, const SensorPoint& s) {
  static const Vec3 kAxes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const Vec3 o = s.position + kProbeLiftM * s.normal;
  int open = 0;
  for (const Vec3& d : kAxes) open += !hitWithin(accel, o, d, 0.0, 1e30);
  return open;
}

FileLoc pointLoc(const SensorSet& set, std::size_t i) { return i < set.pointLocs.size() ? set.pointLocs[i] : set.loc; }

// "2 of 24 sensor points lie" / "the sensor point lies".
std::string pointsThat(std::size_t n, std::size_t total, const std::string& verbOne, const std::string& verbMany) {
  if (total == 1) return "the sensor point " + verbOne;
  return std::to_string(n) + " of " + std::to_string(total) + " sensor points " + (n == 1 ? verbOne : verbMany);
}

std::string firstPoint(const SensorSet& set, std::size_t i) {
  return set.points->size() == 1 ? " at " + vec((*set.points)[i].position)
                                 : " (first: point " + std::to_string(i + 1) + " at " + vec((*set.points)[i].position) + ")";
}

// A point on a shape, for aiming a shadow ray at it: its centre (the centroid of a polygon).
Vec3 shapeCentre(const Scene& scene, const Shape& s) {
  switch (s.type) {
    case ShapeType::kTriangle: return s.a + (s.b + s.c) / 3.0;
    case ShapeType::kPolygon: {
      Vec3 c(0.0);
      for (uint32_t k = 0; k < s.vertexCount; ++k) c += scene.vertices.points[s.firstVertex + k];
      return s.vertexCount > 0 ? c / static_cast<double>(s.vertexCount) : s.a;
    }
    case ShapeType::kCone: return 0.5 * (s.a + s.b);
    default: return s.a;  // sphere, ring: the centre
  }
}

// The sensors a luminaire check aims at: up to kSensorsPerLuminaireCheck of each set, spread
// evenly over its points.
std::vector<const SensorPoint*> sampledSensors(const std::vector<SensorSet>& sets) {
  std::vector<const SensorPoint*> out;
  for (const SensorSet& set : sets) {
    const std::size_t n = set.points->size();
    const std::size_t k = std::min(n, kSensorsPerLuminaireCheck);
    for (std::size_t i = 0; i < k; ++i) out.push_back(&(*set.points)[i * n / k]);
  }
  return out;
}

bool reachesAny(const Tracer& tracer, const Vec3& lum, const std::vector<const SensorPoint*>& sensors) {
  for (const SensorPoint* s : sensors) {
    const Vec3 o = s->position + Tracer::originOffset(s->position) * s->normal;
    const Vec3 d = lum - o;
    const double dist = glm::length(d);
    if (dist < 1e-9) return true;
    if (photopic(tracer.transmittance(o, d / dist, dist * (1.0 - 1e-9), kNoShape, kNoShape)) > 0.0) return true;
  }
  return false;
}

}  // namespace

std::vector<SensorSet> sensorSets(const std::vector<PreparedGrid>& grids) {
  std::vector<SensorSet> out;
  for (const PreparedGrid& g : grids) {
    SensorSet s;
    s.name = "grid '" + g.spec->name + "'";
    s.points = &g.grid.points;
    s.loc = g.spec->loc;
    for (const int line : g.grid.lines) s.pointLocs.push_back(FileLoc{g.spec->pointsFile.string(), line, 0});
    out.push_back(std::move(s));
  }
  return out;
}

void checkSceneInput(const Scene& scene, Warnings& out) {
  out.insert(out.end(), scene.inputWarnings.begin(), scene.inputWarnings.end());
}

void checkLightSources(const Scene& scene, const FileLoc& where, Warnings& out) {
  if (!scene.luminaires.empty() || !scene.distant.empty()) return;
  if (scene.sky && scene.sky->model) return;
  for (const Shape& s : scene.shapes) {
    const Material& m = scene.materials[s.material];
    const SourceDistribution* dist = sourceDistributionOf(scene, m);
    if (m.isEmitter() && photopic(m.color) > 0.0 && (!dist || dist->emits())) return;
  }
  out.push_back({"no_light_source",
                 "the scene has no light source: no luminaire, no light, glow or illum surface and no sky; "
                 "every result is 0 lx",
                 where});
}

void checkLuminaires(const Tracer& tracer, const std::vector<LuminairePlacement>& luminaires,
                     const std::vector<SensorSet>& sensors, Warnings& out) {
  const Box box = tracer.scene().bounds();
  if (box.empty()) return;
  const std::vector<const SensorPoint*> targets = sampledSensors(sensors);
  double topSensorZ = -1e300;
  for (const SensorPoint* s : targets) topSensorZ = std::max(topSensorZ, s->position.z);
  const RayAccelerator& accel = tracer.accelerator();
  const std::string boxText = vec(box.lo) + " – " + vec(box.hi) + " m";
  for (const LuminairePlacement& l : luminaires) {
    const Vec3& p = l.positionM;
    const std::string who = "luminaire '" + l.name + "' at " + vec(p) + " m";
    // Over a flat scene (a car park's or a road's ground alone) a luminaire on its pole is above
    // the box: it is outside only beyond the ground's plan extent or below the ground.
    const bool overFlatGround = box.hi.z - box.lo.z <= kLuminaireBoxToleranceM &&
                                inside(box, Vec3(p.x, p.y, box.lo.z), kLuminaireBoxToleranceM) && p.z > box.lo.z;
    if (!inside(box, p, kLuminaireBoxToleranceM) && !overFlatGround) {
      if (millimetresFor(box, p, kLuminaireBoxToleranceM))
        out.push_back({"millimetre_positions",
                       who + " lies outside the scene " + boxText + " but inside it if read in millimetres: "
                             "case positions are in metres",
                       l.loc});
      else
        out.push_back({"luminaire_outside_scene", who + " lies outside the scene's bounding box " + boxText, l.loc});
      continue;
    }
    if (targets.empty() || reachesAny(tracer, p, targets)) continue;
    // Its light reaches none of the sensors: say where it is hidden. Enclosed within
    // kClosedVolumeM on all six axes: inside a closed volume (a fitting's body, a box); else
    // over a surface that lies above every sensor: above the ceiling (or inside its slab).
    static const Vec3 kAxes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    int enclosed = 0;
    for (const Vec3& d : kAxes) enclosed += hitWithin(accel, p, d, 0.0, kClosedVolumeM);
    RayHit below;
    if (enclosed == 6)
      out.push_back({"luminaire_in_closed_volume",
                     who + " reaches no sensor: surfaces enclose it within " + num(kClosedVolumeM) +
                         " m on every side (inside a closed volume?)",
                     l.loc});
    else if (accel.intersect(p, Vec3(0.0, 0.0, -1.0), 0.0, 1e30, below) && p.z - below.t > topSensorZ)
      out.push_back({"luminaire_above_ceiling",
                     who + " reaches no sensor: a surface " + num(below.t) + " m below it lies above every sensor "
                           "(is it above the ceiling?)",
                     l.loc});
    else
      out.push_back({"luminaire_reaches_no_sensor", who + " reaches none of the sensors: its light is blocked", l.loc});
  }
}

void checkMillimetrePositions(const CaseFile& c, const Box& box, Warnings& out) {
  if (box.empty()) return;
  const std::string boxText = vec(box.lo) + " – " + vec(box.hi) + " m";
  auto check = [&](const std::string& who, const Vec3& p, const FileLoc& loc) {
    if (!millimetresFor(box, p, kLuminaireBoxToleranceM)) return false;
    out.push_back({"millimetre_positions",
                   who + " at " + vec(p) + " m lies outside the scene " + boxText +
                       " but inside it if read in millimetres: case positions are in metres",
                   loc});
    return true;
  };
  // One warning a list: its first such position (the rest are likely written the same way).
  for (const ComplianceSpec& s : c.compliance) {
    const std::string entry = "[[compliance]] '" + s.name + "'";
    for (size_t i = 0; i < s.sunlightPoints.size(); ++i)
      if (check(entry + ": sunlight point " + std::to_string(i + 1), s.sunlightPoints[i], s.sunlightLoc)) break;
    for (size_t i = 0; i < s.viewPoints.size(); ++i)
      if (check(entry + ": view point " + std::to_string(i + 1), s.viewPoints[i], s.viewLoc)) break;
    for (size_t i = 0; i < s.glareViews.size(); ++i)
      if (check(entry + ": glare view " + std::to_string(i + 1), s.glareViews[i].positionM, s.glareViews[i].loc)) break;
  }
  // An observer is a plan position and an eye height: judged in plan (its height within the box).
  for (const ObserverSpec& o : c.observers) {
    const Vec3 plan(o.positionM.x, o.positionM.y, std::clamp(o.eyeHeightM, box.lo.z, box.hi.z));
    if (millimetresFor(box, plan, kLuminaireBoxToleranceM) || millimetresFor(box, o.eyeM(), kLuminaireBoxToleranceM))
      out.push_back({"millimetre_positions",
                     "observer '" + o.name + "' at " + vec(o.eyeM()) + " m lies outside the scene " + boxText +
                         " but inside it if read in millimetres: case positions are in metres",
                     o.loc});
  }
}

void checkViewOutOpenings(const Tracer& tracer, const CaseFile& c, Warnings& out) {
  constexpr int kRays = 360;  // one a degree round the eye's horizon
  for (const ComplianceSpec& s : c.compliance) {
    size_t points = 0, first = 0;
    int firstDeg = 0;
    for (size_t i = 0; i < s.viewPoints.size(); ++i) {
      int open = 0;
      for (int k = 0; k < kRays; ++k) {
        const double a = degToRad(k + 0.5);
        uint64_t rays = 0;
        const SightLine line = traceSightLine(tracer, s.viewPoints[i], Vec3(std::cos(a), std::sin(a), 0.0),
                                              std::numeric_limits<double>::infinity(), rays);
        open += line.glazingCrossed == 0 && !line.blocked;
      }
      if (open > 0 && points++ == 0) {
        first = i;
        firstDeg = open;
      }
    }
    if (points == 0) continue;
    out.push_back({"view_out_unglazed_opening",
                   "[[compliance]] '" + s.name + "': " + std::to_string(points) + " of " +
                       std::to_string(s.viewPoints.size()) + " view points see outside without glazing (the first, " +
                       "point " + std::to_string(first + 1) + " at " + vec(s.viewPoints[first]) + " m, over " +
                       std::to_string(firstDeg) + " deg of its horizon): EN 17037's view out counts lines of sight "
                       "through glazing only, so an unglazed opening (or an eye outdoors) reads 0 deg and \"none\" there",
                   s.viewLoc});
  }
}

void checkGridSpacing(const PreparedGrid& g, Warnings& out) {
  const GridSpec& spec = *g.spec;
  if (spec.kind != GridKind::kPlane || !g.grid.regular || spec.plane.outline.empty()) return;
  Vec2 lo(1e300), hi(-1e300);
  for (const Vec2& q : spec.plane.outline) {
    lo = glm::min(lo, q);
    hi = glm::max(hi, q);
  }
  const Vec2 extent = hi - lo - 2.0 * spec.plane.borderM;
  const double spacing = g.grid.nominalSpacingM;
  if (spacing > extent.x || spacing > extent.y)
    out.push_back({"grid_spacing_exceeds_extent",
                   "grid '" + spec.name + "': spacing " + num(spacing) + " m exceeds its calculation area of " +
                       num(extent.x) + " × " + num(extent.y) + " m (after the border): " +
                       std::to_string(g.grid.size()) + " point(s), so Emin and U0 do not describe the area",
                   spec.loc});
}

void checkModellingHeight(const PreparedGrid& g, Warnings& out) {
  const GridSpec& spec = *g.spec;
  if (!spec.modelling || g.grid.points.empty()) return;
  // Every point within kModellingHeightToleranceM of one of the two heights.
  auto near = [](double z, double h) { return std::abs(z - h) <= kModellingHeightToleranceM + 1e-9; };
  for (const SensorPoint& p : g.grid.points) {
    const double z = p.position.z;
    if (near(z, kSeatedEyeHeightM) || near(z, kStandingEyeHeightM)) continue;
    out.push_back({"modelling_height",
                   "grid '" + spec.name + "': modelling (EN 12464-1:2021) is assessed at " + num(kSeatedEyeHeightM) +
                       " m (seated) or " + num(kStandingEyeHeightM) + " m (standing) above the floor; this grid has a point at " +
                       num(z) + " m, where the ratio Ez/Eh describes no one's view",
                   spec.modellingLoc});
    return;
  }
}

void checkSensors(const Tracer& tracer, const SensorSet& set, Warnings& out) {
  const std::vector<SensorPoint>& pts = *set.points;
  if (pts.empty() || tracer.scene().surfaceCount() == 0) return;
  const RayAccelerator& accel = tracer.accelerator();
  std::size_t near = 0, firstNear = 0;
  std::vector<int> open(pts.size());
  std::size_t enclosed = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (nearSurface(accel, pts[i]) && near++ == 0) firstNear = i;
    open[i] = openDirections(accel, pts[i]);
    enclosed += open[i] == 0;
  }
  if (near > 0)
    out.push_back({"sensor_near_surface",
                   set.name + ": " + pointsThat(near, pts.size(), "lies", "lie") + " on or within 5 mm of a surface that cuts " +
                       (near == 1 ? "its" : "their") + " hemisphere" + firstPoint(set, firstNear) +
                       "; such a sensor sees both sides of the surface",
                   pointLoc(set, firstNear)});
  // Outside: beyond the scene's box in a scene with no sky, or open to the outside where at least
  // three quarters of a set of four or more are enclosed (so an open scene never warns).
  // The box of the scene and its luminaires, as grids are judged (prepareGrids).
  Box box = tracer.scene().bounds();
  for (const LuminaireSource& l : tracer.scene().luminaires) box.extend(l.position);
  const bool mostEnclosed = pts.size() >= 4 && 4 * enclosed >= 3 * pts.size();
  std::size_t outside = 0, firstOutside = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const bool beyondBox = !tracer.scene().sky && !inside(box, pts[i].position, 1e-3);
    if ((beyondBox || (mostEnclosed && open[i] > 0)) && outside++ == 0) firstOutside = i;
  }
  if (outside > 0)
    out.push_back({"sensor_outside_room",
                   set.name + ": " + pointsThat(outside, pts.size(), "lies", "lie") + " outside the room" +
                       firstPoint(set, firstOutside) +
                       (mostEnclosed ? " (open to the outside where the others are enclosed)" : " (beyond the scene)"),
                   pointLoc(set, firstOutside)});
}

void checkSiteAgainstWeather(const CaseFile& c, const EpwLocation& w, Warnings& out) {
  if (!c.site.present) return;
  const Site site = caseSite(c, &w);
  const double dLat = std::abs(site.latitudeDeg - w.latitudeDeg);
  double dLon = std::fmod(std::abs(site.longitudeDeg - w.longitudeDeg), 360.0);
  dLon = std::min(dLon, 360.0 - dLon);
  const bool tz = c.site.timezoneHours && std::abs(*c.site.timezoneHours - w.timezoneHours) > 1e-6;
  if (dLat <= kSiteToleranceDeg && dLon <= kSiteToleranceDeg && !tz) return;
  std::string what = "[site] (" + num(site.latitudeDeg) + "°, " + num(site.longitudeDeg) + "°";
  if (c.site.timezoneHours) what += ", UTC" + std::string(*c.site.timezoneHours >= 0 ? "+" : "") + num(*c.site.timezoneHours);
  what += ") contradicts the weather file's LOCATION (" + w.city + ": " + num(w.latitudeDeg) + "°, " +
          num(w.longitudeDeg) + "°, UTC" + (w.timezoneHours >= 0 ? "+" : "") + num(w.timezoneHours) + ")";
  what += tz && dLat <= kSiteToleranceDeg && dLon <= kSiteToleranceDeg ? " in its time zone"
                                                                        : " by more than 1°";
  out.push_back({"site_contradicts_weather",
                 what + ": the sun is placed for one site and the weather of another, so sun-dependent results "
                        "(ASE, sun hours, direct sun) are wrong",
                 c.site.loc});
}

void checkCaseSite(const CaseFile& c, Warnings& out) {
  if (!c.site.present || c.sky.weather.empty() || !c.sky.present) return;
  checkSiteAgainstWeather(c, readEpw(c.sky.weather.string()).location, out);
}

void checkSkySun(const CaseFile& c, const Scene& scene, Warnings& out) {
  const SkyType& type = c.sky.type;
  if (!c.sky.present || !c.sky.sun || !type.hasSun() || type.kind == SkyKind::kPerez) return;
  if (c.sky.directNormalIlluminanceLux || !c.sky.weather.empty()) return;  // a sun of 0 lx said so
  if (!scene.sky || scene.sky->horizontalSunLux > 0.0 || !(scene.sky->sunAltitudeDeg > 0.0)) return;
  out.push_back({"sky_without_sun",
                 "[sky] type '" + skyTypeName(type) + "' has its sun " + num(scene.sky->sunAltitudeDeg) +
                     "° above the horizon but no direct normal illuminance (`direct_normal_illuminance`, or a "
                     "`weather` file's hour): the sun disc carries no light" +
                     (c.sky.diffuseHorizontalIlluminanceLux ? std::string()
                                                            : ", and the sky's diffuse horizontal illuminance is the "
                                                              "default 10 000 lx") +
                     "; `sun = false` says that no sun is meant",
                 c.sky.loc});
}

void checkErrorBars(const Tracer& tracer, const SensorSet& set, const double* lux, const double* errorLux,
                    Warnings& out) {
  const Scene& scene = tracer.scene();
  std::vector<uint32_t> glows;
  for (uint32_t i = 0; i < scene.shapes.size() && glows.size() < kGlowShapesChecked; ++i) {
    const Material& m = scene.materials[scene.shapes[i].material];
    if (m.isEmitter() && !m.isSampledSource() && photopic(m.color) > 0.0) glows.push_back(i);  // glows
  }
  if (glows.empty()) return;
  const std::vector<SensorPoint>& pts = *set.points;
  std::size_t count = 0, first = 0;
  uint32_t firstGlow = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (lux[i] != 0.0 || errorLux[i] != 0.0) continue;
    const Vec3 o = pts[i].position + Tracer::originOffset(pts[i].position) * pts[i].normal;
    for (const uint32_t g : glows) {
      const Vec3 d = shapeCentre(scene, scene.shapes[g]) - o;
      const double dist = glm::length(d);
      if (!(dist > 0.0) || glm::dot(d, pts[i].normal) <= 0.0) continue;
      if (photopic(tracer.transmittance(o, d / dist, dist, g, kNoShape)) <= 0.0) continue;
      if (count++ == 0) {
        first = i;
        firstGlow = g;
      }
      break;
    }
  }
  if (count == 0) return;
  const std::string glowName = scene.shapeNames.size() > firstGlow ? scene.shapeNames[firstGlow] : "";
  out.push_back({"untrusted_error_bar",
                 set.name + ": " + pointsThat(count, pts.size(), "reads", "read") + " 0 ± 0 lx" + firstPoint(set, first) +
                     " although the glow surface '" + glowName + "' faces " + (count == 1 ? "it" : "them") +
                     " unobstructed: no hemisphere sample found it (a glow is sampled directly only within its radius "
                     "or where its bounding sphere is smaller than a hemisphere stratum), so the value and its zero "
                     "error bar are not to be trusted; raise the samples, give the glow a radius or make it a light",
                 pointLoc(set, first)});
}

void checkDarkSensors(const SensorSet& set, const double* lux, const double* errorLux, Warnings& out) {
  const std::vector<SensorPoint>& pts = *set.points;
  std::size_t dark = 0, first = 0;
  bool lit = false;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    lit |= lux[i] > 0.0;
    if (lux[i] != 0.0 || errorLux[i] != 0.0) continue;
    if (dark++ == 0) first = i;
  }
  if (dark == 0 || !lit) return;
  out.push_back({"sensor_reads_nothing",
                 set.name + ": " + pointsThat(dark, pts.size(), "reads", "read") + " 0 ± 0 lx" + firstPoint(set, first) +
                     " while the others are lit: no ray from " + (dark == 1 ? "it" : "them") +
                     " reached any light, as from inside furniture or a closed volume; the grid's Emin, U0 and "
                     "average count " + (dark == 1 ? "it" : "them") + " (leave such points out: a border, a task "
                     "area's room, the outline)",
                 pointLoc(set, first)});
}

void checkPhotometry(const Scene& scene, const std::vector<LuminairePlacement>& luminaires, Warnings& out) {
  std::set<const PhotometricWeb*> seen;
  for (std::size_t i = 0; i < luminaires.size() && i < scene.luminaires.size(); ++i) {
    const PhotometricWeb* web = scene.luminaires[i].web.get();
    if (!web || !seen.insert(web).second) continue;
    const std::string file = luminaires[i].file.filename().string();
    const double lor = web->lightOutputRatio();  // NaN for absolute photometry
    if (web->maxIntensityCd() <= 0.0)
      out.push_back({"luminaire_photometry", "the photometric file " + file + " has no intensity above 0 cd: the luminaire gives no light",
                     luminaires[i].loc});
    else if (lor > 1.0 + 1e-3)
      out.push_back({"luminaire_photometry",
                     "the photometric file " + file + " gives a light output ratio of " + formatFixed(100.0 * lor, 1) +
                         " %: more light than its lamps (check the lamp flux and the multiplier)",
                     luminaires[i].loc});
  }
}

void checkLuminairePower(const Scene& scene, const CaseFile& c, Warnings& out) {
  std::set<int> warned;
  for (std::size_t i = 0; i < c.luminaires.size() && i < scene.luminaires.size(); ++i) {
    const LuminairePlacement& p = c.luminaires[i];
    const PhotometricWeb* web = scene.luminaires[i].web.get();
    if (!web || p.powerW || web->inputWatts() > 0.0 || !warned.insert(p.entry).second) continue;
    const std::size_t e = static_cast<std::size_t>(p.entry);
    const std::string name = e < c.luminaireEntries.size() ? c.luminaireEntries[e].name : p.name;
    out.push_back({"luminaire_power_unknown",
                   "luminaire '" + name + "': its photometric file " + p.file.filename().string() +
                       " gives no input power and the entry has no 'power_w'; the installed power and the power "
                       "density leave it out (a lower bound)",
                   p.loc});
  }
}

void checkWeatherGaps(const EpwFile& weather, const std::string& fileName, Warnings& out) {
  if (weather.missingIrradianceHours == 0) return;
  out.push_back({"weather_missing_hours",
                 std::to_string(weather.missingIrradianceHours) + " of " + std::to_string(weather.records.size()) +
                     " hours have missing irradiance; they are treated as dark",
                 FileLoc{fileName, 0, 0}});
}

Warnings pointInTimeWarnings(const CaseFile& c, const Tracer& tracer, const std::vector<PreparedGrid>& grids) {
  Warnings w;
  checkSceneInput(tracer.scene(), w);
  checkLightSources(tracer.scene(), FileLoc{c.path.string(), 0, 0}, w);
  checkCaseSite(c, w);
  checkSkySun(c, tracer.scene(), w);
  const std::vector<SensorSet> sets = sensorSets(grids);
  checkLuminaires(tracer, c.luminaires, sets, w);
  checkMillimetrePositions(c, tracer.scene().bounds(), w);
  checkPhotometry(tracer.scene(), c.luminaires, w);
  checkLuminairePower(tracer.scene(), c, w);
  for (const PreparedGrid& g : grids)
    if (g.outside) w.push_back(*g.outside);
  for (const PreparedGrid& g : grids) checkGridSpacing(g, w);
  for (const PreparedGrid& g : grids) checkModellingHeight(g, w);
  for (const SensorSet& set : sets) checkSensors(tracer, set, w);
  return w;
}

Warnings annualInputWarnings(const CaseFile& c, const EpwLocation& weather, const Scene& scene,
                             const std::vector<PreparedGrid>& grids) {
  Warnings w;
  checkSceneInput(scene, w);
  checkSiteAgainstWeather(c, weather, w);
  checkMillimetrePositions(c, scene.bounds(), w);
  const Tracer probe(scene);
  checkViewOutOpenings(probe, c, w);
  const std::vector<SensorSet> sets = sensorSets(grids);
  for (const PreparedGrid& g : grids)
    if (g.outside) w.push_back(*g.outside);
  for (const PreparedGrid& g : grids) checkGridSpacing(g, w);
  for (const SensorSet& set : sets) checkSensors(probe, set, w);
  return w;
}

}  // namespace candela
