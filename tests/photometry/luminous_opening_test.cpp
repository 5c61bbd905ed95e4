#include "photometry/luminous_opening.h"

#include "photometry/eulumdat.h"
#include "photometry/ies_lm63.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace candela {
namespace {

PhotometricInfo opening(OpeningShape shape, double w, double l, double h) {
  PhotometricInfo info;
  info.openingShape = shape;
  info.openingWidthM = w;
  info.openingLengthM = l;
  info.openingHeightM = h;
  return info;
}

// A direction γ from the nadir in the plane C (degrees), as photometric_web.h's axes.
Vec3 dir(double cDeg, double gammaDeg) { return PhotometricWeb::directionOf(cDeg, gammaDeg); }

TEST(LuminousOpening, FlatShapesShrinkWithTheCosineOfGamma) {
  const PhotometricInfo rect = opening(OpeningShape::kRectangular, 0.6, 1.2, 0.0);
  EXPECT_NEAR(projectedOpeningAreaM2(rect, dir(0, 0)), 0.72, 1e-12);
  EXPECT_NEAR(projectedOpeningAreaM2(rect, dir(30, 60)), 0.36, 1e-12);  // cos 60° = 1/2, any C
  EXPECT_NEAR(projectedOpeningAreaM2(rect, 5.0 * dir(0, 60)), 0.36, 1e-12);  // any length
  const PhotometricInfo disc = opening(OpeningShape::kCircular, 0.2, 0.2, 0.0);
  EXPECT_NEAR(projectedOpeningAreaM2(disc, dir(77, 60)), 0.5 * kPi * 0.01, 1e-12);
  EXPECT_NEAR(projectedOpeningAreaM2(opening(OpeningShape::kEllipse, 0.2, 0.4, 0.0), dir(0, 0)), kPi * 0.02, 1e-12);
  EXPECT_EQ(projectedOpeningAreaM2(opening(OpeningShape::kPoint, 0, 0, 0), dir(0, 30)), 0.0);
}

TEST(LuminousOpening, LuminousSidesAddTheirProjections) {
  // Box 0.6 (X) × 1.2 (Y) × 0.1 (Z) seen at γ = 60° in C0: bottom 0.72 cos 60°, the face normal
  // to X (1.2 × 0.1) times sin 60°, the faces normal to Y edge-on.
  const PhotometricInfo box = opening(OpeningShape::kRectangularWithSides, 0.6, 1.2, 0.1);
  EXPECT_NEAR(projectedOpeningAreaM2(box, dir(0, 60)), 0.72 * 0.5 + 0.12 * std::sqrt(0.75), 1e-12);
  EXPECT_NEAR(projectedOpeningAreaM2(box, dir(90, 60)), 0.72 * 0.5 + 0.06 * std::sqrt(0.75), 1e-12);
  // Vertical cylinder, diameter 0.3, height 0.2: disc cos γ plus the rectangle d·h sin γ.
  const PhotometricInfo cyl = opening(OpeningShape::kVerticalCylinder, 0.3, 0.3, 0.2);
  EXPECT_NEAR(projectedOpeningAreaM2(cyl, dir(40, 60)), kPi * 0.0225 * 0.5 + 0.06 * std::sqrt(0.75), 1e-12);
  // Its elliptical form with equal axes is the same cylinder.
  const PhotometricInfo ecyl = opening(OpeningShape::kVerticalEllipticalCylinder, 0.3, 0.3, 0.2);
  EXPECT_NEAR(projectedOpeningAreaM2(ecyl, dir(40, 60)), projectedOpeningAreaM2(cyl, dir(40, 60)), 1e-12);
  // Horizontal cylinder along C0-C180, length 1.0, diameter 0.1, seen straight down and along its axis.
  const PhotometricInfo hcyl = opening(OpeningShape::kHorizontalCylinderAlongWidth, 1.0, 0.1, 0.1);
  EXPECT_NEAR(projectedOpeningAreaM2(hcyl, dir(0, 0)), 0.1, 1e-12);
  EXPECT_NEAR(projectedOpeningAreaM2(hcyl, dir(0, 90)), kPi * 0.0025, 1e-12);
}

TEST(LuminousOpening, SpheresAndEllipsoidsShowTheirSilhouette) {
  const PhotometricInfo sphere = opening(OpeningShape::kSphere, 0.4, 0.4, 0.4);
  EXPECT_NEAR(projectedOpeningAreaM2(sphere, dir(12, 34)), kPi * 0.04, 1e-12);
  // Ellipsoid semi-axes 0.1, 0.2, 0.3: along each axis the ellipse of the other two.
  const PhotometricInfo ell = opening(OpeningShape::kEllipsoid, 0.2, 0.4, 0.6);
  EXPECT_NEAR(projectedOpeningAreaM2(ell, Vec3(1, 0, 0)), kPi * 0.2 * 0.3, 1e-12);
  EXPECT_NEAR(projectedOpeningAreaM2(ell, Vec3(0, 0, -1)), kPi * 0.1 * 0.2, 1e-12);
}

TEST(LuminousOpening, VerticalDiscsFaceTheirPlane) {
  // A width (no length) faces C0, a length faces C90 (LM-63-2019 table 1).
  const PhotometricInfo facingC0 = opening(OpeningShape::kVerticalCircle, 0.2, 0.0, 0.2);
  const PhotometricInfo facingC90 = opening(OpeningShape::kVerticalCircle, 0.0, 0.2, 0.2);
  EXPECT_NEAR(projectedOpeningAreaM2(facingC0, dir(0, 90)), kPi * 0.01, 1e-12);
  EXPECT_NEAR(projectedOpeningAreaM2(facingC0, dir(90, 90)), 0.0, 1e-12);
  EXPECT_NEAR(projectedOpeningAreaM2(facingC90, dir(90, 60)), kPi * 0.01 * std::sqrt(0.75), 1e-12);
  EXPECT_TRUE(hasLuminousArea(facingC0));
  EXPECT_TRUE(hasLuminousArea(facingC90));
  EXPECT_FALSE(hasLuminousArea(opening(OpeningShape::kPoint, 0, 0, 0)));
}

TEST(LuminousOpening, ReadersRecordTheLineOfTheOpening) {
  const std::string data = CANDELA_TEST_DATA;
  // lambert_rot.ies: "1 4000 1 19 1 1 2 0 0 0" on line 6, the width its eighth number.
  const PhotometricWeb ies = readIes(data + "/ies/lambert_rot.ies");
  EXPECT_EQ(ies.info().openingLoc.line, 6);
  EXPECT_NE(ies.info().openingLoc.file.find("lambert_rot.ies"), std::string::npos);
  // EULUMDAT line 16: length of the luminous area.
  EXPECT_EQ(readEulumdat(data + "/ldt/asym_isym0.ldt").info().openingLoc.line, 16);
}

}  // namespace
}  // namespace candela
