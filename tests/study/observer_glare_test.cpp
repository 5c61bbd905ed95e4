// UGR at an [[observer]] (study/view_glare.h luminaireGlare), against a hand calculation of
// CIE 117's formula for a single luminaire under a uniform background.
#include "study/view_glare.h"

#include "engine/luminaire_source.h"
#include "engine/tracer.h"
#include "tests/engine/lambertian_panel.h"
#include "engine/irradiance_estimator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace candela {
namespace {

// Guth's position index in the IES closed form, written out here from the angles of the source:
// σ from the line of sight, τ the angle of the plane through the line of sight and the source
// from the vertical (both in degrees).
double guth(double sigmaDeg, double tauDeg) {
  const double lnP = (35.2 - 0.31889 * tauDeg - 1.22 * std::exp(-2.0 * tauDeg / 9.0)) * 1e-3 * sigmaDeg +
                     (21.0 + 0.26667 * tauDeg - 0.002963 * tauDeg * tauDeg) * 1e-5 * sigmaDeg * sigmaDeg;
  return std::exp(lnP);
}

// A Lambertian 0.6 m × 0.6 m panel (I = 1000 cd · cos γ, so L = 1000/0.36 cd/m² from every
// direction) 1.6 m above a seated eye, 3 m ahead and 0.5 m to the right; the background a uniform
// 360° glow of 20 cd/m², so that Lb (the indirect vertical illuminance over π) is 20 cd/m².
// UGR = 8 log10(0.25/Lb · L² ω / P²) with ω = A cos γ / d².
TEST(ObserverGlare, SingleLuminaireAgainstAHandCalculation) {
  Scene sc;
  const double lg = 20.0;
  Material glow;
  glow.type = MaterialType::kGlow;
  glow.name = "background";
  glow.color = Rgb(lg / kLumensPerWatt);
  sc.addDistant({0.0, 0.0, 1.0}, 360.0, sc.addMaterial(glow), "background");
  LuminaireMounting lp;
  lp.positionM = {0.5, 3.0, 2.8};
  sc.luminaires.push_back(placeLuminaire(test_support::lambertianPanel(1000.0, 0.6, 0.6, 1), lp));
  const Tracer tracer(sc);
  ObserverSpec o;
  o.positionM = {0.0, 0.0};
  o.eyeHeightM = 1.2;
  o.direction = {0.0, 1.0};
  TraceSettings s;
  s.lightSamples = 1024;
  s.hemisphereSamples = 256;
  const LuminaireGlare g = luminaireGlare(tracer, observerView(o), s, kObserverStreamBase);
  ASSERT_EQ(g.sources.size(), 1u);

  const Vec3 d(0.5, 3.0, 1.6);
  const double dist = glm::length(d), cosG = 1.6 / dist;
  const double l = 1000.0 / 0.36, omega = 0.36 * cosG / (dist * dist);
  const double sigma = radToDeg(std::acos(3.0 / dist)), tau = radToDeg(std::atan2(0.5, 1.6));
  const double p = guth(sigma, tau);
  // The web is tabulated every degree: I interpolated within 4e-5 of 1000 cos γ.
  EXPECT_NEAR(g.sources[0].luminanceCdM2, l, 1e-4 * l);
  EXPECT_NEAR(g.sources[0].solidAngleSr, omega, 1e-12);
  EXPECT_NEAR(g.sources[0].positionIndex, p, 1e-9 * p);
  // Lb: the eye's vertical illuminance (estimated) less the panel's direct share (integrated over
  // its opening), over π. Its error: 4 standard errors of the estimate and the direct share's
  // 2e-3 (Render.EyeLightSeparatesDirectFromIndirect).
  const IrradianceEstimate est = estimateIrradiance(tracer, o.eyeM(), Vec3(0.0, 1.0, 0.0), kObserverStreamBase, s);
  const double direct = g.verticalLux - kPi * lg;
  const double lbTolerance = (4.0 * est.standardErrorLux() + 2e-3 * direct) / kPi;
  EXPECT_NEAR(g.backgroundCdM2, lg, lbTolerance);
  const double want = 8.0 * std::log10(0.25 / lg * l * l * omega / (p * p));
  // UGR moves 8/ln 10 ≈ 3.47 per unit relative change of Lb, and 2 × that of L.
  const double tolerance = 8.0 / std::log(10.0) * (lbTolerance / lg + 2e-4);
  std::printf("[ measured ] one panel: UGR %.3f (hand %.3f, ±%.3f), Lb %.3f cd/m² (%.0f)\n", g.ugr, want, tolerance,
              g.backgroundCdM2, lg);
  EXPECT_NEAR(g.ugr, want, tolerance);
  // And nothing behind the observer counts: turned round, no luminaire in view.
  o.direction = {0.0, -1.0};
  EXPECT_TRUE(luminaireGlare(tracer, observerView(o), s, kObserverStreamBase).sources.empty());
}

}  // namespace
}  // namespace candela
