// The BSDF and aBSDF materials (engine/materials/bsdf.cpp) against closed forms, with scattering
// functions defined here (the XML files' reader has tests of its own): a horizontal window of
// infinite extent at height 1 under a uniform sky or a sun, a sensor below it.
//   - A Lambertian transmitter f = τ/π: the window's luminance is τ E_v/π everywhere, so a sensor
//     facing it reads τ E_v (the sun: exact, every path sees the same; the sky: within 4 standard
//     errors), and a vertical sensor τ E_v/2.
//   - f = k cos θ_out (k = 3τ/2π, hemispherical τ): the same horizontal reading, a vertical one of
//     τ E_v/π instead of τ E_v/2: the direction of the light leaving is the function's.
//   - A transmitter sampled with a density far from its value stays unbiased.
//   - A Lambertian reflector ρ/π facing up as a floor: a sensor facing it reads ρ E_v.
//   - aBSDF with a direct part of 0.6: the sun and the sky straight through, 0.6 E.
// And read from LBNL XML files written by the test (tests/engine/bsdf_test_xml.h): a Lambertian
// Klems transmitter (τE exactly), clear glass as a diagonal Klems matrix (aBSDF: its peak straight
// through, τE exactly; BSDF: the sun spread over its patch, τE within 4 standard errors).
// The window's edge is 1e4 m away: what it leaves of the hemisphere changes readings by < 1e-7.
#include "engine/bsdf.h"
#include "engine/irradiance_estimator.h"
#include "engine/materials/family.h"
#include "engine/materials/pattern_hook.h"
#include "engine/render.h"
#include "tests/support/test_views.h"
#include "engine/radiance/reader.h"
#include "engine/tracer.h"
#include "tests/engine/bsdf_test_xml.h"
#include "tests/support/material_harness.h"
#include "tests/support/temp_files.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>

namespace candela {
namespace {

namespace fs = std::filesystem;

// A scattering function given by f(in, out) in local coordinates, drawn cosine-weighted on the
// side `drawOn` asks (so that a draw's density differs from f's shape), with an optional direct
// part.
class TestBsdf final : public Bsdf {
 public:
  using F = std::function<double(const Vec3& in, const Vec3& out)>;
  // albedo(out, transmitted): ∫ f |cos in| d(in) over the side, in closed form (each test checks
  // it against quadrature, albedoByQuadrature).
  using A = std::function<double(const Vec3& out, bool transmitted)>;
  TestBsdf(F f, A albedo, double peak = 0.0) : f_(std::move(f)), albedo_(std::move(albedo)), peak_(peak) {}
  Rgb eval(const Vec3& in, const Vec3& out, bool) const override { return Rgb(f_(in, out)); }
  bool sampleIn(const Vec3& out, const Vec2& u, double pick, Sample& s, bool) const override {
    // Each side with probability 1/2, cosine-weighted on it.
    const double side = pick < 0.5 ? 1.0 : -1.0;
    const double r = std::sqrt(u.x), phi = kTwoPi * u.y;
    s.in = Vec3(r * std::cos(phi), r * std::sin(phi), side * std::sqrt(std::max(0.0, 1.0 - u.x)));
    s.pdf = 0.5 * std::abs(s.in.z) * kInvPi;
    if (!(s.pdf > 0.0)) return false;
    s.weight = Rgb(f_(s.in, out) * std::abs(s.in.z) / s.pdf);
    return true;
  }
  double pdfIn(const Vec3& in, const Vec3&, bool) const override { return 0.5 * std::abs(in.z) * kInvPi; }
  Rgb albedoToward(const Vec3& out, bool transmitted, bool) const override { return Rgb(albedo_(out, transmitted)); }
  Rgb hemispherical(const Vec3& in, bool transmitted) const override { return Rgb(albedo_(in, transmitted)); }
  Rgb peakThrough(const Vec3&) const override { return Rgb(peak_); }
  bool reflects(bool) const override { return true; }
  bool transmits() const override { return true; }
  std::string kind() const override { return "test"; }

  // ∫ f |cos in| d(in) over the side by a midpoint rule in (cos θ, φ), 200 × 200 cells.
  double albedoByQuadrature(const Vec3& out, bool transmitted) const {
    double sum = 0.0;
    const int n = 200;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double mu = (i + 0.5) / n, phi = kTwoPi * (j + 0.5) / n, st = std::sqrt(1.0 - mu * mu);
        const double z = ((out.z > 0.0) != transmitted) ? mu : -mu;
        sum += f_(Vec3(st * std::cos(phi), st * std::sin(phi), z), out) * mu;
      }
    return sum * kTwoPi / (n * n);
  }
  void expectAlbedoAsQuadrature() const {
    for (const Vec3& out : {Vec3(0, 0, 1), Vec3(0.6, 0, 0.8), Vec3(0, -0.8, -0.6)})
      for (bool t : {false, true}) EXPECT_NEAR(albedo_(out, t), albedoByQuadrature(out, t), 1e-4);
  }

 private:
  F f_;
  A albedo_;
  double peak_;
};

constexpr double kSkyLux = test_support::kUniformSkyLux;
using test_support::sunLux;
using test_support::sunSolidAngle;

std::string sun(double zenithDeg) { return test_support::distantSun(zenithDeg); }

// A plane at height z of material `material` (a trans stand-in the test turns into the BSDF),
// its normal down (the room below: Radiance's BSDF normal points into the room) or up.
std::string plane(double z, bool up) { return test_support::infinitePlane("stand", z, up, "window"); }

// The scene with the stand-in turned into `type` (BSDF or aBSDF) with scattering b.
Scene window(const std::string& name, const std::string& text, const Bsdf& b, MaterialType type, bool sky) {
  const fs::path dir = test_support::scratchDir("bsdf_material", name);
  std::ofstream(dir / "scene.rad") << "void trans stand 0 0 7 .5 .5 .5 0 0 .5 0\n" << text;
  Scene sc;
  readRadianceFile(dir / "scene.rad", sc);
  for (Material& m : sc.materials)
    if (m.name == "stand") {
      m.type = type;
      m.bsdf = &b;
      m.color = m.backColor = m.transmissionColor = Rgb(0.0);
      deriveMaterial(m);
      m.anisotropyU = Vec3(0.0, 1.0, 0.0);
    }
  if (sky) test_support::addUniformSky(sc);
  return sc;
}

IrradianceEstimate measure(const Scene& sc, const Vec3& at, const Vec3& n, int samples = 4096) {
  TraceSettings s;
  s.seed = 5;
  s.hemisphereSamples = samples;
  s.maxBounces = 3;
  return estimateIrradiance(Tracer(sc), at, Response::planar(n), 0, s);
}

void expectWithin4Se(const IrradianceEstimate& e, double want, const std::string& what) {
  EXPECT_NEAR(e.illuminanceLux(), want, 4.0 * e.standardErrorLux() + 1e-6 * want) << what;
  EXPECT_LT(e.standardErrorLux(), 0.02 * want) << what;  // the test can fail: the error is small
}

const Vec3 kUp(0, 0, 1), kDown(0, 0, -1), kEast(1, 0, 0);
const Vec3 kBelow(0.3, 0.2, 0.0), kAbove(0.3, 0.2, 2.0);

// Transmission only, on opposite sides.
double lambertT(const Vec3& in, const Vec3& out, double tau) { return (in.z > 0.0) != (out.z > 0.0) ? tau * kInvPi : 0.0; }
const TestBsdf kLambert([](const Vec3& in, const Vec3& out) { return lambertT(in, out, 0.5); },
                        [](const Vec3&, bool t) { return t ? 0.5 : 0.0; });

TEST(BsdfMaterial, TheTestFunctionsAlbedosAreTheirIntegrals) { kLambert.expectAlbedoAsQuadrature(); }

TEST(BsdfMaterial, LambertianTransmitterUnderTheSunGivesTauEExactly) {
  const TestBsdf& b = kLambert;
  for (double zen : {0.0, 35.0}) {
    const Scene sc = window("sun" + std::to_string(int(zen)), sun(zen) + plane(1.0, false), b, MaterialType::kBsdf, false);
    const double e = measure(sc, kBelow, kUp).illuminanceLux();
    EXPECT_NEAR(e, 0.5 * sunLux(zen), 1e-4 * sunLux(zen)) << zen;
    // A vertical sensor sees the window's uniform luminance τE/π over a quarter sphere: τE/2.
    const IrradianceEstimate v = measure(sc, kBelow, kEast);
    EXPECT_NEAR(v.illuminanceLux(), 0.25 * sunLux(zen), 4.0 * v.standardErrorLux() + 1e-4 * sunLux(zen)) << zen;
  }
}

TEST(BsdfMaterial, LambertianTransmitterUnderAUniformSkyGivesTauE) {
  const TestBsdf& b = kLambert;
  const Scene sc = window("sky", plane(1.0, false), b, MaterialType::kBsdf, true);
  expectWithin4Se(measure(sc, kBelow, kUp), 0.5 * kSkyLux, "horizontal");
  expectWithin4Se(measure(sc, kBelow, kEast), 0.25 * kSkyLux, "vertical");
}

TEST(BsdfMaterial, TheLightLeavesInTheFunctionsDirections) {
  // f = k cos θ_out towards the room, k = 3τ/2π: hemispherical τ; a horizontal sensor reads τE,
  // a vertical one τE/π (a Lambertian window: τE/2).
  const double tau = 0.5, k = 3.0 * tau / kTwoPi;
  const TestBsdf b([k](const Vec3& in, const Vec3& out) { return (in.z > 0.0) != (out.z > 0.0) ? k * std::abs(out.z) : 0.0; },
                   [k](const Vec3& out, bool t) { return t ? k * std::abs(out.z) * kPi : 0.0; });
  b.expectAlbedoAsQuadrature();
  const Scene sun0 = window("cosout", sun(0.0) + plane(1.0, false), b, MaterialType::kBsdf, false);
  EXPECT_NEAR(measure(sun0, kBelow, kUp).illuminanceLux(), tau * sunLux(0.0), 1e-4 * sunLux(0.0));
  const IrradianceEstimate v = measure(sun0, kBelow, kEast);
  EXPECT_NEAR(v.illuminanceLux(), tau * sunLux(0.0) / kPi, 4.0 * v.standardErrorLux() + 1e-6 * sunLux(0.0));
  EXPECT_LT(v.standardErrorLux(), 0.01 * sunLux(0.0));
  // Under the sky the same, the sky's light arriving only by the paths drawn from the function.
  const Scene sky = window("cosout-sky", plane(1.0, false), b, MaterialType::kBsdf, true);
  expectWithin4Se(measure(sky, kBelow, kUp), tau * kSkyLux, "sky horizontal");
  expectWithin4Se(measure(sky, kBelow, kEast), tau * kSkyLux / kPi, "sky vertical");
}

TEST(BsdfMaterial, AFunctionOfTheIncomingDirectionIsTakenAtTheSourcesDirection) {
  // f = c (cos θ_in)² transmitted: the sun at zenith angle θ gives the window the luminance
  // c cos² θ E_sun,n cos θ … and a horizontal sensor π times it.
  const double c = 0.3;
  const TestBsdf b([c](const Vec3& in, const Vec3& out) { return (in.z > 0.0) != (out.z > 0.0) ? c * in.z * in.z : 0.0; },
                   [c](const Vec3&, bool t) { return t ? c * kPi / 2.0 : 0.0; });
  b.expectAlbedoAsQuadrature();
  for (double zen : {0.0, 50.0}) {
    const Scene sc = window("cosin" + std::to_string(int(zen)), sun(zen) + plane(1.0, false), b, MaterialType::kBsdf, false);
    const double cz = std::cos(degToRad(zen));
    EXPECT_NEAR(measure(sc, kBelow, kUp).illuminanceLux(), kPi * c * cz * cz * sunLux(zen), 1e-4 * sunLux(zen)) << zen;
  }
}

TEST(BsdfMaterial, LambertianReflectorGivesRhoE) {
  const TestBsdf b([](const Vec3& in, const Vec3& out) { return (in.z > 0.0) == (out.z > 0.0) ? 0.4 * kInvPi : 0.0; },
                   [](const Vec3&, bool t) { return t ? 0.0 : 0.4; });
  b.expectAlbedoAsQuadrature();
  // A floor at 0 facing up; the sensor at 2 m facing it.
  const Scene sunny = window("floor-sun", sun(30.0) + plane(0.0, true), b, MaterialType::kBsdf, false);
  EXPECT_NEAR(measure(sunny, kAbove, kDown).illuminanceLux(), 0.4 * sunLux(30.0), 1e-4 * sunLux(30.0));
  const Scene sky = window("floor-sky", plane(0.0, true), b, MaterialType::kBsdf, true);
  expectWithin4Se(measure(sky, kAbove, kDown), 0.4 * kSkyLux, "sky");
}

// Two scattering surfaces facing each other, light caught between them: a diffusing window at 1
// (τ = 0.4 through, ρ = 0.5 back on the room side) over a reflecting floor of ρ₂ = 0.8, both
// BSDF. The floor's irradiance sums the series of reflections between them,
// E₂ = τ E_sky / (1 − ρ ρ₂) = 2/3 E_sky, and a sensor facing the floor reads ρ₂ E₂ = 0.5333 E_sky:
// the paths that go back and forth end by Russian roulette after two scattering vertices in a
// row (engine/integrator_path.cpp), unbiased.
TEST(BsdfMaterial, LightCaughtBetweenTwoScatteringSurfacesIsTheSeries) {
  const TestBsdf window([](const Vec3& in, const Vec3& out) {
                          if ((in.z > 0.0) != (out.z > 0.0)) return 0.4 * kInvPi;
                          return out.z > 0.0 ? 0.5 * kInvPi : 0.0;  // the room side (the normal's) reflects
                        },
                        [](const Vec3& out, bool t) { return t ? 0.4 : (out.z > 0.0 ? 0.5 : 0.0); });
  const TestBsdf floor([](const Vec3& in, const Vec3& out) { return (in.z > 0.0) == (out.z > 0.0) ? 0.8 * kInvPi : 0.0; },
                       [](const Vec3&, bool t) { return t ? 0.0 : 0.8; });
  window.expectAlbedoAsQuadrature();
  floor.expectAlbedoAsQuadrature();
  const fs::path dir = test_support::scratchDir("bsdf_material", "caught");
  std::ofstream(dir / "scene.rad") << "void trans stand 0 0 7 .5 .5 .5 0 0 .5 0\n"
                                      "void trans floor_stand 0 0 7 .5 .5 .5 0 0 .5 0\n"
                                   << plane(1.0, false) << test_support::infinitePlane("floor_stand", 0.0, true, "floor");
  Scene sc;
  readRadianceFile(dir / "scene.rad", sc);
  for (Material& m : sc.materials) {
    if (m.name != "stand" && m.name != "floor_stand") continue;
    m.type = MaterialType::kBsdf;
    m.bsdf = m.name == "stand" ? static_cast<const Bsdf*>(&window) : static_cast<const Bsdf*>(&floor);
    m.color = m.backColor = m.transmissionColor = Rgb(0.0);
    deriveMaterial(m);
    m.anisotropyU = Vec3(0.0, 1.0, 0.0);
  }
  test_support::addUniformSky(sc);
  TraceSettings s;
  s.seed = 7;
  s.hemisphereSamples = 4096;
  s.maxBounces = kUnlimitedBounces;
  const IrradianceEstimate e = estimateIrradiance(Tracer(sc), Vec3(0.3, 0.2, 0.5), Response::planar(kDown), 0, s);
  expectWithin4Se(e, 0.8 * 0.4 / (1.0 - 0.5 * 0.8) * kSkyLux, "between");
}

TEST(BsdfMaterial, ABsdfLetsItsDirectPartStraightThrough) {
  // Nothing scattered, 0.6 straight through: the sun and the sky at 0.6 of their light.
  const TestBsdf b([](const Vec3&, const Vec3&) { return 0.0; }, [](const Vec3&, bool) { return 0.0; }, 0.6);
  const Scene sunny = window("absdf-sun", sun(35.0) + plane(1.0, false), b, MaterialType::kABsdf, false);
  EXPECT_NEAR(measure(sunny, kBelow, kUp).illuminanceLux(), 0.6 * sunLux(35.0), 1e-4 * sunLux(35.0));
  const Scene sky = window("absdf-sky", plane(1.0, false), b, MaterialType::kABsdf, true);
  expectWithin4Se(measure(sky, kBelow, kUp), 0.6 * kSkyLux, "sky");
  // BSDF stops shadow rays: the same function as a BSDF lets nothing through.
  const Scene stopped = window("bsdf-stops", sun(35.0) + plane(1.0, false), b, MaterialType::kBsdf, false);
  EXPECT_EQ(measure(stopped, kBelow, kUp).illuminanceLux(), 0.0);
}

// A window of material `material` (a BSDF or aBSDF line naming w.xml) at height 1, normal down
// (into the room below), with w.xml holding `xml`.
Scene xmlWindow(const std::string& name, const std::string& xml, const std::string& material, const std::string& text,
                bool sky) {
  const fs::path dir = test_support::scratchDir("bsdf_xml_window", name);
  std::ofstream(dir / "w.xml") << xml;
  return test_support::readSceneText(dir, material + "\n" + text + plane(1.0, false), sky);
}

constexpr int kFull = 145;

TEST(BsdfMaterial, LambertianKlemsFileGivesTauE) {
  using test_support::bsdfXml;
  const std::string xml = bsdfXml({{"Transmission Front", std::vector<double>(kFull * kFull, 0.5 / kPi)}});
  const std::string bsdf = "void BSDF stand 6 0 w.xml 0 1 0 . 0 0";
  const Scene sunny = xmlWindow("lambert-sun", xml, bsdf, sun(35.0), false);
  EXPECT_NEAR(measure(sunny, kBelow, kUp).illuminanceLux(), 0.5 * sunLux(35.0), 1e-4 * sunLux(35.0));
  expectWithin4Se(measure(xmlWindow("lambert-sky", xml, bsdf, "", true), kBelow, kUp), 0.5 * kSkyLux, "sky");
  // The file is listed with the files the scene read.
  ASSERT_EQ(sunny.functionFiles.size(), 1u);
  EXPECT_NE(sunny.functionFiles[0].find("w.xml"), std::string::npos);
}

// Half the light absorbed: every draw of a path meeting the window goes on, its weight the
// half the file passes (Σ f Λ over the Klems patches = τ), instead of ending every other path.
TEST(BsdfMaterial, APathGoesOnThroughAnAbsorbingFileCarryingItsAlbedo) {
  using test_support::bsdfXml;
  const std::string xml = bsdfXml({{"Transmission Front", std::vector<double>(kFull * kFull, 0.5 / kPi)},
                                   {"Transmission Back", std::vector<double>(kFull * kFull, 0.5 / kPi)}});
  const Scene sc = xmlWindow("lambert-draws", xml, "void BSDF stand 6 0 w.xml 0 1 0 . 0 0", "", false);
  const Material* m = nullptr;
  for (const Material& x : sc.materials)
    if (x.name == "stand") m = &x;
  ASSERT_NE(m, nullptr);
  Rng rng(3, 0);
  double sum = 0.0;
  const int n = 2000;
  for (const Vec3 d : {Vec3(0.0, 0.0, 1.0), glm::normalize(Vec3(0.3, -0.2, -1.0))}) {
    const PatternPoint at{Vec3(0.3, 0.2, 1.0), d, Vec3(0.0, 0.0, -1.0), 1.0};
    for (int i = 0; i < n; ++i) {
      ScatterSample s;
      ASSERT_TRUE(familyOf(*m).sampleScattering(*m, at, Vec2(rng.uniform(), rng.uniform()), rng, s)) << i;
      EXPECT_TRUE(s.transmitted);
      EXPECT_GT(s.dir.z * d.z, 0.0);  // on through, to the far side
      EXPECT_NEAR(photopic(s.weight), 0.5, 1e-3) << i;
      sum += photopic(s.weight);
    }
  }
  EXPECT_NEAR(sum / (2 * n), 0.5, 1e-3);
}

TEST(BsdfMaterial, ClearGlassKlemsFile) {
  using test_support::bsdfXml;
  using test_support::klemsFullLambda;
  std::vector<double> m(kFull * kFull, 0.0);
  for (int k = 0; k < kFull; ++k) m[static_cast<size_t>(k * kFull + k)] = 0.8 / klemsFullLambda(k);
  const std::string xml = bsdfXml({{"Transmission Front", m}});
  // aBSDF: the whole 0.8 is the direct part, the sun straight through.
  const Scene peak = xmlWindow("clear-absdf", xml, "void aBSDF stand 5 w.xml 0 1 0 . 0 0", sun(35.0), false);
  EXPECT_NEAR(measure(peak, kBelow, kUp).illuminanceLux(), 0.8 * sunLux(35.0), 1e-4 * sunLux(35.0));
  // BSDF: the sun's light leaves over the patch the matrix sends it to, 0.8 of it in all.
  const Scene spread = xmlWindow("clear-bsdf", xml, "void BSDF stand 6 0 w.xml 0 1 0 . 0 0", sun(35.0), false);
  const IrradianceEstimate e = measure(spread, kBelow, kUp, 65536);
  EXPECT_NEAR(e.illuminanceLux(), 0.8 * sunLux(35.0), 4.0 * e.standardErrorLux());
  EXPECT_LT(e.standardErrorLux(), 0.05 * sunLux(35.0));
}

// A BSDF with a thickness is a proxy: the camera's primary rays pass it and show what lies behind
// (a glow of radiance 10 here, seen through a proxy plane facing the camera), with the camera's
// surface estimates and with plain paths alike; sensors' rays still meet it (its Lambertian
// transmission gives a sensor above it τ times the glow's light).
TEST(BsdfMaterial, AProxyShowsTheCameraWhatLiesBehindIt) {
  using test_support::bsdfXml;
  const std::string xml = bsdfXml({{"Transmission Front", std::vector<double>(kFull * kFull, 0.5 / kPi)}});
  const fs::path dir = test_support::scratchDir("bsdf_xml_window", "proxy");
  std::ofstream(dir / "w.xml") << xml;
  // The proxy at z = 1 facing up (towards the camera at z = 3), the glow at z = 0 facing up.
  std::ofstream(dir / "scene.rad")
      << "void BSDF proxy 6 0.5 w.xml 0 1 0 . 0 0\n"
         "proxy polygon p 0 0 12 -1e4 -1e4 1  1e4 -1e4 1  1e4 1e4 1  -1e4 1e4 1\n"
         "void glow g 0 0 4 10 10 10 0\n"
         "g polygon floor 0 0 12 -1e4 -1e4 0  1e4 -1e4 0  1e4 1e4 0  -1e4 1e4 0\n";
  Scene sc;
  readRadianceFile(dir / "scene.rad", sc);
  const Tracer tracer(sc);
  TraceSettings s;
  s.maxBounces = 2;
  const View v = test_support::makeView(ViewType::kPerspective, {0, 0, 3}, {0, 0, -1}, {0, 1, 0}, {40, 40}, 5, 5);
  const double want = kLumensPerWatt * 10.0;
  for (int samples : {0, 64}) {
    RenderSettings r;
    r.irradianceSamples = samples;
    const Image img = renderView(tracer, v, s, 2, r);
    for (std::size_t i = 0; i < img.luminance.size(); ++i) EXPECT_NEAR(img.luminance[i], want, 1e-9 * want) << i;
  }
  // A sensor above it facing down: the proxy's transmitted glow, τ·10 W/sr/m² over its whole
  // hemisphere (paths end by Russian roulette with probability 1 − τ: within 4 standard errors).
  expectWithin4Se(measure(sc, Vec3(0.3, 0.2, 2.0), kDown), kPi * kLumensPerWatt * 5.0, "sensor");
}

}  // namespace
}  // namespace candela
