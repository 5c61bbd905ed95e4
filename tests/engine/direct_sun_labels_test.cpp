// directSunCoefficientsByLabel (engine/daylight_coefficients.h): the direct sun at a sensor split
// by the labelled glass its beam crosses, for the annual study's window groups.
#include "engine/daylight_coefficients.h"

#include "engine/fresnel.h"
#include "engine/tracer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace candela {
namespace {

void addUpRect(Scene& sc, double x0, double y0, double x1, double y1, double z, uint32_t mat) {
  sc.addPolygon({{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}}, mat);
}

// A sensor at the origin facing up under two panes at z = 1: pane 0 over x < 0, pane 1 over
// x > 0 (both |y| < 1), sky everywhere else. Suns straight through each pane and one beside both.
TEST(DirectSunByLabel, EachBeamGoesToThePaneItCrosses) {
  Scene sc;
  Material glass;
  glass.type = MaterialType::kGlass;
  glass.name = "pane";
  glass.color = Rgb(0.9);
  glass.refractiveIndex = 1.52;
  const uint32_t g = sc.addMaterial(glass);
  addUpRect(sc, -1.0, -1.0, -0.01, 1.0, 1.0, g);
  addUpRect(sc, 0.01, -1.0, 1.0, 1.0, 1.0, g);
  const Tracer tracer(sc);
  const std::vector<Vec3> pos = {{0, 0, 0}}, nrm = {{0, 0, 1}};
  const SensorBlock block{pos, nrm, 0};
  const std::vector<Vec3> suns = {glm::normalize(Vec3(-0.5, 0, 1)), glm::normalize(Vec3(0.5, 0, 1)),
                                  glm::normalize(Vec3(0, 3, 1))};
  SurfaceLabels labels;
  labels.ofSurface = {0, 1};
  labels.count = 2;
  const auto parts = directSunCoefficientsByLabel(tracer, block, suns, 4, 7, 1, labels);
  ASSERT_EQ(parts.size(), 3u);
  // The total is directSunCoefficients' to the bit.
  const std::vector<float> plain = directSunCoefficients(tracer, block, suns, 4, 7, 1);
  ASSERT_EQ(parts[0].size(), plain.size());
  for (std::size_t j = 0; j < plain.size(); ++j) EXPECT_EQ(parts[0][j], plain[j]);
  // Through pane 0, then pane 1: all of it to that pane (float sums of the same samples).
  EXPECT_GT(parts[0][0], 0.5f);
  EXPECT_NEAR(parts[1][0], parts[0][0], 1e-6);
  EXPECT_EQ(parts[2][0], 0.0f);
  EXPECT_NEAR(parts[2][1], parts[0][1], 1e-6);
  EXPECT_EQ(parts[1][1], 0.0f);
  // Beside both panes (open sky): the total has it, no pane does. cos θ = 1/√10 unobstructed.
  EXPECT_NEAR(parts[0][2], 1.0 / std::sqrt(10.0), 1e-3);
  EXPECT_EQ(parts[1][2], 0.0f);
  EXPECT_EQ(parts[2][2], 0.0f);
  labels.ofSurface = {0};
  EXPECT_THROW(directSunCoefficientsByLabel(tracer, block, suns, 4, 7, 1, labels), std::invalid_argument);
}

}  // namespace
}  // namespace candela
