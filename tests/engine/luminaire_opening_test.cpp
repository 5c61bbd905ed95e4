// A luminaire's opening as a surface (engine/luminaire_opening.h): it hides what lies beyond it
// from the room, and lets its own luminaire's light through.
#include "engine/luminaire_opening.h"
#include "engine/lights.h"
#include "engine/tracer.h"
#include "validation/analytic.h"

#include "tests/engine/lambertian_panel.h"
#include "engine/irradiance_estimator.h"

#include <gtest/gtest.h>

namespace candela {
namespace {

// A 0.6 m Lambertian panel 2.5 m up, facing down (it sends nothing upwards).
Scene panelScene(std::optional<double> openingReflectance) {
  Scene sc;
  LuminaireMounting m;
  m.name = "P";
  m.positionM = {0, 0, 2.5};
  sc.luminaires.push_back(placeLuminaire(test_support::lambertianPanel(1000.0, 0.6, 0.6, 1), m));
  if (openingReflectance) addOpeningSurface(sc, 0, *openingReflectance);
  return sc;
}

TEST(LuminaireOpening, IsAnOpaqueDiffuseRectangleInTheOpeningPlane) {
  Scene sc = panelScene(0.3);
  ASSERT_EQ(sc.shapes.size(), 1u);
  EXPECT_EQ(sc.luminaires[0].openingShape, 0u);
  const Shape& s = sc.shapes[0];
  EXPECT_NEAR(shapeArea(s, sc.vertices), 0.36, 1e-12);
  EXPECT_NEAR(glm::dot(s.n, Vec3(0, 0, -1)), 1.0, 1e-12);  // facing the nadir
  EXPECT_NEAR(glm::dot(s.n, sc.vertices.points[s.firstVertex]), -2.5, 1e-12);
  const Material& mat = sc.materials[s.material];
  EXPECT_EQ(mat.type, MaterialType::kPlastic);
  EXPECT_DOUBLE_EQ(photopic(mat.diffuseReflectance), 0.3);
  EXPECT_DOUBLE_EQ(photopic(mat.specularReflectance), 0.0);
  EXPECT_EQ(collectLights(sc)[0].ownShape, 0u);  // its luminaire's shadow rays pass it
}

TEST(LuminaireOpening, APointLuminaireHasNoOpeningToAdd) {
  Scene sc;
  sc.luminaires.push_back(placeLuminaire(test_support::lambertianPanel(1000.0, 0.0, 0.0), LuminaireMounting{}));
  EXPECT_EQ(addOpeningSurface(sc, 0, 0.5), kNoShape);
  EXPECT_TRUE(sc.shapes.empty());
}

// A sensor 0.5 m above the opening, facing down, over a uniform Lambertian floor source (6 m
// square, radiance 1 W/sr/m², 3 m below it): without the surface it receives L · PSA(floor); a
// black opening hides the part of the floor behind it, L · PSA(opening) — the opening's shadow
// from the sensor (±2.4 m on the floor) lies within the floor source, and the panel sends no
// light upwards, so E = L · (PSA(floor) − PSA(opening)) exactly (Lambert's formula for both).
TEST(LuminaireOpening, BlackOpeningHidesTheFloorFromTheCeilingBehindIt) {
  const Vec3 p(0.1, 0.05, 3.0), down(0, 0, -1);
  const std::vector<Vec3> floor = {{-3, -3, 0}, {3, -3, 0}, {3, 3, 0}, {-3, 3, 0}};
  const std::vector<Vec3> opening = {{-0.3, -0.3, 2.5}, {0.3, -0.3, 2.5}, {0.3, 0.3, 2.5}, {-0.3, 0.3, 2.5}};
  const double lumensPerWattWhite = kLumensPerWatt * photopic(Rgb(1.0));
  const double open = lumensPerWattWhite * polygonProjectedSolidAngle(floor, p, down);
  const double hidden = lumensPerWattWhite * polygonProjectedSolidAngle(opening, p, down);
  ASSERT_GT(hidden, 0.2 * open);  // the opening hides a good part of the floor
  for (const std::optional<double> rho : {std::optional<double>(), std::optional<double>(0.0)}) {
    Scene sc = panelScene(rho);
    Material lamp;
    lamp.type = MaterialType::kLight;
    lamp.color = Rgb(1.0);
    sc.addPolygon(floor, sc.addMaterial(lamp));  // counter-clockwise from above: faces up
    const Tracer tracer(sc);
    TraceSettings s;
    s.lightSamples = 4096;
    const IrradianceEstimate e = estimateIrradiance(tracer, p, down, 0, s);
    const double want = rho ? open - hidden : open;
    EXPECT_NEAR(e.illuminanceLux(), want, 4.0 * e.standardErrorLux() + 1e-9 * want)
        << (rho ? "black opening" : "no opening surface");
  }
}

// The panel's own light passes its opening surface: below it, near and far, the illuminance is
// Lambert's for the 0.6 m square of luminance I0/A (the surface is lit by nothing: its own
// panel's light runs along its plane).
TEST(LuminaireOpening, OwnLightPassesTheOpeningSurface) {
  const Scene sc = panelScene(0.5);
  const Tracer tracer(sc);
  TraceSettings s;
  s.lightSamples = 4096;
  const double luminance = 1000.0 / 0.36;
  for (auto [x, h] : {std::pair{0.2, 0.5}, {0.0, 3.5}}) {
    const IrradianceEstimate e = estimateIrradiance(tracer, {x, 0.0, 2.5 - h}, {0, 0, 1}, 0, s);
    const double want = analytic::rectangleAbove(luminance, {-0.3, -0.3, 0.3, 0.3}, h, x, 0.0);
    EXPECT_NEAR(e.illuminanceLux(), want, 4.0 * e.standardErrorLux() + 1e-4 * want) << "h " << h;
  }
}

}  // namespace
}  // namespace candela
