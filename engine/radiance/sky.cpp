#include "engine/radiance/sky.h"

#include "base/units.h"
#include "engine/radiance/transform.h"
#include "photometry/site.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace candela {

namespace {

// rayinit.cal's guarded functions, as the .cal files call them.
double boundedAcos(double x) { return std::acos(std::clamp(x, -1.0, 1.0)); }
double guardedExp(double x) { return x < -100.0 ? 0.0 : std::exp(x); }

// skybright.cal and perezlum.cal blend the sky into the ground brightness near the horizon:
// wmean((Dz + 1.01)^10, sky, (Dz + 1.01)^-10, ground).
double blendWithGround(double dz, double sky, double ground) {
  const double w = std::pow(dz + 1.01, 10.0), v = std::pow(dz + 1.01, -10.0);
  return (w * sky + v * ground) / (w + v);
}

// A sky a full angle of 360 degrees covers; 180 degrees about +Z or -Z is a hemisphere.
constexpr double kAngleTolerance = 1e-6;

}  // namespace

bool isSkyPattern(PatternKind kind) { return kind == PatternKind::kSkyBright || kind == PatternKind::kPerezLum; }

RadianceSkyFunction::RadianceSkyFunction(const ScenePattern& p) : kind_(p.kind), a_(p.reals) {
  const std::string what = p.type + " '" + p.name + "'";
  const bool bright = kind_ == PatternKind::kSkyBright;
  const std::string& file = p.strings[1];
  const std::string function = bright ? "skybr" : "skybright";
  if (p.strings[0] != function)
    throw InputError(p.loc, what + ": " + file + " defines the sky function '" + function + "', not '" + p.strings[0] + "'");
  // Transform arguments (Radiance reference manual, "Transformations"; xform appends its own,
  // engine/radiance/transform.h): a turn about +Z turns the sky, a translation or scale leaves
  // directions as they are; a transform that tilts or mirrors the sky is refused.
  RadTransform xf;
  const size_t end = parseRadTransform(p.strings, 2, xf, p.loc, what);
  if (end != p.strings.size())
    throw InputError(p.loc, what + ": '" + p.strings[end] + "' after the function file is not a transform argument");
  const glm::dmat3 r = glm::dmat3(xf.matrix) / std::abs(xf.scale);
  const Vec3 up = r * Vec3(0.0, 0.0, 1.0), east = r * Vec3(1.0, 0.0, 0.0);
  if (xf.scale < 0.0 || glm::length(up - Vec3(0.0, 0.0, 1.0)) > 1e-9)
    throw InputError(p.loc, what + ": its transform tilts or mirrors the sky; a sky function may only be turned "
                                   "about +Z (-rz), moved or scaled");
  rotationDeg_ = radToDeg(std::atan2(east.y, east.x));
  // Radiances beyond 1e30 W/sr/m2 would overflow in products (as the emitters' bound in the reader).
  for (double v : a_)
    if (!(std::abs(v) <= 1e30)) throw InputError(p.loc, what + ": a real argument beyond 1e30");
  if (bright) {
    if (a_.empty() || a_[0] != std::floor(a_[0]) || a_[0] < 1 || a_[0] > 4)
      throw InputError(p.loc, what + ": skybright.cal's first argument is the sky type 1 (CIE clear), 2 (CIE overcast), "
                                     "3 (uniform) or 4 (CIE intermediate)");
    type_ = static_cast<int>(a_[0]);
    const size_t need = (type_ == 1 || type_ == 4) ? 7 : 3;
    if (a_.size() < need)
      throw InputError(p.loc, what + ": skybright.cal's sky type " + std::to_string(type_) + " needs " +
                                  std::to_string(need) + " real arguments, got " + std::to_string(a_.size()));
    ground_ = a_[2];
    if (need == 7) {
      if (a_[3] == 0.0) throw InputError(p.loc, what + ": skybright.cal's normalisation (4th argument) is 0");
      sun_ = Vec3(a_[4], a_[5], a_[6]);
    }
  } else {
    if (a_.size() < 10)
      throw InputError(p.loc, what + ": perezlum.cal needs 10 real arguments, got " + std::to_string(a_.size()));
    ground_ = a_[1];
    sun_ = Vec3(a_[7], a_[8], a_[9]);
  }
}

double RadianceSkyFunction::value(const Vec3& d) const {
  const std::vector<double>& A = a_;
  double sky = 0.0;
  if (kind_ == PatternKind::kPerezLum) {
    // perezlum.cal: A1 (1 + A3 Exp(A4 / Dz)) (1 + A5 Exp(A6 gamma) + A7 cos^2 gamma), Dz held at
    // 0.01 and below.
    const double cg = d.x * A[7] + d.y * A[8] + d.z * A[9];
    const double gamma = boundedAcos(cg);
    const double dz = d.z - 0.01 > 0.0 ? d.z : 0.01;
    sky = A[0] * (1.0 + A[2] * guardedExp(A[3] / dz)) * (1.0 + A[4] * guardedExp(A[5] * gamma) + A[6] * cg * cg);
    return blendWithGround(d.z, sky, A[1]);
  }
  switch (type_) {
    case 1: {  // CIE clear sky (1973 formula), A4 its normalisation
      const double cg = d.x * A[4] + d.y * A[5] + d.z * A[6];
      const double gamma = boundedAcos(cg);
      const double gradation = d.z - .01 > 0.0 ? 1.0 - std::exp(-.32 / d.z) : 1.0;
      sky = A[1] * (.91 + 10.0 * std::exp(-3.0 * gamma) + .45 * cg * cg) * gradation / A[3];
      break;
    }
    case 2: sky = A[1] * (1.0 + 2.0 * d.z) / 3.0; break;  // CIE overcast (Moon & Spencer)
    case 3: sky = A[1]; break;                           // uniform
    default: {                                          // CIE intermediate (Matsuura)
      const double cg = d.x * A[4] + d.y * A[5] + d.z * A[6];
      const double gamma = boundedAcos(cg);
      const double zt = boundedAcos(A[6]), eta = boundedAcos(d.z);
      sky = A[1] * ((1.35 * std::sin(5.631 - 3.59 * eta) + 3.12) * std::sin(4.396 - 2.6 * zt) + 6.37 - eta) / 2.326 *
            std::exp(gamma * -.563 * ((2.629 - eta) * (1.562 - zt) + .812)) / A[3];
      break;
    }
  }
  return blendWithGround(d.z, sky, A[2]);
}

std::string RadianceSkyFunction::description() const {
  if (kind_ == PatternKind::kPerezLum) return "gendaylit Perez (perezlum.cal)";
  static const char* const kNames[] = {"", "CIE clear", "CIE overcast", "uniform", "CIE intermediate"};
  return std::string("gensky ") + kNames[type_] + " (skybright.cal)";
}

RadianceSky::RadianceSky(const RadianceSkyFunction& f, double factor) : f_(f), factor_(factor) {
  // calibrate(E) scales the relative luminance to a horizontal illuminance E; calibrating to the
  // hemisphere's own integral leaves the scale at exactly 1 (the same integral both times).
  calibrate(1.0);
  calibrate(scale() > 0.0 ? 1.0 / scale() : 0.0);
}

double RadianceSky::relativeLuminance(const Vec3& d) const { return std::max(0.0, factor_ * f_.value(d)); }

void SceneSkyBuilder::addSource(const Scene& scene, uint32_t material, const Vec3& dir, double angleDeg,
                                const std::string& name, const FileLoc& loc) {
  const Material& m = scene.materials[material];
  const ScenePattern& p = scene.patterns[static_cast<size_t>(m.pattern)];
  if (pattern_ >= 0 && pattern_ != m.pattern) {
    const ScenePattern& first = scene.patterns[static_cast<size_t>(pattern_)];
    throw InputError(loc, "source '" + name + "' brings a second sky ('" + p.name + "', line " +
                              std::to_string(p.loc.line) + "); the scene's sky is already '" + first.name + "' (" +
                              first.loc.file + ":" + std::to_string(first.loc.line) + "): a scene has one sky");
  }
  const Vec3 n = glm::normalize(dir);
  const bool whole = angleDeg >= 360.0 - kAngleTolerance;
  const bool half = std::abs(angleDeg - 180.0) <= kAngleTolerance;
  const bool up = half && n.z > 1.0 - 1e-9, down = half && n.z < -1.0 + 1e-9;
  if (!whole && !up && !down)
    throw InputError(loc, "source '" + name + "' with the sky function '" + p.name +
                              "' must be the sky hemisphere (0 0 1 180), the ground hemisphere (0 0 -1 180) or the "
                              "whole sphere (angle 360)");
  (void)RadianceSkyFunction(p);  // checks the pattern's arguments at its own line
  const Part part{static_cast<int>(material), name, loc};
  auto take = [&](Part& slot, const char* which) {
    if (slot.material >= 0)
      throw InputError(loc, "source '" + name + "': the " + which + " hemisphere is already source '" + slot.name +
                                "' (line " + std::to_string(slot.loc.line) + ")");
    slot = part;
  };
  if (whole || up) take(sky_, "sky");
  if (whole || down) take(ground_, "ground");
  pattern_ = m.pattern;
  changed_ = true;
}

void SceneSkyBuilder::apply(Scene& scene) {
  // Rebuilt after a new sky source, or a new distant source that may be the sun.
  if (!changed_ && !(applied_ && scene.distant.size() != distantSeen_)) return;
  changed_ = false;
  distantSeen_ = scene.distant.size();
  const ScenePattern& p = scene.patterns[static_cast<size_t>(pattern_)];
  // A sky that another reader of the same scene set (scene files read in two batches).
  if (!applied_ && scene.sky && scene.sky->fromScene)
    throw InputError(sky_.material >= 0 ? sky_.loc : ground_.loc,
                     "the sky function '" + p.name + "' brings a second sky; the scene's sky is already defined at " +
                         scene.sky->sceneLoc.file + ":" + std::to_string(scene.sky->sceneLoc.line) +
                         ": a scene has one sky");
  applied_ = true;
  if (sky_.material < 0)
    throw InputError(ground_.loc, "source '" + ground_.name + "' is a ground hemisphere with the sky function '" +
                                      p.name + "' but the scene has no sky hemisphere (0 0 1 180) with it");
  const RadianceSkyFunction f(p);
  const double skyFactor = luminanceFromRadiance(scene.materials[static_cast<size_t>(sky_.material)].color);
  auto model = std::make_shared<RadianceSky>(f, skyFactor);

  SkyDome dome;
  dome.model = model;
  dome.northDeg = -f.rotationDeg();  // the pattern turned counter-clockwise by -rz
  dome.horizontalSkyLux = model->horizontalIlluminanceLux();
  if (ground_.material >= 0) {
    // Far below the horizon the function is the ground brightness; near it, the sky's and the
    // ground's blend, evaluated direction by direction.
    dome.groundFactorCdM2 = luminanceFromRadiance(scene.materials[static_cast<size_t>(ground_.material)].color);
    dome.groundLuminanceCdM2 = dome.groundFactorCdM2 * f.groundBrightness();
    dome.groundFunction = std::make_shared<const RadianceSkyFunction>(f);
  }
  dome.fromScene = true;
  dome.sceneLoc = sky_.loc;
  // The sun: the brightest small distant `light` (gensky's 0.5 degree, gendaylit's 0.533 degree
  // `solar source sun`), else the sun direction of the sky function.
  double best = 0.0;
  for (size_t i = 0; i < scene.distant.size(); ++i) {
    const DistantSource& d = scene.distant[i];
    const Material& m = scene.materials[d.material];
    if (m.type != MaterialType::kLight || d.halfAngleRad > degToRad(2.5)) continue;
    const double normalLux = luminanceFromRadiance(m.color) * kPi * std::pow(std::sin(d.halfAngleRad), 2);
    if (normalLux <= best) continue;
    best = normalLux;
    dome.sceneSun = static_cast<int>(i);
    dome.sunDirModel = d.direction;
    dome.horizontalSunLux = normalLux * std::max(0.0, d.direction.z);
  }
  if (dome.sceneSun < 0 && f.sunDirection())
    dome.sunDirModel = trueToModel(glm::normalize(*f.sunDirection()), dome.northDeg);
  const AzAlt aa = azAltFromDirection(dome.sunDirModel, dome.northDeg);
  dome.sunAltitudeDeg = aa.altitudeDeg;
  dome.sunAzimuthDeg = aa.azimuthDeg;
  scene.sky = dome;
}

}  // namespace candela
