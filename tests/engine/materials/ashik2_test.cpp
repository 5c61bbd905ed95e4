// ashik2 (Ashikhmin-Shirley) against closed forms: the sampler's density against the formula it
// claims (moments and the fraction of samples kept), the reflected light of an infinite plane
// under a uniform sky against a quadrature of the BRDF written out here from the paper and
// Radiance's m_ashikhmin (not the code under test), the u direction through its transform, and
// the refusals at their line.
#include "engine/irradiance_estimator.h"
#include "engine/materials/ashikhmin.h"
#include "engine/materials/pattern_hook.h"
#include "engine/radiance/reader.h"
#include "engine/tracer.h"
#include "tests/support/material_harness.h"
#include "tests/support/temp_files.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace candela {
namespace {

namespace fs = std::filesystem;

// The BRDF's specular part (without its colour) for the viewer at polar angles (tv, pv) and the
// light at (tl, pl) about the normal z, u along x: Ashikhmin & Shirley 2000, eq. 4, with
// Radiance's max(cos θ_l, cos θ_v) (dirashik) and the Fresnel term taken out.
double specularBrdf(double tv, double pv, double tl, double pl, double nu, double nv) {
  const Vec3 wi(std::sin(tv) * std::cos(pv), std::sin(tv) * std::sin(pv), std::cos(tv));
  const Vec3 wo(std::sin(tl) * std::cos(pl), std::sin(tl) * std::sin(pl), std::cos(tl));
  const Vec3 h = glm::normalize(wi + wo);
  const double hx = h.x, hy = h.y, hz = h.z;
  const double e = (nu * hx * hx + nv * hy * hy) / std::max(1e-300, 1.0 - hz * hz);
  return std::sqrt((nu + 1) * (nv + 1)) / (8 * kPi) * std::pow(hz, e) /
         (glm::dot(wo, h) * std::max(std::cos(tl), std::max(0.001, std::cos(tv))));
}

// ∫ f cos θ_l dω_l over the upper hemisphere by the midpoint rule (n × 4n cells).
double albedo(double tv, double pv, double nu, double nv, int n = 200) {
  double sum = 0.0;
  const double dt = 0.5 * kPi / n, dp = kTwoPi / (4 * n);
  for (int i = 0; i < n; ++i) {
    const double tl = (i + 0.5) * dt;
    for (int j = 0; j < 4 * n; ++j)
      sum += specularBrdf(tv, pv, tl, (j + 0.5) * dp, nu, nv) * std::cos(tl) * std::sin(tl);
  }
  return sum * dt * dp;
}

AshikhminLobe lobe(double nu, double nv) {
  MaterialParameters m;
  m.exponentU = nu;
  m.exponentV = nv;
  m.anisotropyU = Vec3(1.0, 0.0, 0.3);  // not in the surface: projected
  return ashikhminLobe(m, glm::normalize(Vec3(-0.5, 0.2, -1.0)), Vec3(0, 0, 1));
}

// E_p[g/q] = ∫ g dω for the sampler's true density p only if p is the density q it claims: with
// g = f cos (the directional albedo, by the quadrature above) and g = q·[cos θ_o > 0] (the
// fraction of samples that stay above the surface, by quadrature of q). 200 000 samples; each
// within 4 standard errors.
TEST(Ashikhmin, SamplerDrawsTheDensityItClaims) {
  const double nu = 20.0, nv = 5.0;
  const AshikhminLobe l = lobe(nu, nv);
  const Vec3 wi = glm::normalize(Vec3(0.5, -0.2, 1.0));
  const double tv = std::acos(wi.z), pv = std::atan2(wi.y, wi.x);
  Rng rng(3, 0);
  const int count = 200000;
  double sum = 0.0, sq = 0.0;
  int kept = 0;
  for (int i = 0; i < count; ++i) {
    Vec3 wo;
    if (!sampleAshikhmin(l, wi, rng.uniform(), rng.uniform(), wo)) continue;
    ++kept;
    const double g = ashikhminSpecular(l, wi, wo) * wo.z / ashikhminDensity(l, wi, wo);
    sum += g;
    sq += g * g;
  }
  const double mean = sum / count, se = std::sqrt((sq / count - mean * mean) / count);
  EXPECT_NEAR(mean, albedo(tv, pv, nu, nv), 4.0 * se);
  // The fraction kept against ∫ q dω over the upper hemisphere.
  double q = 0.0;
  const int n = 300;
  const double dt = 0.5 * kPi / n, dp = kTwoPi / (4 * n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < 4 * n; ++j) {
      const double t = (i + 0.5) * dt, p = (j + 0.5) * dp;
      q += ashikhminDensity(l, wi, Vec3(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t))) *
           std::sin(t);
    }
  q *= dt * dp;
  const double frac = static_cast<double>(kept) / count;
  EXPECT_NEAR(frac, q, 4.0 * std::sqrt(q * (1.0 - q) / count) + 1e-3);
  EXPECT_LE(q, 1.0 + 1e-3);
}

// The half vector's azimuth: more of the lobe lies across u when nu > nv. Chi-square of the
// sampled φ_h in 16 bins against the marginal density √((nu+1)(nv+1))/(2π(nu cos²φ + nv sin²φ +
// 1)) (the paper's eq. 6 integrated over θ_h) at normal incidence.
TEST(Ashikhmin, HalfVectorAzimuthFollowsItsMarginal) {
  const double nu = 40.0, nv = 4.0;
  const AshikhminLobe l = lobe(nu, nv);
  const Vec3 wi(0, 0, 1);
  const int bins = 16, count = 160000;
  std::vector<double> observed(bins, 0.0);
  Rng rng(5, 0);
  for (int i = 0; i < count; ++i) {
    Vec3 wo;
    sampleAshikhmin(l, wi, rng.uniform(), rng.uniform(), wo);  // at normal incidence none is lost
    const Vec3 h = glm::normalize(wi + wo);
    double phi = std::atan2(glm::dot(h, l.v), glm::dot(h, l.u));
    if (phi < 0) phi += kTwoPi;
    observed[std::min(bins - 1, static_cast<int>(phi / kTwoPi * bins))] += 1.0;
  }
  double chi2 = 0.0;
  for (int b = 0; b < bins; ++b) {
    double p = 0.0;
    const int steps = 1000;
    for (int s = 0; s < steps; ++s) {
      const double phi = (b + (s + 0.5) / steps) * kTwoPi / bins;
      p += std::sqrt((nu + 1) * (nv + 1)) / (kTwoPi * (nu * std::cos(phi) * std::cos(phi) +
                                                       nv * std::sin(phi) * std::sin(phi) + 1.0));
    }
    const double expected = p / steps * kTwoPi / bins * count;
    chi2 += (observed[b] - expected) * (observed[b] - expected) / expected;
  }
  EXPECT_LT(chi2, 37.7);  // the 0.1 % point of chi-square with 15 degrees of freedom
}

constexpr double kSkyLux = test_support::kUniformSkyLux;

// dir/u.cal gives u along x; the scene with the uniform sky when `sky`.
Scene readIn(const std::string& name, const std::string& text, bool sky = true) {
  const fs::path dir = test_support::scratchDir("ashik2", name);
  std::ofstream(dir / "u.cal") << "ux = 1; uy = 0; uz = 0;\n";
  return test_support::readSceneText(dir, text, sky);
}

const std::string kPlane = test_support::infinitePlane("a", 0.0, true);

// An infinite plane under a uniform sky of luminance L = E/π over a black ground, seen by a
// sensor 2 m above facing down: E_s = L ∫ cos θ_v [π ρ_d + s'(θ_v) R(θ_v, φ_v)] dω_v, R the
// specular albedo above and s' = s + (1 − s)(1 − cos θ_v)⁵ (Radiance's Fresnel at the viewer).
double expectedLux(double rhoD, double s, double nu, double nv) {
  const int n = 24;
  double sum = 0.0;
  const double dt = 0.5 * kPi / n, dp = 0.5 * kPi / n;  // a quarter of azimuths: the lobe is symmetric
  for (int i = 0; i < n; ++i) {
    const double tv = (i + 0.5) * dt, c = std::cos(tv);
    const double sp = s + (1.0 - s) * std::pow(1.0 - c, 5);
    for (int j = 0; j < n; ++j)
      sum += 4.0 * c * std::sin(tv) * sp * albedo(tv, (j + 0.5) * dp, nu, nv, 120) * dt * dp;
  }
  return kSkyLux / kPi * (kPi * rhoD + sum);
}

void expectLux(const Scene& sc, double want, const std::string& what) {
  TraceSettings st;
  st.seed = 2;
  st.hemisphereSamples = 8192;
  st.maxBounces = 2;
  const IrradianceEstimate e = estimateIrradiance(Tracer(sc), Vec3(0.3, 0.2, 2.0), Response::planar(Vec3(0, 0, -1)), 0, st);
  EXPECT_NEAR(e.illuminanceLux(), want, 4.0 * e.standardErrorLux()) << what;
  EXPECT_LT(e.standardErrorLux(), 0.01 * want) << what;
}

TEST(Ashik2, PlaneUnderAUniformSkyReflectsItsQuadrature) {
  const double want = expectedLux(0.3, 0.2, 20.0, 5.0);
  expectLux(readIn("lobe", "void ashik2 a 4 ux uy uz u.cal 0 8 .3 .3 .3 .2 .2 .2 20 5\n" + kPlane), want,
            "diffuse and lobe");
  // Turned 90° about z the lobe is the same over the plane (the sky is uniform).
  expectLux(readIn("turned", "void ashik2 a 6 ux uy uz u.cal -rz 90 0 8 .3 .3 .3 .2 .2 .2 20 5\n" + kPlane), want,
            "turned");
  // A black specular colour has no Fresnel term (Radiance's): the diffuse part alone.
  expectLux(readIn("matte", "void ashik2 a 4 ux uy uz u.cal 0 8 .3 .3 .3 0 0 0 20 5\n" + kPlane), 0.3 * kSkyLux,
            "diffuse only");
  // The diffuse part takes the pattern's colour; the specular part does not.
  expectLux(readIn("pattern", "void brightfunc half 2 .5 . 0 0\nhalf ashik2 a 4 ux uy uz u.cal 0 8 .3 .3 .3 .2 .2 "
                              ".2 20 5\n" + kPlane),
            want - 0.15 * kSkyLux, "pattern on the diffuse part");
}

// Radiance's dirashik: a sampled source's light on the diffuse part takes 1 − (1 − cos θ_l)⁵ of
// its own angle, the view none. A sun 75° from the zenith over the plane (the factor 0.776), no
// sky; a sensor 2 m up facing down, tilted 45° away from the sun so that the lobe's image of the
// sun (exponents 1000: within a few degrees of the mirror direction) is behind it:
//   E = ρ_d/π (1 − (1 − cos 75°)⁵) E_sun ∫ (n·ω) dω over the plane's directions it sees.
// Without the factor the sensor reads 29 % more.
TEST(Ashik2, SourcesLightTheDiffusePartWithTheirOwnFresnelFactor) {
  const double zenDeg = 75.0, tilt = degToRad(45.0);
  const Scene sc = readIn("dirashik",
                          test_support::distantSun(zenDeg) + "void ashik2 a 4 ux uy uz u.cal 0 8 .3 .3 .3 .1 .1 .1 1000 1000\n" +
                              kPlane,
                          false);
  const Vec3 n(0.0, -std::sin(tilt), -std::cos(tilt));
  const double seen = test_support::belowHorizonIntegral(n, [](double) { return 1.0; });
  const double want = 0.3 * kInvPi * (1.0 - std::pow(1.0 - std::cos(degToRad(zenDeg)), 5)) *
                      test_support::sunLux(zenDeg) * seen;
  TraceSettings st;
  st.seed = 2;
  st.hemisphereSamples = 8192;
  st.maxBounces = 2;
  const IrradianceEstimate e = estimateIrradiance(Tracer(sc), Vec3(0.3, 0.2, 2.0), Response::planar(n), 0, st);
  EXPECT_NEAR(e.illuminanceLux(), want, 4.0 * e.standardErrorLux());
  EXPECT_LT(e.standardErrorLux(), 0.01 * want);
}

TEST(Ashik2, DirectionThroughItsTransformAndFresnelAtTheViewer) {
  const fs::path dir = test_support::scratchDir("ashik2", "read");
  std::ofstream(dir / "u.cal") << "ux = 1; uy = 0; uz = 0;\n";
  std::ofstream(dir / "scene.rad") << "void ashik2 a 6 ux uy uz u.cal -rz 90 0 8 .5 .4 .3 .1 .2 .3 100 10\n"
                                      "a polygon p 0 0 12 0 0 0 1 0 0 1 1 0 0 1 0\n";
  Scene sc;
  readRadianceFile(dir / "scene.rad", sc);
  ASSERT_EQ(sc.materials.size(), 1u);
  const Material& m = sc.materials[0];
  EXPECT_EQ(m.type, MaterialType::kAshik2);
  PatternEvaluator eval(sc);
  Material out;
  const Vec3 d = glm::normalize(Vec3(0.0, 1.0, -1.0));  // 45° from the normal
  const Material& at = patterned(sc, m, {Vec3(0.5, 0.5, 0.0), d, Vec3(0, 0, 1), 1.0}, eval, out);
  EXPECT_NEAR(at.anisotropyU.y, 1.0, 1e-12);
  const double f = std::pow(1.0 - std::sqrt(0.5), 5);
  EXPECT_NEAR(at.specularReflectance.x, 0.1 + 0.9 * f, 1e-12);
  EXPECT_NEAR(at.specularReflectance.z, 0.3 + 0.7 * f, 1e-12);
  EXPECT_NEAR(at.diffuseReflectance.y, 0.4, 1e-15);
}

std::string errorOf(const std::string& name, const std::string& text) {
  try {
    readIn(name, text + "a polygon p 0 0 9 0 0 0 1 0 0 0 1 0\n");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Ashik2, RefusalsNameTheirLineAndReason) {
  EXPECT_NE(errorOf("reals", "\nvoid ashik2 a 4 ux uy uz u.cal 0 6 .3 .3 .3 .2 .2 .2\n")
                .find("scene.rad:2: ashik2 'a' needs 8 real arguments, got 6"),
            std::string::npos);
  EXPECT_NE(errorOf("strings", "void ashik2 a 2 ux u.cal 0 8 .3 .3 .3 .2 .2 .2 20 5\n")
                .find("scene.rad:1: ashik2 'a' needs 4 or more string arguments"),
            std::string::npos);
  EXPECT_NE(errorOf("colour", "void ashik2 a 4 ux uy uz u.cal 0 8 .3 .3 .3 .2 1.2 .2 20 5\n")
                .find("scene.rad:1: ashik2 'a' reflects more than it receives"),
            std::string::npos);
  EXPECT_NE(errorOf("exponent", "void ashik2 a 4 ux uy uz u.cal 0 8 .3 .3 .3 .2 .2 .2 -1 5\n")
                .find("scene.rad:1: ashik2 'a' needs its u and v exponents at least 0"),
            std::string::npos);
  EXPECT_NE(errorOf("undefined", "void ashik2 a 4 ux uy wz u.cal 0 8 .3 .3 .3 .2 .2 .2 20 5\n").find("scene.rad:1:"),
            std::string::npos);
}

}  // namespace
}  // namespace candela
