// The closed-form harness of the material tests (tests/engine/materials/): an infinite plane of a
// material, a distant sun as a Radiance light source, a uniform sky over a black ground, and the
// lower hemisphere's integral that a tilted sensor above a plane sees.
#pragma once

#include "base/math.h"
#include "base/units.h"
#include "engine/daylight.h"
#include "engine/radiance/reader.h"
#include "engine/scene.h"
#include "photometry/sky_type.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

namespace candela::test_support {

inline constexpr double kSunRadiance = 1e5;  // W/sr/m²
inline constexpr double kSunDeg = 0.5;       // the disc's full angle
inline constexpr double kUniformSkyLux = 10000.0;

inline double sunSolidAngle() { return kTwoPi * (1.0 - std::cos(degToRad(kSunDeg / 2))); }
// The sun's illuminance on a horizontal plane at zenith angle zenithDeg.
inline double sunLux(double zenithDeg) {
  return kLumensPerWatt * kSunRadiance * sunSolidAngle() * std::cos(degToRad(zenithDeg));
}

// The sun at zenith angle zenithDeg (towards +y), as a distant light source.
inline std::string distantSun(double zenithDeg) {
  const double t = degToRad(zenithDeg);
  const std::string l = std::to_string(kSunRadiance);
  return "void light sunl 0 0 3 " + l + " " + l + " " + l + "\nsunl source sun 0 0 4 0 " + std::to_string(std::sin(t)) +
         " " + std::to_string(std::cos(t)) + " " + std::to_string(kSunDeg) + "\n";
}

// An infinite plane of `material` at height z, its front facing up (or down).
inline std::string infinitePlane(const std::string& material, double z, bool up, const std::string& name = "plane") {
  const std::string h = std::to_string(z);
  return material + " polygon " + name + " 0 0 12 -1e4 -1e4 " + h + (up ? "  1e4 -1e4 " : "  -1e4 1e4 ") + h +
         "  1e4 1e4 " + h + (up ? "  -1e4 1e4 " : "  1e4 -1e4 ") + h + "\n";
}

// A uniform sky of `lux` on the horizontal over a black ground.
inline void addUniformSky(Scene& sc, double lux = kUniformSkyLux) {
  DaylightSpec d;
  d.skyType = parseSkyType("uniform").value();
  d.diffuseHorizontalLux = lux;
  d.groundReflectance = 0.0;
  addDaylight(sc, d);
}

// dir/scene.rad holding `text`, read; with the uniform sky when `sky`.
inline Scene readSceneText(const std::filesystem::path& dir, const std::string& text, bool sky) {
  std::ofstream(dir / "scene.rad") << text;
  Scene sc;
  readRadianceFile(dir / "scene.rad", sc);
  if (sky) addUniformSky(sc);
  return sc;
}

// ∫ weight(|ω_z|) (n·ω) dω over the directions ω below the horizon with n·ω > 0 (what a sensor of
// normal n above a plane sees of it), by the midpoint rule on 400 × 800 cells.
template <class Weight>
double belowHorizonIntegral(const Vec3& n, Weight weight) {
  const int nt = 400, np = 800;
  double sum = 0.0;
  for (int i = 0; i < nt; ++i) {
    const double t = kPi / 2 + (i + 0.5) * (kPi / 2) / nt;
    for (int j = 0; j < np; ++j) {
      const double ph = (j + 0.5) * kTwoPi / np;
      const Vec3 w(std::sin(t) * std::cos(ph), std::sin(t) * std::sin(ph), std::cos(t));
      const double c = glm::dot(n, w);
      if (c > 0.0) sum += weight(std::abs(w.z)) * c * std::sin(t);
    }
  }
  return sum * (kPi / 2 / nt) * (kTwoPi / np);
}

}  // namespace candela::test_support
