// The `dielectric` material: the Fresnel and Snell functions against closed forms, a clear slab
// under a uniform sky against the slab's hemispherical transmittance integrated numerically
// (written here independently of the engine: the trigonometric form of Fresnel's equations,
// Simpson's rule), and the Radiance reader's handling of the primitive and its errors.
#include "engine/fresnel.h"
#include "engine/radiance/reader.h"
#include "engine/tracer.h"
#include "photometry/sky_model.h"
#include "photometry/make_sky.h"
#include "engine/irradiance_estimator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace candela {
namespace {


// ---------------------------------------------------------------- Fresnel and Snell

TEST(Dielectric, NormalIncidenceReflectance) {
  // R = ((n − 1)/(n + 1))² at normal incidence, from either side (eta and 1/eta).
  for (double n : {1.33, 1.5, 2.4}) {
    const double want = (n - 1.0) * (n - 1.0) / ((n + 1.0) * (n + 1.0));
    EXPECT_NEAR(fresnelReflectance(1.0, n), want, 1e-15) << n;
    EXPECT_NEAR(fresnelReflectance(1.0, 1.0 / n), want, 1e-15) << n;
    const Fresnel f = fresnel(1.0, n);
    EXPECT_NEAR(f.rs, f.rp, 1e-15);
    EXPECT_FALSE(f.tir);
    EXPECT_NEAR(f.cosT, 1.0, 1e-15);
  }
}

TEST(Dielectric, BrewsterAngleHasNoPReflection) {
  // At Brewster's angle tan θB = eta the p component vanishes; θi + θt = 90°, so the s
  // component is sin²(θi − θt) / sin²(θi + θt) = sin²(2θB − 90°) = cos²(2θB).
  for (double eta : {1.5, 1.0 / 1.5}) {
    const double thetaB = std::atan(eta);
    const Fresnel f = fresnel(std::cos(thetaB), eta);
    EXPECT_NEAR(f.rp, 0.0, 1e-15) << eta;
    EXPECT_NEAR(f.rs, std::pow(std::cos(2.0 * thetaB), 2), 1e-14) << eta;
    EXPECT_NEAR(f.cosT, std::sin(thetaB), 1e-14) << eta;  // θt = 90° − θB
  }
}

TEST(Dielectric, TotalInternalReflectionBeyondTheCriticalAngle) {
  // From glass (n = 1.5) into air, eta = 1/1.5: critical angle asin(1/1.5) = 41.8°.
  const double eta = 1.0 / 1.5, thetaC = std::asin(eta);
  for (double dTheta : {1e-6, 0.01, 0.3}) {
    const Fresnel f = fresnel(std::cos(thetaC + dTheta), eta);
    EXPECT_TRUE(f.tir) << dTheta;
    EXPECT_EQ(f.unpolarised(), 1.0) << dTheta;
  }
  const Fresnel below = fresnel(std::cos(thetaC - 0.01), eta);
  EXPECT_FALSE(below.tir);
  EXPECT_LT(below.unpolarised(), 1.0);
  EXPECT_GT(below.unpolarised(), fresnelReflectance(1.0, eta));
}

TEST(Dielectric, ReflectanceIsTheSameFromBothSidesOfOneRay) {
  // Stokes reciprocity: a ray refracted from θi into θt reflects the same fraction as the
  // reverse ray (θt, 1/eta); and the trigonometric forms R_s = sin²(θi−θt)/sin²(θi+θt),
  // R_p = tan²(θi−θt)/tan²(θi+θt) (Born & Wolf 1.5.2) agree with the engine's algebraic ones.
  const double eta = 1.5;
  for (double deg : {5.0, 30.0, 56.3, 70.0, 89.0}) {
    const double ti = degToRad(deg);
    const Fresnel f = fresnel(std::cos(ti), eta);
    const double tt = std::acos(f.cosT);
    EXPECT_NEAR(std::sin(tt), std::sin(ti) / eta, 1e-14) << deg;
    EXPECT_NEAR(f.rs, std::pow(std::sin(ti - tt) / std::sin(ti + tt), 2), 1e-13) << deg;
    EXPECT_NEAR(f.rp, std::pow(std::tan(ti - tt) / std::tan(ti + tt), 2), 1e-13) << deg;
    const Fresnel back = fresnel(f.cosT, 1.0 / eta);
    EXPECT_NEAR(back.rs, f.rs, 1e-13) << deg;
    EXPECT_NEAR(back.rp, f.rp, 1e-13) << deg;
  }
  EXPECT_NEAR(fresnelReflectance(0.0, eta), 1.0, 1e-15);  // grazing
}

TEST(Dielectric, RefractedDirectionObeysSnell) {
  const Vec3 nf(0, 0, 1);  // facing the incoming ray, which travels downwards
  for (double eta : {1.5, 1.0 / 1.5}) {
    for (double deg : {0.0, 20.0, 40.0}) {
      const double ti = degToRad(deg);
      const Vec3 d = glm::normalize(Vec3(std::sin(ti) * 0.6, std::sin(ti) * 0.8, -std::cos(ti)));
      const Fresnel f = fresnel(std::cos(ti), eta);
      ASSERT_FALSE(f.tir);
      const Vec3 t = refractDirection(d, nf, eta, f.cosT);
      EXPECT_NEAR(glm::length(t), 1.0, 1e-14);
      EXPECT_NEAR(-t.z, f.cosT, 1e-14);
      EXPECT_NEAR(std::hypot(t.x, t.y), std::sin(ti) / eta, 1e-14);  // Snell
      EXPECT_NEAR(t.x * 0.8 - t.y * 0.6, 0.0, 1e-14);                  // plane of incidence kept
    }
  }
}

// ---------------------------------------------------------------- a slab under the sky

// Hemispherical transmittance of a clear slab (index n, thickness dM, transmission tau per
// metre) for uniform radiance from one side, 2 ∫ T(θ) cos θ sin θ dθ over [0, π/2], with
// T(θ) = (1 − R)² a / (1 − R² a²), a = tau^(dM / cos θt): incoherent multiple reflections between
// the two faces, R the unpolarised Fresnel reflectance (trigonometric form), as the engine models
// each reflection. Composite Simpson, 20000 intervals (the integrand is smooth).
double slabHemisphericalTransmittance(double n, double dM, double tau) {
  auto integrand = [&](double ti) {
    const double st = std::sin(ti) / n, tt = std::asin(st);
    double r = 0.0;
    if (ti < 1e-8) {
      r = (n - 1.0) * (n - 1.0) / ((n + 1.0) * (n + 1.0));
    } else if (ti >= 0.5 * kPi) {
      r = 1.0;
    } else {
      const double rs = std::pow(std::sin(ti - tt) / std::sin(ti + tt), 2);
      const double rp = std::pow(std::tan(ti - tt) / std::tan(ti + tt), 2);
      r = 0.5 * (rs + rp);
    }
    const double a = std::pow(tau, dM / std::cos(tt));
    const double t = (1.0 - r) * (1.0 - r) * a / (1.0 - r * r * a * a);
    return t * std::cos(ti) * std::sin(ti);
  };
  const int k = 20000;
  const double h = 0.5 * kPi / k;
  double sum = integrand(0.0) + integrand(0.5 * kPi);
  for (int i = 1; i < k; ++i) sum += (i % 2 ? 4.0 : 2.0) * integrand(i * h);
  return 2.0 * sum * h / 3.0;
}

TEST(Dielectric, SlabUnderTheSkyTransmitsItsHemisphericalTransmittance) {
  // A 10 cm slab (n = 1.5, transmission 0.2 per metre) 1 m above a sensor facing up, 2 km wide
  // (the uncovered rim is ~1e-6 of the cosine-weighted hemisphere), under a uniform sky: a glow
  // `source` (found by the hemisphere rays only) and a daylight sky dome (also sampled by its
  // luminance, MIS: the refracted rays must count it in full, since shadow rays cannot pass a
  // dielectric). E = E_open · T_h. Nothing below the sensor, so light the slab reflects escapes.
  const double n = 1.5, dM = 0.1, tau = 0.2;
  const double th = slabHemisphericalTransmittance(n, dM, tau);
  std::printf("[ measured ] slab hemispherical transmittance (numerical) %.6f\n", th);
  for (bool dome : {false, true}) {
    Scene sc;
    double open = 0.0;
    if (dome) {
      SkyConditions cond;
      cond.diffuseHorizontalLux = 10000.0;
      SkyDome d;
      d.model = makeSky({SkyKind::kUniform}, cond);
      d.horizontalSkyLux = cond.diffuseHorizontalLux;
      sc.sky = d;
      open = cond.diffuseHorizontalLux;
    } else {
      Material glow;
      glow.type = MaterialType::kGlow;
      glow.name = "sky";
      glow.color = Rgb(1.0);
      sc.addDistant(Vec3(0, 0, 1), 180.0, sc.addMaterial(glow), "sky");
      open = kLumensPerWatt * kPi * 1.0;
    }
    Material m;
    m.type = MaterialType::kDielectric;
    m.name = "slab";
    m.color = Rgb(tau);
    m.refractiveIndex = n;
    const uint32_t slab = sc.addMaterial(m);
    const double w = 1e3, z0 = 1.0, z1 = 1.0 + dM;
    sc.addPolygon({{-w, -w, z0}, {-w, w, z0}, {w, w, z0}, {w, -w, z0}}, slab);  // faces down (out)
    sc.addPolygon({{-w, -w, z1}, {w, -w, z1}, {w, w, z1}, {-w, w, z1}}, slab);  // faces up (out)
    const Tracer tracer(sc);
    TraceSettings s;
    s.hemisphereSamples = 4096;
    const IrradianceEstimate e = estimateIrradiance(tracer, Vec3(0, 0, 0), Vec3(0, 0, 1), dome ? 1 : 0, s);
    const double want = open * th, got = e.illuminanceLux(), se = e.standardErrorLux();
    std::printf("[ measured ] slab under a %s: %.6g ± %.3g lux, reference %.6g lux (open sky %.6g)\n",
                dome ? "sky dome" : "glow sky", got, se, want, open);
    EXPECT_GT(se, 0.0);
    EXPECT_NEAR(got, want, 4.0 * se);
    EXPECT_NEAR(got, want, 0.02 * want);
  }
}

TEST(Dielectric, AbsorbsPerChannelAlongThePathInside) {
  // Near-normal incidence: a distant glow disk (60° across, radiance 1) straight above, seen
  // through a 0.5 m slab whose transmission per metre differs per channel: per channel
  // E_c = ∫disk T_c(θ) cos θ dω with a = tau_c^(d / cos θt), found by the hemisphere rays.
  const double n = 1.5, dM = 0.5;
  const Rgb tau(0.2, 0.5, 0.9);
  Scene sc;
  Material glow;
  glow.type = MaterialType::kGlow;
  glow.name = "disk";
  glow.color = Rgb(1.0);
  const double fullDeg = 60.0;
  sc.addDistant(Vec3(0, 0, 1), fullDeg, sc.addMaterial(glow), "disk");
  Material m;
  m.type = MaterialType::kDielectric;
  m.name = "slab";
  m.color = tau;
  m.refractiveIndex = n;
  const uint32_t slab = sc.addMaterial(m);
  const double w = 1e3, z0 = 1.0, z1 = 1.0 + dM;
  sc.addPolygon({{-w, -w, z0}, {-w, w, z0}, {w, w, z0}, {w, -w, z0}}, slab);
  sc.addPolygon({{-w, -w, z1}, {w, -w, z1}, {w, w, z1}, {-w, w, z1}}, slab);
  const Tracer tracer(sc);
  TraceSettings s;
  s.hemisphereSamples = 8192;
  const IrradianceEstimate e = estimateIrradiance(tracer, Vec3(0, 0, 0), Vec3(0, 0, 1), 0, s);
  // Over the 5° half-angle disk, the integral of T(θ) cos θ dω, by the slab function above
  // restricted to the disk: Simpson over [0, 5°].
  const double half = degToRad(0.5 * fullDeg);
  for (int c = 0; c < 3; ++c) {
    auto integrand = [&](double ti) {
      const double tt = std::asin(std::sin(ti) / n);
      const double r = ti < 1e-8 ? std::pow((n - 1.0) / (n + 1.0), 2)
                                 : 0.5 * (std::pow(std::sin(ti - tt) / std::sin(ti + tt), 2) +
                                          std::pow(std::tan(ti - tt) / std::tan(ti + tt), 2));
      const double a = std::pow(tau[c], dM / std::cos(tt));
      return (1.0 - r) * (1.0 - r) * a / (1.0 - r * r * a * a) * std::cos(ti) * std::sin(ti);
    };
    const int k = 2000;
    const double h = half / k;
    double sum = integrand(0.0) + integrand(half);
    for (int i = 1; i < k; ++i) sum += (i % 2 ? 4.0 : 2.0) * integrand(i * h);
    const double want = kTwoPi * sum * h / 3.0;  // W/m² per unit radiance
    std::printf("[ measured ] channel %d: %.6g W/m², reference %.6g W/m² (photopic standard error %.2g %%)\n", c,
                e.irradiance[c], want, 100.0 * e.standardErrorLux() / e.illuminanceLux());
    // The channels share the paths (only the absorption differs), so the photopic standard
    // error scaled to the channel is a fair yardstick; 3 % is the loose bound.
    const double se = e.standardErrorLux() / kLumensPerWatt * want / std::max(1e-300, photopic(e.irradiance));
    EXPECT_NEAR(e.irradiance[c], want, 4.0 * se + 1e-12) << c;
    EXPECT_NEAR(e.irradiance[c], want, 0.03 * want) << c;
  }
}

TEST(Dielectric, ShadowRaysDoNotPass) {
  Scene sc;
  Material m;
  m.type = MaterialType::kDielectric;
  m.name = "slab";
  m.color = Rgb(1.0);
  m.refractiveIndex = 1.5;
  const uint32_t slab = sc.addMaterial(m);
  sc.addPolygon({{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}}, slab);
  const Tracer tracer(sc);
  EXPECT_EQ(photopic(tracer.transmittance(Vec3(0, 0, 0), Vec3(0, 0, 1), 2.0, kNoShape, kNoShape)), 0.0);
  EXPECT_EQ(photopic(tracer.transmittance(Vec3(0, 0, 0), Vec3(0, 0, 1), 0.5, kNoShape, kNoShape)), 1.0);
}

}  // namespace
}  // namespace candela
