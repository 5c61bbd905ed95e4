// Light that reaches a diffuse point through a flat mirror and a `trans` sheet with specular
// transmission, in either order, and sky light through such a sheet: each must be counted once.
// The flat mirror's virtual sources (Tracer::mirrorIrradiance) and the path tracer both see
// these paths, so each scene is checked against its geometric unfolding, which has no mirror
// (and so no virtual sources): everything a point in front of the mirror sees through it is
// there instead, so both scenes give the same irradiance. Sky through a sheet is checked against
// its closed form. Monte Carlo results are compared within 4 combined standard errors (a 4σ miss
// has probability ~6e-5; seeds are fixed), plus a loose relative bound.
#include "engine/tracer.h"
#include "photometry/sky_model.h"
#include "tests/engine/test_materials.h"
#include "photometry/make_sky.h"
#include "engine/irradiance_estimator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace candela {
namespace {

using test_support::addMaterial;

// A clear sheet: trans with colour tau, no specularity, all light transmitted specularly, so its
// specular transmittance is tau and it neither reflects nor scatters.
uint32_t addClearTrans(Scene& sc, double tau) {
  Material m;
  m.type = MaterialType::kTrans;
  m.name = "clear";
  m.color = Rgb(tau);
  m.transmissivity = 1.0;
  m.transmittedSpecular = 1.0;
  return sc.addMaterial(m);
}

void addUpRect(Scene& sc, double x0, double y0, double x1, double y1, double z, uint32_t mat) {
  sc.addPolygon({{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}}, mat);
}
// A wall in the plane x = const, y ∈ [y0, y1], z ∈ [z0, z1], facing −x.
void addWallX(Scene& sc, double x, double y0, double y1, double z0, double z1, uint32_t mat) {
  sc.addPolygon({{x, y0, z0}, {x, y0, z1}, {x, y1, z1}, {x, y1, z0}}, mat);
}

// The mirror wall scene of tracer_test.cpp (grey floor ρ 0.5 on x ∈ [−1, 1], a 1 cm lamp of
// radiance 2e4 at (0.5, 0, 1), a perfect mirror wall at x = 1) with a clear sheet (τ = 0.6).
// sheetNearLamp: a horizontal sheet at z = 0.9 under the lamp, x ∈ [0.2, 0.999], so light from
// the lamp reaches the floor through the sheet and then, or directly, the mirror (paths
// diffuse → mirror → trans → lamp). Otherwise: a vertical sheet at x = 0.9 in front of the whole
// mirror, crossed on the way to the mirror and back (diffuse → trans → mirror → trans → lamp).
// Unfolded: no mirror; floor, lamp and sheet reflected in the plane x = 1 are added.
Scene mirrorTransScene(bool unfolded, bool sheetNearLamp) {
  Scene sc;
  const uint32_t lamp = addMaterial(sc, MaterialType::kLight, 2e4, "lamp");
  const uint32_t grey = addMaterial(sc, MaterialType::kPlastic, 0.5, "grey");
  const uint32_t clear = addClearTrans(sc, 0.6);
  sc.addSphere(Vec3(0.5, 0, 1), 0.01, lamp);
  if (sheetNearLamp) {
    addUpRect(sc, 0.2, -0.4, 0.999, 0.4, 0.9, clear);
  } else {
    addWallX(sc, 0.9, -1.5, 1.5, 0.0, 3.0, clear);
  }
  if (unfolded) {
    addUpRect(sc, -1, -1, 3, 1, 0, grey);
    sc.addSphere(Vec3(1.5, 0, 1), 0.01, lamp);
    if (sheetNearLamp) {
      addUpRect(sc, 1.001, -0.4, 1.8, 0.4, 0.9, clear);
    } else {
      addWallX(sc, 1.1, -1.5, 1.5, 0.0, 3.0, clear);
    }
  } else {
    addUpRect(sc, -1, -1, 1, 1, 0, grey);
    const uint32_t mirror = addMaterial(sc, MaterialType::kMirror, 1.0, "mirror");
    addWallX(sc, 1.0, -1.5, 1.5, 0.0, 3.0, mirror);
  }
  return sc;
}

void expectFoldedEqualsUnfolded(bool sheetNearLamp, const char* what) {
  const Scene a = mirrorTransScene(false, sheetNearLamp), b = mirrorTransScene(true, sheetNearLamp);
  const Tracer ta(a), tb(b);
  TraceSettings s;
  s.hemisphereSamples = 1024;
  // Points in front of the sheet and the mirror: on the floor facing up, and above it facing
  // down and towards the mirror.
  const std::vector<std::pair<Vec3, Vec3>> pts = {
      {{-0.5, 0.0, 0.01}, {0, 0, 1}}, {{0.3, 0.5, 0.01}, {0, 0, 1}}, {{0.0, 0.3, 2.0}, {0, 0, -1}},
      {{0.6, -0.2, 0.5}, {1, 0, 0}}};
  for (size_t i = 0; i < pts.size(); ++i) {
    const IrradianceEstimate ea = estimateIrradiance(ta, pts[i].first, pts[i].second, i, s);
    const IrradianceEstimate eb = estimateIrradiance(tb, pts[i].first, pts[i].second, i + 100, s);
    // Where both are exact (direct light and images only: floor points facing up see nothing
    // else), a floor of 1e-9 relative for rounding (two closed forms by different routes).
    const double tol = 4.0 * std::hypot(ea.standardErrorLux(), eb.standardErrorLux()) + 1e-9 * eb.illuminanceLux();
    std::printf("[ measured ] %s, point %zu: mirror %.5g ± %.2g lux, unfolded %.5g ± %.2g lux\n", what, i,
                ea.illuminanceLux(), ea.standardErrorLux(), eb.illuminanceLux(), eb.standardErrorLux());
    EXPECT_NEAR(ea.illuminanceLux(), eb.illuminanceLux(), tol) << what << ", point " << i;
    EXPECT_NEAR(ea.illuminanceLux(), eb.illuminanceLux(), 0.03 * eb.illuminanceLux()) << what << ", point " << i;
  }
}

TEST(MirrorTrans, MirrorThenTransEqualsTheUnfoldedScene) {
  expectFoldedEqualsUnfolded(true, "diffuse -> mirror -> trans -> lamp");
}

TEST(MirrorTrans, TransThenMirrorEqualsTheUnfoldedScene) {
  expectFoldedEqualsUnfolded(false, "diffuse -> trans -> mirror -> trans -> lamp");
}

TEST(MirrorTrans, SkyThroughASheetIsCountedOnce) {
  // A uniform sky of horizontal illuminance E_h above a clear sheet (τ = 0.6) that covers it to
  // within 1e-4 rad of the horizon: a sensor below facing up receives τ E_h (the uncovered rim
  // adds ~1e-8 E_h). The sky is sampled both by its luminance (shadow rays through the sheet) and
  // by the hemisphere rays, combined by MIS: the rays through the sheet must keep their MIS
  // weight. Equal light and hemisphere sample counts make the MIS weights far from 0 and 1.
  Scene sc;
  SkyConditions cond;
  cond.diffuseHorizontalLux = 10000.0;
  SkyDome dome;
  dome.model = makeSky({SkyKind::kUniform}, cond);
  dome.horizontalSkyLux = cond.diffuseHorizontalLux;
  sc.sky = dome;
  const double tau = 0.6;
  addUpRect(sc, -1e4, -1e4, 1e4, 1e4, 1.0, addClearTrans(sc, tau));
  const Tracer tracer(sc);
  TraceSettings s;
  s.hemisphereSamples = 256;
  s.lightSamples = 256;
  const IrradianceEstimate e = estimateIrradiance(tracer, Vec3(0, 0, 0), Vec3(0, 0, 1), 0, s);
  const double want = tau * cond.diffuseHorizontalLux;
  std::printf("[ measured ] sky through a clear sheet: %.6g ± %.2g lux, reference %.6g lux\n", e.illuminanceLux(),
              e.standardErrorLux(), want);
  EXPECT_NEAR(e.illuminanceLux(), want, 4.0 * e.standardErrorLux() + 1e-6 * want);
  EXPECT_NEAR(e.illuminanceLux(), want, 0.02 * want);
}

}  // namespace
}  // namespace candela
