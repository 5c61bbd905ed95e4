// A Honeybee-style model (tests/data/honeybee): a room from !genbox and !genprism, two ies2rad
// panels placed with !xform -n -rz -t, a glazed window, and a !gensky sky with its skyfunc lines
// in a separate file, read as a user passes them to `candela points`; against the same room
// written by hand for candela (polygons, [[luminaire]] entries of the IES file, candela's own
// CIE overcast sky). The two are independent estimates of the same illuminance: at each point
// they must agree within 4 standard errors of their difference.
#include "study/points_study.h"
#include "study/grids/sensor_grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace candela {
namespace {

namespace fs = std::filesystem;

const fs::path kDir = fs::path(CANDELA_TEST_DATA) / "honeybee";

PointsResult trace(const PointsJob& job) {
  const PointsScene scene = loadPointsScene(job);
  return computePoints(scene, job.accelerator, readPointsFile(kDir / "points.pts").points);
}

TEST(HoneybeeModel, GeneratorsIes2radAndGenskyGiveTheHandWrittenCasesIlluminance) {
  PointsJob model;
  model.scenes = {kDir / "model" / "room.rad", kDir / "sky" / "overcast.sky"};
  model.trace.seed = 11;
  model.trace.quality = Quality::kHigh;  // error bars near 0.3 %: 4σ is a tight test
  // One batch a point: the test compares the two readings of one room, whatever their error bars,
  // and with the per-point target it took 44 s (195 s under the sanitizers).
  model.trace.targetRelativeError = 0.0;
  PointsJob equivalent;
  equivalent.caseFile = kDir / "equivalent" / "case.toml";
  equivalent.trace.seed = 12;  // independent random numbers
  equivalent.trace.quality = Quality::kHigh;
  equivalent.trace.targetRelativeError = 0.0;
  const PointsResult a = trace(model), b = trace(equivalent);
  ASSERT_EQ(a.estimates.size(), 6u);
  ASSERT_EQ(b.estimates.size(), 6u);
  for (size_t i = 0; i < a.estimates.size(); ++i) {
    const double ea = a.estimates[i].illuminanceLux(), eb = b.estimates[i].illuminanceLux();
    const double sa = a.estimates[i].standardErrorLux(), sb = b.estimates[i].standardErrorLux();
    const double sigma = std::sqrt(sa * sa + sb * sb);
    std::cout << "point " << i + 1 << ": model " << ea << " ± " << sa << " lx, hand-written " << eb << " ± " << sb
              << " lx (" << (ea - eb) / sigma << " σ)\n";
    EXPECT_GT(eb, 50.0) << "point " << i + 1;  // lit by both the panels and the sky
    EXPECT_LE(std::abs(ea - eb), 4.0 * sigma) << "point " << i + 1;
  }
}

}  // namespace
}  // namespace candela
