// The grids' error target (engine/sensors.cpp, docs/estimator.md#the-grids-error-target): a
// point's goal is a share of the larger of its value and its group's mean, so a dim point in a
// bright grid stops where the per-point target would sample on, and the groups, not the order
// or the threads, decide it.
#include "engine/sensors.h"
#include "engine/tracer.h"
#include "tests/engine/test_materials.h"
#include "engine/irradiance_estimator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace candela {
namespace {

using test_support::addMaterial;

// A grey floor (ρ 0.5) and a grey sphere of radius 1 m resting on it, under a uniform sky.
Scene sphereOnGreyFloor() {
  Scene sc;
  const uint32_t sky = addMaterial(sc, MaterialType::kGlow, 1.0);
  sc.addDistant(Vec3(0, 0, 1), 360.0, sky, "sky");
  const uint32_t grey = addMaterial(sc, MaterialType::kPlastic, 0.5);
  sc.addPolygon({{-20, -20, 0}, {20, -20, 0}, {20, 20, 0}, {-20, 20, 0}}, grey);
  sc.addSphere(Vec3(0, 0, 1), 1.0, grey);
  return sc;
}

// Floor points facing up: five in the open (bright) and, last, one 0.2 m from the contact under
// the sphere (dim: it sees the sky only near the horizon).
std::vector<SensorPoint> floorPoints() {
  std::vector<SensorPoint> pts;
  for (int i = 0; i < 5; ++i) pts.push_back({Vec3(3.0 + i, 1.0, 0.01), Vec3(0, 0, 1)});
  pts.push_back({Vec3(0.2, 0.0, 0.01), Vec3(0, 0, 1)});
  return pts;
}

TraceSettings pathSettings() {
  TraceSettings s;
  s.hemisphereSamples = 64;
  s.lightSamples = 16;
  s.method = Method::kPath;
  s.maxBatches = kExplicitTargetMaxBatches;
  return s;
}

std::vector<IrradianceEstimate> inGroups(const Tracer& tracer, const std::vector<SensorPoint>& pts,
                                         const TraceSettings& s, const std::vector<size_t>& ends, int threads = 2,
                                         size_t blockPoints = kSensorBlockPoints) {
  std::vector<IrradianceEstimate> out;
  computeIrradianceInBlocks(
      tracer, pts, s, threads, {}, localDistribution(),
      [&](size_t, const IrradianceEstimate* e, size_t n) { out.insert(out.end(), e, e + n); }, blockPoints, ends);
  return out;
}

bool same(const IrradianceEstimate& a, const IrradianceEstimate& b) {
  return a.illuminanceLux() == b.illuminanceLux() && a.standardErrorLux() == b.standardErrorLux();
}

TEST(GridTarget, ADimPointInABrightGridStopsAtTheGridsGoal) {
  const Scene sc = sphereOnGreyFloor();
  const Tracer tracer(sc);
  const std::vector<SensorPoint> pts = floorPoints();
  const size_t dim = pts.size() - 1;
  const std::vector<IrradianceEstimate> first = computeIrradiance(tracer, pts, pathSettings(), 2);
  double mean = 0.0;
  for (const IrradianceEstimate& e : first) mean += e.illuminanceLux() / static_cast<double>(pts.size());
  const double e = first[dim].illuminanceLux(), se = first[dim].standardErrorLux();
  std::printf("[ measured ] dim point %.3f ± %.3f lx, group mean %.2f lx\n", e, se, mean);
  // Below the point's own share of g but above the group's (with a factor 2 for the pilot's mean):
  // se/e > g > 2 se/mean, g their geometric mean, a margin of √(mean/2e) on each side.
  ASSERT_GT(mean, 8.0 * e) << "the scene no longer has a dim point";
  const double g = se * std::sqrt(2.0 / (e * mean));

  TraceSettings grid = pathSettings();
  grid.gridTargetRelativeError = g;
  TraceSettings perPoint = pathSettings();
  perPoint.targetRelativeError = g;

  // One group: the dim point's first batch meets g × the mean, so it is that batch, bit for bit.
  const std::vector<IrradianceEstimate> one = inGroups(tracer, pts, grid, {pts.size()});
  EXPECT_TRUE(same(one[dim], first[dim])) << one[dim].illuminanceLux() << " " << first[dim].illuminanceLux();
  // The per-point target g samples it on, to g of its own value.
  const std::vector<IrradianceEstimate> own = inGroups(tracer, pts, perPoint, {});
  EXPECT_FALSE(same(own[dim], first[dim]));
  EXPECT_LE(own[dim].standardErrorLux(), g * own[dim].illuminanceLux());
  // Every point of the grid run meets g × the larger of its value and the group's mean (the
  // pilot's mean within 25 % of it: 6 points of the same samples, a few per cent apart).
  for (size_t i = 0; i < pts.size(); ++i)
    EXPECT_LE(one[i].standardErrorLux(), g * std::max(one[i].illuminanceLux(), 1.25 * mean)) << i;

  // In a group of its own its goal is g × its own value (the pilot's single estimate of it
  // within 4 of its standard errors), so it takes more batches.
  const std::vector<IrradianceEstimate> alone = inGroups(tracer, pts, grid, {dim, pts.size()});
  EXPECT_FALSE(same(alone[dim], first[dim]));
  EXPECT_LE(alone[dim].standardErrorLux(), g * (alone[dim].illuminanceLux() + 4.0 * se));
  // The bright points' goal is unchanged by the split: their group's mean is still theirs.
  for (size_t i = 0; i < dim; ++i) EXPECT_LE(alone[i].standardErrorLux(), g * 1.25 * mean) << i;
}

// With the grids' target and the cache, the numbers depend on the seed and the groups only: not
// on the threads nor on the block size (the pilot and every point have their own streams).
TEST(GridTarget, SameNumbersForAnyThreadsAndBlockSize) {
  const Scene sc = sphereOnGreyFloor();
  const Tracer tracer(sc);
  std::vector<SensorPoint> pts = floorPoints();
  for (int i = 0; i < 6; ++i) pts.push_back({Vec3(0.1 + 0.3 * i, -0.5, 0.01), Vec3(0, 0, 1)});
  TraceSettings s = pathSettings();
  s.method = Method::kCache;
  s.cache.recordSamples = 64;
  s.gridTargetRelativeError = 0.01;
  s.maxBatches = 4;
  const std::vector<size_t> ends = {6, pts.size()};
  const std::vector<IrradianceEstimate> whole = inGroups(tracer, pts, s, ends, 2);
  for (int threads : {1, 2})
    for (size_t block : {size_t{1}, size_t{5}, size_t{100}}) {
      const std::vector<IrradianceEstimate> got = inGroups(tracer, pts, s, ends, threads, block);
      ASSERT_EQ(got.size(), pts.size());
      for (size_t i = 0; i < pts.size(); ++i) EXPECT_TRUE(same(got[i], whole[i])) << threads << " " << block << " " << i;
    }
}

TEST(GridTarget, GroupsMustCoverThePoints) {
  const Scene sc = sphereOnGreyFloor();
  const Tracer tracer(sc);
  TraceSettings s = pathSettings();
  s.gridTargetRelativeError = 0.01;
  EXPECT_THROW(inGroups(tracer, floorPoints(), s, {3}), std::invalid_argument);
}

}  // namespace
}  // namespace candela
